#pragma once
// The scene text a MoorDyn conversion writes, piece by piece: "key = value" lines with their
// comments lined up, and the warnings gathered on the way. Shared by the conversion's parts
// (moordyn_convert.cpp: lines, points, materials; moordyn_environment.cpp: options).
#include <sstream>
#include <string>
#include <vector>

#include "scene/moordyn_file.h"

namespace cablefilm {

struct MoorDynTomlOut {
  std::string file;  // the MoorDyn file's name as messages show it (escaped)
  std::ostringstream text;
  std::vector<std::string> warnings;

  // "key = value", then "# comment" in the column after it (the comment is escaped: it may
  // hold names from the file).
  void Key(const std::string& key, const std::string& value, const std::string& comment = "");
  // A "# ..." line (escaped).
  void Comment(const std::string& comment);
  // "file:line: " + message (escaped), as a warning ("file: " for line 0: a default's).
  void Warn(int line, const std::string& message);
};

// [environment] and [seabed] from OPTIONS, and a comment (or a warning) for every option.
void WriteMoorDynEnvironment(const MoorDynSystem& system, MoorDynTomlOut* out);

// The fluid density the file gives, or MoorDyn's default [kg/m^3].
double MoorDynDensity(const MoorDynSystem& system);

// [[body]] for each of BODIES (moordyn_bodies.cpp), with the fluid density rho [kg/m^3] for
// their added mass and drag.
void WriteMoorDynBodies(const MoorDynSystem& system, double rho, MoorDynTomlOut* out);

}  // namespace cablefilm
