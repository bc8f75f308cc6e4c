#include "run/sweep_plan.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

#include "core/error.h"
#include "scene/scene_edit.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

constexpr std::size_t kMaxCasesFileBytes = std::size_t{64} << 20;

std::string Trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  const std::size_t b = s.find_last_not_of(" \t");
  return s.substr(a, b - a + 1);
}

// The cells of one CSV record starting at `at` (advanced past its line break).
std::vector<std::string> CsvRecord(const std::string& text, std::size_t* at, long* line,
                                   const std::string& file) {
  std::vector<std::string> cells(1);
  std::size_t i = *at;
  bool quoted = false, was_quoted = false;
  const long first_line = *line;
  while (i < text.size()) {
    const char c = text[i];
    if (quoted) {
      if (c == '"') {
        if (i + 1 < text.size() && text[i + 1] == '"') {
          cells.back() += '"';
          i += 2;
          continue;
        }
        quoted = false;
      } else {
        if (c == '\n') ++*line;
        cells.back() += c;
      }
      ++i;
      continue;
    }
    if (c == '"' && Trim(cells.back()).empty() && !was_quoted) {
      cells.back().clear();
      quoted = was_quoted = true;
    } else if (c == ',') {
      cells.emplace_back();
      was_quoted = false;
    } else if (c == '\n') {
      ++i;
      ++*line;
      break;
    } else if (c != '\r') {
      if (was_quoted && c != ' ' && c != '\t')
        throw Error(EscapeText(file) + ":" + std::to_string(*line) +
                    ": text after a quoted cell (a quote inside a quoted cell is written \"\")");
      cells.back() += c;
    }
    ++i;
  }
  if (quoted)
    throw Error(EscapeText(file) + ":" + std::to_string(first_line) + ": a quoted cell never ends");
  *at = i;
  return cells;
}

// Whether `v` is meant as a range A..B: ".." outside quotes, brackets and braces (no TOML value
// has it there).
bool LooksLikeRange(const std::string& v) {
  const std::size_t dots = v.find("..");
  return dots != std::string::npos && v.find_first_of("\"'[{") == std::string::npos;
}

// A whole number of a range's end, or Error naming the key and the range.
long long RangeEnd(const std::string& text, const std::string& key, const std::string& range) {
  const std::string t = Trim(text);
  std::size_t used = 0;
  long long v = 0;
  bool ok = !t.empty() && t.find_first_not_of("+-0123456789") == std::string::npos;
  if (ok) {
    try {
      v = std::stoll(t, &used);
    } catch (const std::exception&) {
      ok = false;
    }
  }
  if (!ok || used != t.size())
    throw Error(EscapeText(key) + ": the range " + QuoteText(range) +
                ": expected whole numbers A..B (e.g. 1..10), got " + QuoteText(t));
  return v;
}

}  // namespace

std::vector<std::string> ExpandWholeRange(const std::string& range, const std::string& key) {
  const std::size_t dots = range.find("..");
  const long long a = RangeEnd(range.substr(0, dots), key, range);
  const long long b = RangeEnd(range.substr(dots + 2), key, range);
  if (b < a)
    throw Error(EscapeText(key) + ": the range " + QuoteText(range) +
                " is empty; expected A..B with A <= B");
  if (static_cast<double>(b) - static_cast<double>(a) + 1 > kMaxSweepRange)
    throw Error(EscapeText(key) + ": the range " + QuoteText(range) + " has " +
                FormatNumber(static_cast<double>(b) - static_cast<double>(a) + 1) +
                " values; expected at most " + FormatNumber(kMaxSweepRange));
  std::vector<std::string> values;
  for (long long v = a; v <= b; ++v) values.push_back(std::to_string(v));
  return values;
}

SweepKey ParseSetOption(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos)
    throw Error("expected KEY=V1,V2,... (a scene key, then its values), got " + QuoteText(text));
  SweepKey k;
  k.key = Trim(text.substr(0, eq));
  CheckKeyPath(k.key);
  const std::string list = text.substr(eq + 1);
  // The values: split at the commas outside [], {} and quotes.
  std::string cell;
  int depth = 0;
  char quote = 0;
  auto take = [&] {
    const std::string v = Trim(cell);
    cell.clear();
    if (LooksLikeRange(v)) {
      for (std::string& w : ExpandWholeRange(v, k.key)) k.values.push_back(std::move(w));
      return;
    }
    CheckValueText(v, EscapeText(k.key) + ": value " + std::to_string(k.values.size() + 1));
    k.values.push_back(v);
  };
  for (std::size_t i = 0; i < list.size(); ++i) {
    const char c = list[i];
    if (quote) {
      cell += c;
      if (c == '\\' && quote == '"' && i + 1 < list.size()) cell += list[++i];
      else if (c == quote) quote = 0;
      continue;
    }
    if (c == '"' || c == '\'') quote = c;
    if (c == '[' || c == '{') ++depth;
    if ((c == ']' || c == '}') && depth > 0) --depth;
    if (c == ',' && depth == 0) {
      take();
      continue;
    }
    cell += c;
  }
  take();
  return k;
}

SweepCases ReadCasesCsv(const std::string& path) {
  const std::string name = EscapeText(path);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw Error(name + ": is a directory; expected a CSV file of cases");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(name + ": cannot open the cases file: " + std::strerror(errno));
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxCasesFileBytes)
      throw Error(name + ": larger than 64 MiB; expected a CSV file of cases");
  }
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);  // a UTF-8 byte order mark
  SweepCases cases;
  std::size_t at = 0;
  long line = 1;
  while (at < text.size()) {
    const long row_line = line;
    std::vector<std::string> cells = CsvRecord(text, &at, &line, path);
    for (std::string& c : cells) c = Trim(c);
    if (cells.size() == 1 && cells[0].empty()) continue;  // a blank line
    if (cases.keys.empty()) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        try {
          CheckKeyPath(cells[i]);
        } catch (const Error& e) {
          throw Error(name + ":" + std::to_string(row_line) + ": column " +
                      std::to_string(i + 1) + " of the header: " + e.what());
        }
      }
      cases.keys = cells;
      continue;
    }
    if (cells.size() != cases.keys.size())
      throw Error(name + ":" + std::to_string(row_line) + ": expected " +
                  std::to_string(cases.keys.size()) + " values (one per key of the header), got " +
                  std::to_string(cells.size()));
    for (std::size_t i = 0; i < cells.size(); ++i)
      CheckValueText(cells[i], name + ":" + std::to_string(row_line) + ": " +
                                   EscapeText(cases.keys[i]));
    if (static_cast<double>(cases.rows.size()) >= kMaxSweepCases)
      throw Error(name + ":" + std::to_string(row_line) + ": more than " +
                  FormatNumber(kMaxSweepCases) + " cases; expected at most that many");
    cases.rows.push_back(std::move(cells));
  }
  if (cases.keys.empty()) throw Error(name + ": empty; expected a header naming the keys");
  if (cases.rows.empty())
    throw Error(name + ": no case; expected a row of values after the header");
  return cases;
}

SweepCases ExpandCases(const SweepCases& listed, const std::vector<SweepKey>& sets) {
  SweepCases out;
  out.keys = listed.keys;
  std::set<std::string> seen;
  for (const std::string& k : listed.keys)
    if (!seen.insert(k).second) throw Error(EscapeText(k) + ": a column of the cases twice");
  double count = std::max<std::size_t>(1, listed.rows.size());
  for (const SweepKey& s : sets) {
    if (!seen.insert(s.key).second)
      throw Error(EscapeText(s.key) + ": given twice (by two --set, or by --set and --cases)");
    out.keys.push_back(s.key);
    count *= static_cast<double>(s.values.size());
  }
  if (count > kMaxSweepCases)
    throw Error("the sweep has " + FormatNumber(count) + " cases; expected at most " +
                FormatNumber(kMaxSweepCases));
  out.rows = listed.rows.empty() ? std::vector<std::vector<std::string>>{{}} : listed.rows;
  for (const SweepKey& s : sets) {
    std::vector<std::vector<std::string>> next;
    next.reserve(out.rows.size() * s.values.size());
    for (const auto& row : out.rows)
      for (const std::string& v : s.values) {
        next.push_back(row);
        next.back().push_back(v);
      }
    out.rows = std::move(next);
  }
  // Rows in the order of the keys: listed first, then each --set (the first varying slowest).
  return out;
}

std::string CaseFolderName(size_t index, size_t count) {
  std::size_t width = 3;
  for (std::size_t n = count > 0 ? count - 1 : 0; n >= 1000; n /= 10) ++width;
  std::string digits = std::to_string(index);
  if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
  return "case_" + digits;
}

std::string CsvCell(const std::string& text) {
  const bool quote = text.find_first_of(",\"\r\n") != std::string::npos ||
                     (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!quote) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace cablefilm