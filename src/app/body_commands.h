#pragma once
// The quasi-static commands of a moored body (core/body_statics.h): `stiffness` prints the
// moorings' 6x6 stiffness matrix at the system's equilibrium; `offset` writes the
// offset-restoring curve along a heading as CSV.
#include <string>

namespace cablefilm {

struct OffsetOptions {
  std::string body;        // empty: the scene's only body
  double heading = 0;      // [deg] from +x towards +z
  double max_offset = -1;  // [m]; negative: a twentieth of the shortest line on the body
  int points = 11;         // offsets from 0 to max_offset
  std::string out;         // CSV file; empty or "-": standard output
};

int StiffnessCommand(const std::string& scene_path, const std::string& body);
int OffsetCommand(const std::string& scene_path, const OffsetOptions& options);

}  // namespace cablefilm
