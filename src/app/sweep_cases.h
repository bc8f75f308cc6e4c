#pragma once
// The cases of a sweep: which scene keys take which values, and each case's scene, the original
// TOML with its values set (edited with toml++ and printed, so every other value is kept to
// the last bit). Keys are dotted scene paths as the loader's messages spell them:
// environment.current, ends.end.period, material[0].youngs_modulus, cable.section[1].segments,
// film.tension_range[1]. Values are TOML values (0.5, 30, "explicit", [1.0, 0.0]); a bare word
// (explicit) is taken as a string.
#include <string>
#include <vector>

namespace cablefilm {

// At most this many cases in one sweep (the cross product is checked before it is built).
constexpr double kMaxSweepCases = 1e5;

// One --set: a key and its values, each value's text as given (trimmed).
struct SweepKey {
  std::string key;
  std::vector<std::string> values;
};

// "KEY=V1,V2,...": the values split at the commas outside brackets, braces and quotes. Throws
// Error with a message naming the key (or the option) when the key is no dotted path or a
// value is no TOML value.
SweepKey ParseSetOption(const std::string& text);

// Throws Error when `text` is no TOML value (nor a bare word); `where` starts the message.
void CheckValueText(const std::string& text, const std::string& where);

// The cases: keys (columns) and one row of value texts per case.
struct SweepCases {
  std::vector<std::string> keys;
  std::vector<std::vector<std::string>> rows;
};

// A CSV of cases (RFC 4180: commas, double quotes around a cell that holds commas): a header
// naming the keys, then one row of values per case. Throws Error naming the file and the line.
SweepCases ReadCasesCsv(const std::string& path);

// The cases: every row of `listed` (none: one empty case) times the cross product of `sets`,
// the first --set varying slowest. Throws Error on a key given twice or too many cases.
SweepCases ExpandCases(const SweepCases& listed, const std::vector<SweepKey>& sets);

// The scene text of one case: `scene_text` (the file `scene_path`) with keys[i] set to the
// TOML value values[i], a motion table's relative `file` made absolute (so the case's scene
// runs from its own folder), a missing title set to the original's default (its file name),
// `comment` (lines, each starting with #) first. Throws Error
// naming the key when the scene is no TOML or a key's path does not fit the scene (an index
// beyond an array, a table where a value is, ...); whether the key is one the scene format
// knows is for the loader to say.
std::string CaseSceneText(const std::string& scene_text, const std::string& scene_path,
                          const std::vector<std::string>& keys,
                          const std::vector<std::string>& values, const std::string& comment);

// The value of `key` (a dotted path, as above) in `scene_text` (the file `scene_path`), as a
// TOML document whose one key "v" holds it ("v = 0.5", or "[v]" and its keys for a table).
// Throws Error naming the key when the scene is no TOML or has no such value.
std::string SceneValueDocument(const std::string& scene_text, const std::string& scene_path,
                               const std::string& key);

// Case folder names: case_000, case_001, ... (more digits beyond 1000 cases).
std::string CaseFolderName(size_t index, size_t count);

// A CSV cell: quoted when it holds a comma, a quote or a line break.
std::string CsvCell(const std::string& text);

}  // namespace cablefilm
