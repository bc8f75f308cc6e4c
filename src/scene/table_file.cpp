#include "scene/table_file.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/error.h"
#include "scene/scene_limits.h"
#include "scene/table_lines.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

constexpr char kHeader[] = "t,x,y";      // a table in the plane (z = 0)
constexpr char kHeader3D[] = "t,x,y,z";
constexpr char kHeaderTurn[] = "t,x,y,z,rx,ry,rz";  // a body's, its angles too

bool IsBlank(char c) { return c == ' ' || c == '\t'; }

}  // namespace

bool ParseDecimal(const std::string& cell, double* value) {
  std::size_t b = 0, e = cell.size();
  while (b < e && IsBlank(cell[b])) ++b;
  while (e > b && IsBlank(cell[e - 1])) --e;
  std::size_t i = b;
  auto digits = [&] {
    const std::size_t from = i;
    while (i < e && cell[i] >= '0' && cell[i] <= '9') ++i;
    return i - from;
  };
  if (i < e && (cell[i] == '+' || cell[i] == '-')) ++i;
  std::size_t mantissa = digits();
  if (i < e && cell[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < e && (cell[i] == 'e' || cell[i] == 'E')) {
    ++i;
    if (i < e && (cell[i] == '+' || cell[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  if (i != e) return false;
  const std::string number = cell.substr(b, e - b);
  *value = std::strtod(number.c_str(), nullptr);
  return true;
}

namespace {

// `columns` (3, 4 or 7) decimal numbers separated by commas, nothing else.
bool ParseRow(const std::string& line, int columns, std::array<double, 7>& row) {
  std::size_t from = 0;
  row = {};
  for (int i = 0; i < columns; ++i) {
    const bool last = i + 1 == columns;
    const std::size_t comma = line.find(',', from);
    if (last == (comma != std::string::npos)) return false;  // columns - 1 commas exactly
    const std::string cell = line.substr(from, last ? std::string::npos : comma - from);
    if (!ParseDecimal(cell, &row[i])) return false;
    from = comma + 1;
  }
  return true;
}

}  // namespace

std::vector<std::array<double, 7>> ReadMotionTable(const std::string& path, bool angles) {
  const std::string name = EscapeText(path);

  std::vector<std::array<double, 7>> rows;
  bool header = false;      // the first row was the header "t,x,y", "t,x,y,z" or a body's
  bool first = true;        // no row (header or data) seen yet
  int columns = 3;          // t,x,y, t,x,y,z or t,x,y,z,rx,ry,rz: the header's, or the first row's
  long number = 0;          // line number
  auto where = [&] { return name + ":" + std::to_string(number) + ": "; };
  auto names = [&] {
    return std::string(columns == 7 ? kHeaderTurn : columns == 4 ? kHeader3D : kHeader);
  };
  auto units = [&] { return std::string(columns == 7 ? "in s, m and degrees" : "in s and m"); };
  const std::string forms = angles ? "\"t,x,y\", \"t,x,y,z\" or \"t,x,y,z,rx,ry,rz\""
                                   : "\"t,x,y\" or \"t,x,y,z\"";
  const std::string number_forms =
      angles ? "t,x,y, t,x,y,z or t,x,y,z,rx,ry,rz in s, m and degrees" : "t,x,y or t,x,y,z in s and m";
  auto which = [&] {
    return header ? " (after the header row \"" + names() + "\")"
                  : " (this table has no header row \"" + names() + "\")";
  };
  auto take = [&](std::string&& line, long line_number) {
    number = line_number;
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') return;  // blank or comment
    std::array<double, 7> row{};
    const long commas = std::count(line.begin(), line.end(), ',');
    if (first && !angles && (line == kHeaderTurn || commas == 6))
      throw Error(where() + "seven columns t,x,y,z,rx,ry,rz turn a body; an end's or a point's "
                  "table has rows t,x,y or t,x,y,z (in s and m), got " + ShownLine(line));
    if (first && (line == kHeader || line == kHeader3D || line == kHeaderTurn)) {
      header = true;
      first = false;
      columns = line == kHeaderTurn ? 7 : line == kHeader3D ? 4 : 3;
      return;
    }
    if (first && commas == 3) columns = 4;
    if (first && commas == 6) columns = 7;
    if (!ParseRow(line, columns, row)) {
      if (first)
        throw Error(where() + "expected a header row exactly " + forms + ", or numbers " +
                    number_forms + " (finite decimals, separated by commas), got " + ShownLine(line));
      throw Error(where() + "expected " +
                  std::string(columns == 3 ? "three" : columns == 4 ? "four" : "seven") +
                  " numbers " + names() + " " + units() +
                  " (finite decimals, separated by commas)" + which() + ", got " + ShownLine(line));
    }
    first = false;
    for (double v : row)
      if (!std::isfinite(v))
        throw Error(where() + "expected finite numbers, got " + ShownLine(line));
    if (!(std::abs(row[0]) <= kMaxTime))
      throw Error(where() + "expected a time t from -" + FormatNumber(kMaxTime) + " to " +
                  FormatNumber(kMaxTime) + " s, got " + FormatNumber(row[0]));
    if (!(std::abs(row[1]) <= kMaxLength && std::abs(row[2]) <= kMaxLength &&
          std::abs(row[3]) <= kMaxLength))
      throw Error(where() + "expected offsets from -" + FormatNumber(kMaxLength) + " to " +
                  FormatNumber(kMaxLength) + " m, got " + ShownLine(line));
    if (!(std::abs(row[4]) <= kMaxPhase && std::abs(row[5]) <= kMaxPhase &&
          std::abs(row[6]) <= kMaxPhase))
      throw Error(where() + "expected angles rx, ry, rz from -" + FormatNumber(kMaxPhase) +
                  " to " + FormatNumber(kMaxPhase) + " degrees, got " + ShownLine(line));
    if (!rows.empty() && !(row[0] > rows.back()[0]))
      throw Error(where() + "expected the time to increase, got " + FormatNumber(row[0]) +
                  " after " + FormatNumber(rows.back()[0]));
    if (static_cast<long>(rows.size()) >= kMaxTableRows)
      throw Error(where() + "more than " + FormatNumber(static_cast<double>(kMaxTableRows)) +
                  " rows; expected at most that many");
    rows.push_back(row);
  };
  ReadTableLines(path, "the motion table",
                 "rows t,x,y or t,x,y,z" + std::string(angles ? " or t,x,y,z,rx,ry,rz" : ""),
                 take);
  if (rows.size() < 2)
    throw Error(name + ": expected at least two rows " + names() + which() + ", found " +
                std::to_string(rows.size()));
  return rows;
}

}  // namespace cablefilm
