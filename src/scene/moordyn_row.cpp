#include "scene/moordyn_row.h"

#include <charconv>
#include <cmath>

#include "core/error.h"
#include "scene/moordyn_file.h"
#include "scene/text_escape.h"

namespace cablefilm {

bool ParseMoorDynNumber(const std::string& text, double* value) {
  // MoorDyn reads with atof, which takes a leading "+"; from_chars does not, and takes no
  // hexadecimal in its general format. "inf" and "nan" parse and are refused as not finite.
  const std::size_t start = !text.empty() && text[0] == '+' ? 1 : 0;
  if (start == 1 && text.size() > 1 && text[1] == '-') return false;  // "+-1"
  const char* first = text.data() + start;
  const char* last = text.data() + text.size();
  double v = 0;
  const auto [end, ec] = std::from_chars(first, last, v);
  if (ec != std::errc() || end != last || first == last || !std::isfinite(v)) return false;
  *value = v == 0 ? 0.0 : v;  // no -0 in what is written from it
  return true;
}

bool ParseMoorDynWhole(const std::string& text, int* value) {
  const std::size_t start = !text.empty() && text[0] == '+' ? 1 : 0;
  if (text.size() == start || text.size() - start > 9) return false;
  int v = 0;
  for (std::size_t i = start; i < text.size(); ++i) {
    if (text[i] < '0' || text[i] > '9') return false;
    v = v * 10 + (text[i] - '0');
  }
  *value = v;
  return true;
}

MoorDynRow::MoorDynRow(const std::string& file, const char* section, int row,
                       const MoorDynRowText& text, const std::vector<std::string>& columns,
                       std::size_t required)
    : file_(file), section_(section), row_(row), text_(text), columns_(columns) {
  if (text.words.size() >= required) return;
  std::string names;
  for (std::size_t i = 0; i < required; ++i) names += (i ? " " : "") + columns[i];
  Refuse(text.words.size(), "missing; expected " + std::to_string(required) + " columns (" +
                                names + "), got " + std::to_string(text.words.size()));
}

std::string MoorDynRow::Where(std::size_t column) const {
  const std::string name =
      column < columns_.size() ? columns_[column] : std::to_string(column + 1);
  return file_ + ":" + std::to_string(text_.line) + ": " + section_ + " row " +
         std::to_string(row_) + ", column " + name;
}

void MoorDynRow::Fail(std::size_t column, const std::string& expected) const {
  throw Error(Where(column) + ": expected " + expected + ", got " + QuoteText(Text(column)));
}

void MoorDynRow::Refuse(std::size_t column, const std::string& message) const {
  throw Error(Where(column) + ": " + message);
}

std::string MoorDynRow::Note(const std::string& message) const {
  return file_ + ":" + std::to_string(text_.line) + ": " + section_ + " row " +
         std::to_string(row_) + ": " + message;
}

double MoorDynRow::Number(std::size_t column, double lo, double hi,
                          const std::string& what) const {
  double v = 0;
  if (!ParseMoorDynNumber(Text(column), &v) || !(v >= lo && v <= hi)) Fail(column, what);
  return v;
}

std::vector<double> MoorDynRow::Numbers(std::size_t column, const std::vector<std::size_t>& counts,
                                        double lo, double hi, const std::string& what) const {
  std::vector<double> values;
  const std::string& text = Text(column);
  std::size_t start = 0;
  while (true) {
    const std::size_t bar = text.find('|', start);
    double v = 0;
    const std::string part = text.substr(start, bar == std::string::npos ? bar : bar - start);
    if (!ParseMoorDynNumber(part, &v) || !(v >= lo && v <= hi)) Fail(column, what);
    values.push_back(v);
    if (bar == std::string::npos) break;
    start = bar + 1;
  }
  for (std::size_t n : counts)
    if (values.size() == n) return values;
  Fail(column, what);
}

int MoorDynRow::Whole(std::size_t column, int lo, int hi) const {
  int v = 0;
  if (!ParseMoorDynWhole(Text(column), &v) || v < lo || v > hi)
    Fail(column, "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
  return v;
}

}  // namespace cablefilm
