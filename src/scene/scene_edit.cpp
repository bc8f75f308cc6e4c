#include "scene/scene_edit.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>
#include <toml++/toml.h>

#include "core/error.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

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

// A relative file a scene names (a motion's table `file`, a vessel's `rao_file`, a sea's
// spectrum table or record `file`, the current's `current_file`, a drift's `drift_file`), made
// absolute from the scene's folder: the case's scene
// lives elsewhere.
void AbsoluteFilePaths(toml::table& root, const std::string& scene_path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path base = fs::absolute(fs::path(scene_path).parent_path(), ec);
  if (ec) return;
  auto fix = [&](toml::table* t) {
    if (!t) return;
    for (const char* key : {"file", "rao_file", "current_file", "drift_file"}) {
      const toml::value<std::string>* file = (*t)[key].as_string();
      if (!file || file->get().empty() || file->get().find('\0') != std::string::npos) continue;
      const fs::path name(file->get());
      if (name.is_absolute()) continue;
      t->insert_or_assign(key, (base / name).lexically_normal().string());
    }
  };
  if (toml::table* ends = root["ends"].as_table())
    for (const char* which : {"start", "end"}) fix((*ends)[which].as_table());
  fix(root["waves"].as_table());
  fix(root["environment"].as_table());
  for (const char* list : {"point", "body"})
    if (toml::array* a = root[list].as_array())
      for (toml::node& n : *a) fix(n.as_table());
}

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

void CheckKeyPath(const std::string& key) { ParseKeyPath(key); }

void CheckValueText(const std::string& text, const std::string& where) {
  toml::table t;
  std::string why;
  if (text.empty()) throw Error(where + ": an empty value; expected a TOML value");
  if (!ParseValue(text, &t, &why))
    throw Error(where + ": expected a TOML value (a number, \"a string\" or a bare word, an "
                        "array [1, 2]), got " +
                QuoteText(text) + (why.empty() ? "" : " (" + EscapeText(why) + ")"));
}

std::string EditSceneText(const std::string& scene_text, const std::string& scene_path,
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
  AbsoluteFilePaths(root, scene_path);
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
}  // namespace cablefilm
