#pragma once
// How messages name a scene key. A scene file's key is named as it is ("scene.toml:
// material[0].youngs_modulus"); a key of the scene converted from a MoorDyn file by the row and
// column its value came from, as the MoorDyn reader names them ("sys.txt:6: LINE TYPES row 1,
// column EA"): the file's author never wrote the scene's keys.
#include <map>
#include <string>

namespace cablefilm {

// Where a value of a MoorDyn file's scene came from.
struct KeySource {
  int line = 0;       // of the MoorDyn file, 1-based
  std::string place;  // "LINE TYPES row 1, column EA", "LINES row 2", "OPTIONS WtrDpth"
};
// By scene key: a value's ("material[0].youngs_modulus") or a table's ("line[1]").
using KeySources = std::map<std::string, KeySource>;

struct SceneDef;

// The key's place for a key with a source ("LINE TYPES row 1, column EA"), else the key.
std::string KeyName(const SceneDef& scene, const std::string& key);

// "file:line: " + the place for a key with a source, else "file: key" (the file escaped).
std::string KeyPlace(const SceneDef& scene, const std::string& key);

// A loader's message "file:N: key: ..." about the scene converted from the MoorDyn file `file`
// told at the key's row and column instead: "file:line: PLACE (the scene's key): ...". "" when
// it names no key of `sources` (N is a line of the converted scene, not of the file).
std::string MoorDynKeyMessage(const std::string& message, const std::string& file,
                              const KeySources& sources);

}  // namespace cablefilm
