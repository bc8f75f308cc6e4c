#include "app/sweep_cases.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "core/error.h"
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

// One step of a key's path: a name and the indices after it (material[0] -> "material", {0}).
struct PathStep {
  std::string name;
  std::vector<std::size_t> indices;
};

bool IsKeyChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
}

// Throws Error unless `key` is name[i]...(.name[i]...)*, names of letters, digits, _ and -.
std::vector<PathStep> ParseKeyPath(const std::string& key) {
  const auto bad = [&](const std::string& why) -> Error {
    return Error(EscapeText(key.empty() ? std::string("--set") : key) +
                 ": expected a dotted scene key such as environment.current, "
                 "ends.end.period or material[0].youngs_modulus" +
                 (why.empty() ? "" : " (" + why + ")"));
  };
  std::vector<PathStep> path;
  std::size_t i = 0;
  while (true) {
    PathStep step;
    while (i < key.size() && IsKeyChar(key[i])) step.name += key[i++];
    if (step.name.empty()) throw bad(key.empty() ? "the key is empty" : "an empty name");
    while (i < key.size() && key[i] == '[') {
      const std::size_t close = key.find(']', i);
      const std::string digits = close == std::string::npos ? "" : key.substr(i + 1, close - i - 1);
      if (digits.empty() || digits.size() > 9 ||
          digits.find_first_not_of("0123456789") != std::string::npos)
        throw bad("an index is a whole number in brackets, [0]");
      step.indices.push_back(std::stoul(digits));
      i = close + 1;
    }
    path.push_back(step);
    if (i == key.size()) return path;
    if (key[i] != '.') throw bad("unexpected " + QuoteText(std::string(1, key[i])));
    ++i;
  }
}

// The value of `text` as the one key "v" of a table, or an explanation in `why`.
bool ParseValue(const std::string& text, toml::table* out, std::string* why) {
  if (text.find_first_of("\n\r") != std::string::npos) {
    *why = "a line break";
    return false;
  }
  try {
    toml::table t = toml::parse("v = " + text);
    if (t.size() == 1 && t.contains("v")) {
      *out = std::move(t);
      return true;
    }
    *why = "more than one value";
  } catch (const toml::parse_error& e) {
    *why = std::string(e.description());
  }
  // A bare word is a string: explicit, viridis, table.
  const bool bare = !text.empty() && std::isalpha(static_cast<unsigned char>(text[0])) &&
                    std::all_of(text.begin(), text.end(), [](char c) {
                      return std::isalnum(static_cast<unsigned char>(c)) || c == '_' ||
                             c == '-' || c == '.' || c == '+';
                    });
  if (!bare) return false;
  out->clear();
  out->insert("v", text);
  return true;
}

// What a node is, for messages.
std::string Kind(const toml::node& n) {
  if (const toml::array* a = n.as_array())
    return a->is_array_of_tables() && !a->empty()
               ? "an array of " + std::to_string(a->size()) + " tables"
               : "an array of " + std::to_string(a->size()) + " values";
  if (n.is_table()) return "a table";
  if (n.is_string()) return "a string";
  if (n.is_boolean()) return "true or false";
  if (n.is_number()) return "a number";
  return "a date or time";
}

[[noreturn]] void PathFail(const std::string& key, const std::string& why) {
  throw Error(EscapeText(key) + ": " + why);
}

// Sets `key` (parsed as `path`) of `root` to the value "v" of `value`: tables on the way that
// the scene lacks are made; indices must name elements the scene has.
void SetValue(toml::table& root, const std::string& key, const std::vector<PathStep>& path,
              const toml::node& value) {
  toml::table* table = &root;
  std::string here;
  for (std::size_t s = 0; s < path.size(); ++s) {
    const PathStep& step = path[s];
    const bool last = s + 1 == path.size();
    here += (here.empty() ? "" : ".") + step.name;
    toml::node* node = table->get(step.name);
    if (last && step.indices.empty()) {
      table->insert_or_assign(step.name, value);
      return;
    }
    if (!node) {
      if (!step.indices.empty())
        PathFail(key, "the scene has no " + EscapeText(here) + " to index");
      node = &table->insert_or_assign(step.name, toml::table{}).first->second;
    }
    for (std::size_t k = 0; k < step.indices.size(); ++k) {
      toml::array* array = node->as_array();
      if (!array)
        PathFail(key, EscapeText(here) + " is " + Kind(*node) + " in the scene, not an array");
      const std::size_t index = step.indices[k];
      if (index >= array->size())
        PathFail(key, EscapeText(here) + " is " + Kind(*node) + " in the scene" +
                          (array->empty() ? "" : ", [0] to [" +
                                                     std::to_string(array->size() - 1) + "]") +
                          ": no [" + std::to_string(index) + "]");
      here += "[" + std::to_string(index) + "]";
      if (last && k + 1 == step.indices.size()) {
        array->replace(array->cbegin() + static_cast<std::ptrdiff_t>(index), value);
        return;
      }
      node = array->get(index);
    }
    if (!node->is_table()) {
      const toml::array* a = node->as_array();
      if (a && a->is_array_of_tables() && !a->empty())
        PathFail(key, EscapeText(here) + " is " + Kind(*node) + " [[" + EscapeText(here) +
                          "]] in the scene: name one, " + EscapeText(here) + "[0] to " +
                          EscapeText(here) + "[" + std::to_string(a->size() - 1) + "]");
      PathFail(key, EscapeText(here) + " is " + Kind(*node) + " in the scene, not a table");
    }
    table = node->as_table();
  }
}

// A relative `file` of a table motion, made absolute from the scene's folder: the case's scene
// lives elsewhere.
void AbsoluteTablePaths(toml::table& root, const std::string& scene_path) {
  toml::table* ends = root["ends"].as_table();
  if (!ends) return;
  namespace fs = std::filesystem;
  for (const char* which : {"start", "end"}) {
    toml::table* end = (*ends)[which].as_table();
    if (!end) continue;
    const toml::value<std::string>* file = (*end)["file"].as_string();
    if (!file || file->get().empty() || file->get().find('\0') != std::string::npos) continue;
    const fs::path name(file->get());
    if (name.is_absolute()) continue;
    std::error_code ec;
    const fs::path base = fs::absolute(fs::path(scene_path).parent_path(), ec);
    if (ec) continue;
    end->insert_or_assign("file", (base / name).lexically_normal().string());
  }
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

}  // namespace

void CheckValueText(const std::string& text, const std::string& where) {
  toml::table t;
  std::string why;
  if (text.empty()) throw Error(where + ": an empty value; expected a TOML value");
  if (!ParseValue(text, &t, &why))
    throw Error(where + ": expected a TOML value (a number, \"a string\" or a bare word, an "
                        "array [1, 2]), got " +
                QuoteText(text) + (why.empty() ? "" : " (" + EscapeText(why) + ")"));
}

SweepKey ParseSetOption(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos)
    throw Error("expected KEY=V1,V2,... (a scene key, then its values), got " + QuoteText(text));
  SweepKey k;
  k.key = Trim(text.substr(0, eq));
  ParseKeyPath(k.key);
  const std::string list = text.substr(eq + 1);
  // The values: split at the commas outside [], {} and quotes.
  std::string cell;
  int depth = 0;
  char quote = 0;
  auto take = [&] {
    const std::string v = Trim(cell);
    CheckValueText(v, EscapeText(k.key) + ": value " + std::to_string(k.values.size() + 1));
    k.values.push_back(v);
    cell.clear();
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
          ParseKeyPath(cells[i]);
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

namespace {

// The scene's text as a TOML table; not TOML: an Error naming the file and line.
toml::table ParseSceneToml(const std::string& scene_text, const std::string& scene_path) {
  try {
    return toml::parse(scene_text, scene_path);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << EscapeText(scene_path) << ":" << e.source().begin.line
       << ": not valid TOML: " << EscapeText(e.description());
    throw Error(os.str());
  }
}

}  // namespace

std::string CaseSceneText(const std::string& scene_text, const std::string& scene_path,
                          const std::vector<std::string>& keys,
                          const std::vector<std::string>& values, const std::string& comment) {
  toml::table root = ParseSceneToml(scene_text, scene_path);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    toml::table value;
    std::string why;
    if (!ParseValue(values[i], &value, &why))  // checked when the option was read
      throw Error(EscapeText(keys[i]) + ": not a TOML value: " + QuoteText(values[i]));
    SetValue(root, keys[i], ParseKeyPath(keys[i]), *value.get("v"));
  }
  AbsoluteTablePaths(root, scene_path);
  // The title a scene without one gets is its file's name: the original's, not "scene".
  if (!root.contains("title"))
    root.insert("title", std::filesystem::path(scene_path).stem().string());
  std::ostringstream os;
  os << comment << root << "\n";
  return os.str();
}

std::string SceneValueDocument(const std::string& scene_text, const std::string& scene_path,
                               const std::string& key) {
  toml::table root = ParseSceneToml(scene_text, scene_path);
  const std::vector<PathStep> path = ParseKeyPath(key);
  const toml::node* node = &root;
  std::string here;
  for (const PathStep& step : path) {
    const toml::table* table = node->as_table();
    if (!table) PathFail(key, EscapeText(here) + " is " + Kind(*node) + " in the scene, not a table");
    here += (here.empty() ? "" : ".") + step.name;
    node = table->get(step.name);
    if (!node) PathFail(key, "the scene has no " + EscapeText(here));
    for (const std::size_t index : step.indices) {
      const toml::array* array = node->as_array();
      if (!array)
        PathFail(key, EscapeText(here) + " is " + Kind(*node) + " in the scene, not an array");
      if (index >= array->size())
        PathFail(key, EscapeText(here) + " is " + Kind(*node) + " in the scene: no [" +
                          std::to_string(index) + "]");
      here += "[" + std::to_string(index) + "]";
      node = array->get(index);
    }
  }
  toml::table out;
  out.insert("v", *node);
  std::ostringstream os;
  os << out << "\n";
  return os.str();
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
