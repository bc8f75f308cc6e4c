#include "python/scene_handle.h"

#include <fstream>
#include <sstream>

#include "scene/film_settings.h"
#include "scene/scene_loader.h"
#include "run/sweep_plan.h"
#include "scene/scene_edit.h"
#include "core/error.h"
#include "scene/build_model.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"

namespace cablefilm::python {

SceneHandle SceneHandle::Checked(std::string text, std::string path, SceneDef def) {
  // What `check` does before the equilibrium: the model built and its limits.
  // A system as `run` builds it (the loader has checked its numbers).
  try {
    if (def.is_system()) {
      Model system = BuildSystem(def);
      return SceneHandle(std::move(text), std::move(path), std::move(def), std::nullopt,
                         std::move(system));
    }
    LineModel model = BuildModel(def);
    CheckModelLimits(def, model);
    return SceneHandle(std::move(text), std::move(path), std::move(def), std::move(model),
                       std::nullopt);
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
  // later edits.
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return Checked(text.str(), path, std::move(def));
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

const LineModel& SceneHandle::model() const {
  if (!model_)
    throw SceneProblem(path_ + ": a system of lines ([[line]] and [[point]]): this takes a "
                       "single line ([cable] and [ends])");
  return *model_;
}

const Model& SceneHandle::system() const {
  if (!system_)
    throw SceneProblem(path_ + ": a single line ([cable] and [ends]): this takes a system of "
                       "lines ([[line]], [[point]], [[body]])");
  return *system_;
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
