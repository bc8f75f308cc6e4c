#include "python/scene_handle.h"

#include "core/error.h"
#include "scene/build_model.h"
#include "scene/scene_edit.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"

namespace cablefilm::python {

SceneHandle SceneHandle::Checked(std::string text, std::string path, SceneDef def) {
  // What `check` does before the equilibrium: the model built and its limits.
  try {
    Model model = BuildModel(def);
    CheckModelLimits(def, model);
    return SceneHandle(std::move(text), std::move(path), std::move(def), std::move(model));
  } catch (const Error& e) {
    throw SceneProblem(SceneErrorMessage(path, e.what()));
  }
}

SceneHandle SceneHandle::FromFile(const std::string& path) {
  SceneDef def;
  try {
    def = LoadScene(path);
  } catch (const Error& e) {
    throw SceneProblem(SceneErrorMessage(path, e.what()));
  }
  // The loader has read it whole (a regular file, within the size limit): its text again, for
  // later edits (a MoorDyn file's equivalent scene, whose keys are edited).
  std::string text;
  try {
    text = EditableSceneText(path, nullptr);
  } catch (const Error& e) {
    throw SceneProblem(SceneErrorMessage(path, e.what()));
  }
  return Checked(std::move(text), path, std::move(def));
}

SceneHandle SceneHandle::FromText(const std::string& text, const std::string& path) {
  SceneDef def;
  try {
    def = ParseScene(text, path);
  } catch (const Error& e) {
    throw SceneProblem(SceneErrorMessage(path, e.what()));
  }
  return Checked(text, path, std::move(def));
}

void SceneHandle::Set(const std::vector<std::string>& keys,
                      const std::vector<std::string>& values) {
  std::string edited;
  try {
    edited = EditSceneText(text_, path_, keys, values, "");
  } catch (const Error& e) {
    throw SceneProblem(e.what());
  }
  *this = FromText(edited, path_);
}

std::string SceneHandle::ValueDocument(const std::string& key) const {
  return SceneValueDocument(text_, path_, key);
}

}  // namespace cablefilm::python
