#include "scene/table_file.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace cablefilm {
namespace {

bool ParseRow(const std::string& line, std::array<double, 3>& row) {
  std::stringstream ss(line);
  std::string cell;
  int i = 0;
  while (std::getline(ss, cell, ',')) {
    if (i >= 3) return false;
    char* end = nullptr;
    row[i] = std::strtod(cell.c_str(), &end);
    while (end && (*end == ' ' || *end == '\t' || *end == '\r')) ++end;
    if (end == cell.c_str() || (end && *end != '\0')) return false;
    ++i;
  }
  return i == 3;
}

}  // namespace

std::vector<std::array<double, 3>> ReadMotionTable(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot open the motion table");
  std::vector<std::array<double, 3>> rows;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    std::array<double, 3> row{};
    if (!ParseRow(line, row)) {
      if (rows.empty() && number == 1) continue;  // a header such as "t,x,y"
      throw Error(path + ":" + std::to_string(number) +
                  ": expected three numbers t,x,y (s, m, m), got \"" + line + "\"");
    }
    for (double v : row)
      if (!std::isfinite(v))
        throw Error(path + ":" + std::to_string(number) + ": expected finite numbers");
    if (!rows.empty() && !(row[0] > rows.back()[0]))
      throw Error(path + ":" + std::to_string(number) + ": expected the time to increase, got " +
                  std::to_string(row[0]) + " after " + std::to_string(rows.back()[0]));
    rows.push_back(row);
  }
  if (rows.size() < 2) throw Error(path + ": expected at least two rows t,x,y");
  return rows;
}

}  // namespace cablefilm
