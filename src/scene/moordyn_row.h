#pragma once
// One row of a MoorDyn table read column by column. Every problem is an Error that names the
// file, the line, the section, the row and the column, says what was expected and quotes what
// was found: `sys.txt:14: LINES row 2, column NumSegs: expected a whole number from 1 to
// 10000000, got "x"`.
#include <cstddef>
#include <string>
#include <vector>

#include "scene/moordyn_layout.h"

namespace cablefilm {

class MoorDynRow {
 public:
  // `file`: the name as messages show it (escaped). `columns`: every column's name, of which
  // the first `required` must be present. `row`: 1-based, within the section.
  MoorDynRow(const std::string& file, const char* section, int row, const MoorDynRowText& text,
             const std::vector<std::string>& columns, std::size_t required);

  int line() const { return text_.line; }
  std::size_t size() const { return text_.words.size(); }
  const std::string& Text(std::size_t column) const { return text_.words[column]; }

  // A number from lo to hi; `what` says so in words with its unit ("a number >= 0 in kg, at
  // most 1e+09").
  double Number(std::size_t column, double lo, double hi, const std::string& what) const;
  // `counts` numbers separated by "|" ("0|0|-5"), each as Number's.
  std::vector<double> Numbers(std::size_t column, const std::vector<std::size_t>& counts,
                              double lo, double hi, const std::string& what) const;
  // A whole number from lo to hi (digits only).
  int Whole(std::size_t column, int lo, int hi) const;

  // "file:line: SECTION row n, column C"
  std::string Where(std::size_t column) const;
  // Where(column) + ": expected " + expected + ", got "<text>"".
  [[noreturn]] void Fail(std::size_t column, const std::string& expected) const;
  // Where(column) + ": " + message.
  [[noreturn]] void Refuse(std::size_t column, const std::string& message) const;
  // "file:line: SECTION row n: " + message, for a warning.
  std::string Note(const std::string& message) const;

 private:
  const std::string& file_;
  const char* section_;
  int row_;
  const MoorDynRowText& text_;
  const std::vector<std::string>& columns_;
};

// A whole number written with digits only (an optional "+"), at most 9 digits.
bool ParseMoorDynWhole(const std::string& text, int* value);

}  // namespace cablefilm
