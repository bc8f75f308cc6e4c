#pragma once
// Reads a scene file (scene-format.md) into a SceneDef. Every problem is an Error that names the
// file, the line, the key (e.g. cable.section[1].length) and what was expected; unknown keys
// are errors, so a typo is never silently ignored.
#include <string>
#include <vector>

#include "scene/scene_def.h"
#include "scene/scene_parser.h"

namespace cablefilm {

// A scene file, or a MoorDyn v2 input file (IsMoorDynText) read through its equivalent scene
// (scene/moordyn_convert.h; its warnings in SceneDef::warnings).
SceneDef LoadScene(const std::string& path);
// Whether a file's text is a MoorDyn input file (its section headers, "---- LINES ----").
bool IsMoorDynText(const std::string& text);
// The scene (TOML) equivalent to a MoorDyn input file; what it leaves out in `warnings`.
std::string MoorDynSceneText(const std::string& path, std::vector<std::string>* warnings);
// The scene text whose keys a sweep edits: a scene file's own, a MoorDyn file's equivalent scene
// (MoorDynSceneText, its warnings in `warnings`), so that its keys are the scene's.
std::string EditableSceneText(const std::string& path, std::vector<std::string>* warnings);
// The text of a scene file, at most kMaxSceneBytes (checked while reading: /dev/zero is refused).
std::string ReadSceneFile(const std::string& path);

// An error about the scene `scene_path` as the program reports it after "cablefilm: error: ":
// `what`, led by the scene's name unless it starts with it already (the loader's messages do).
std::string SceneErrorMessage(const std::string& scene_path, const std::string& what);

}  // namespace cablefilm
