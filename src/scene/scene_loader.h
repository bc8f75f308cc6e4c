#pragma once
// Reads a scene file (scene-format.md) into a SceneDef. Every problem is an Error that names the
// file, the line, the key (e.g. cable.section[1].length) and what was expected; unknown keys
// are errors, so a typo is never silently ignored.
#include <string>

#include "scene/scene_def.h"
#include "scene/scene_parser.h"

namespace cablefilm {

SceneDef LoadScene(const std::string& path);
// The text of a scene file, at most kMaxSceneBytes (checked while reading: /dev/zero is refused).
std::string ReadSceneFile(const std::string& path);

// An error about the scene `scene_path` as the program reports it after "cablefilm: error: ":
// `what`, led by the scene's name unless it starts with it already (the loader's messages do).
std::string SceneErrorMessage(const std::string& scene_path, const std::string& what);

}  // namespace cablefilm
