#pragma once
// The CSV table of a recorded end motion: rows "t,x,y" (s, m, m), an optional header line,
// times strictly increasing.
#include <array>
#include <string>
#include <vector>

namespace cablefilm {

// Throws Error naming the file, the line and what was expected.
std::vector<std::array<double, 3>> ReadMotionTable(const std::string& path);

}  // namespace cablefilm
