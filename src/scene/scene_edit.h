#pragma once
// A scene edited key by key in its TOML text (toml++, printed again, so every other value is
// kept to the last bit): what a sweep's cases and the Python module's Scene.set do. Keys are
// dotted scene paths as the loader's messages spell them: environment.current,
// ends.end.period, material[0].youngs_modulus, cable.section[1].segments,
// film.tension_range[1]. Values are TOML values (0.5, 30, "explicit", [1.0, 0.0]); a bare word
// (explicit) is taken as a string. Whether a key is one the scene format knows is for the
// loader to say.
#include <string>
#include <vector>

namespace cablefilm {

// Throws Error naming the key unless it is a dotted path: name[i]...(.name[i]...)*, names of
// letters, digits, _ and -.
void CheckKeyPath(const std::string& key);

// Throws Error when `text` is no TOML value (nor a bare word); `where` starts the message.
void CheckValueText(const std::string& text, const std::string& where);

// `scene_text` (the file `scene_path`) with keys[i] set to the TOML value values[i], a motion
// table's relative `file` made absolute (so the edited scene runs from any folder), a missing
// title set to the original's default (its file name), `comment` (lines, each starting with #)
// first. Throws Error naming the key when the scene is no TOML or a key's path does not fit the
// scene (an index beyond an array, a table where a value is, ...).
std::string EditSceneText(const std::string& scene_text, const std::string& scene_path,
                          const std::vector<std::string>& keys,
                          const std::vector<std::string>& values, const std::string& comment);

// The value of `key` in `scene_text` (the file `scene_path`), as a TOML document whose one key
// "v" holds it ("v = 0.5", or "[v]" and its keys for a table). Throws Error naming the key
// when the scene is no TOML or has no such value.
std::string SceneValueDocument(const std::string& scene_text, const std::string& scene_path,
                               const std::string& key);

}  // namespace cablefilm
