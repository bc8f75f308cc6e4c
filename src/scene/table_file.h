#pragma once
// The CSV table of a recorded end motion: rows "t,x,y" (s, m, m), times strictly increasing,
// read strictly: a first row exactly "t,x,y" (the header) or none; every other row three
// decimal numbers (no hexadecimal, inf or nan, no empty cell); blank lines and lines starting
// with '#' are skipped. At most kMaxTableBytes, kMaxTableRows rows and kMaxTableLineLength
// characters a line (scene_limits.h), checked while reading.
#include <array>
#include <string>
#include <vector>

namespace cablefilm {

// Throws Error naming the file, the line and what was expected.
std::vector<std::array<double, 3>> ReadMotionTable(const std::string& path);

}  // namespace cablefilm
