#pragma once
// The scene text a MoorDyn conversion writes, piece by piece: "key = value" lines with their
// comments lined up, and the warnings gathered on the way. Shared by the conversion's parts
// (moordyn_convert.cpp: lines, points, materials; moordyn_environment.cpp: options).
#include <sstream>
#include <string>
#include <vector>

#include "scene/key_source.h"
#include "scene/moordyn_file.h"

namespace cablefilm {

struct MoorDynTomlOut {
  std::string file;  // the MoorDyn file's name as messages show it (escaped)
  std::ostringstream text;
  std::vector<std::string> warnings;
  KeySources sources;  // where each key written came from, for messages about the scene
  std::string table;   // the table the keys go into ("material[0]"; "" at the top)
  KeySource row;       // the row it comes from (line 0: none)

  // The keys that follow go into table `key` ("material[0]"), from the row at `line` of the
  // file ("LINE TYPES row 1"; line 0: none).
  void Table(const std::string& key, int line, const std::string& place);
  // "key = value", then "# comment" in the column after it (the comment is escaped: it may
  // hold names from the file). `columns`: those of the table's row the value comes from ("EA",
  // "X, Y, Z").
  void Key(const std::string& key, const std::string& value, const std::string& comment = "",
           const std::string& columns = "");
  // `key` of the table came from `place` at `line` of the file (line 0: a default, nowhere).
  void Source(const std::string& key, int line, const std::string& place);
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
