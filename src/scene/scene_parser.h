#pragma once
// The scene's schema (scene-format.md, docs/scene-format.md): its TOML tables and keys read into
// a SceneDef, each value checked (toml_reader.h), then the rules across keys (scene_checks.h).
#include <string>

#include "scene/scene_def.h"
#include "scene/key_log.h"

namespace cablefilm {

// `path` names the scene in messages and is where a motion table's relative file is found from.
// `keys` (optional) collects every key the schema asks for. Throws Error "file:line: key: ...".
SceneDef ParseScene(const std::string& text, const std::string& path, KeyLog* keys = nullptr);

}  // namespace cablefilm
