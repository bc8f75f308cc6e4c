#pragma once
// The CSV table of a recorded end motion: rows "t,x,y" (s, m, m; z = 0) or "t,x,y,z", and for
// a body "t,x,y,z,rx,ry,rz" too (its angles about x, y, z in degrees), times strictly
// increasing, read strictly: a first row exactly "t,x,y", "t,x,y,z" or "t,x,y,z,rx,ry,rz" (the
// header) or none; every other row as many decimal numbers (no hexadecimal, inf or nan, no empty cell);
// blank lines and lines starting with '#' are skipped. At most kMaxTableBytes, kMaxTableRows rows and kMaxTableLineLength
// characters a line (scene_limits.h), checked while reading.
#include <array>
#include <string>
#include <vector>

namespace cablefilm {

// Throws Error naming the file, the line and what was expected.
// Rows (t [s], dx, dy, dz [m], rx, ry, rz [deg]); dz = 0 for a table of three columns, the
// angles 0 for one of three or four. `angles`: seven columns are allowed (a body's table).
std::vector<std::array<double, 7>> ReadMotionTable(const std::string& path, bool angles = false);

// A plain decimal number, surrounded by blanks at most: [+-]digits[.digits][(e|E)[+-]digits]
// (or .digits). No hexadecimal, inf or nan, which strtod alone would take. False if `cell` is
// not one.
bool ParseDecimal(const std::string& cell, double* value);

}  // namespace cablefilm
