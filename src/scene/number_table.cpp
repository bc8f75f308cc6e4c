#include "scene/number_table.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "scene/scene_limits.h"
#include "scene/table_file.h"
#include "scene/table_lines.h"
#include "scene/text_escape.h"

namespace cablefilm {

std::vector<std::vector<double>> ReadNumberTable(const std::string& path,
                                                 const std::vector<std::string>& columns,
                                                 const std::string& what,
                                                 const std::string& units, int min_rows) {
  return ReadNumberTableOfForms(path, {columns}, what, units, min_rows);
}

std::vector<std::vector<double>> ReadNumberTableOfForms(
    const std::string& path, const std::vector<std::vector<std::string>>& forms,
    const std::string& what, const std::string& units, int min_rows, int* form) {
  const std::string name = EscapeText(path);
  std::vector<std::string> headers;
  for (const std::vector<std::string>& form : forms) {
    std::string h;
    for (const std::string& c : form) h += (h.empty() ? "" : ",") + c;
    headers.push_back(h);
  }
  std::string header = headers.front(), all;
  for (const std::string& h : headers) all += (all.empty() ? "\"" : "\" or \"") + h;
  all += "\"";
  std::vector<std::string> columns = forms.front();
  std::string expected = "rows " + all + " " + units;
  std::vector<std::vector<double>> rows;
  bool seen_header = false;
  long number = 0;
  auto where = [&] { return name + ":" + std::to_string(number) + ": "; };
  ReadTableLines(path, what, expected, [&](std::string&& line, long line_number) {
    number = line_number;
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') return;
    if (!seen_header) {
      const auto it = std::find(headers.begin(), headers.end(), line);
      if (it == headers.end())
        throw Error(where() + "expected the header row exactly " + all + " (" + what + ": " +
                    expected + "), got " + ShownLine(line));
      header = *it;
      columns = forms[static_cast<std::size_t>(it - headers.begin())];
      if (form) *form = static_cast<int>(it - headers.begin());
      expected = "rows " + header + " " + units;
      seen_header = true;
      return;
    }
    std::vector<double> row(columns.size());
    std::size_t from = 0;
    for (std::size_t i = 0; i < columns.size(); ++i) {
      const bool last = i + 1 == columns.size();
      const std::size_t comma = line.find(',', from);
      if (last == (comma != std::string::npos) ||
          !ParseDecimal(line.substr(from, last ? std::string::npos : comma - from), &row[i]) ||
          !std::isfinite(row[i]))
        throw Error(where() + "expected " + std::to_string(columns.size()) + " numbers " +
                    header + " " + units + " (finite decimals, separated by commas), got " +
                    ShownLine(line));
      from = comma + 1;
    }
    if (static_cast<long>(rows.size()) >= kMaxTableRows)
      throw Error(where() + "more than " + std::to_string(kMaxTableRows) +
                  " rows; expected at most that many");
    rows.push_back(std::move(row));
  });
  if (static_cast<int>(rows.size()) < min_rows)
    throw Error(name + ": expected at least " + std::to_string(min_rows) + " " + expected +
                ", found " + std::to_string(rows.size()));
  return rows;
}

}  // namespace cablefilm
