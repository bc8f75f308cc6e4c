#pragma once
// The Python module's Scene: a scene's TOML text and the path it came from, always valid. It
// is read by the same loader as `cablefilm check` (scene_loader.h), and its model built and
// checked as `check` and `run` build and check it (BuildModel, then CheckModelLimits); a change
// of a value goes through the sweep's editing of scene keys (scene/scene_edit.h) and is read
// again, so a bad value is refused with the loader's message and the scene keeps its former
// text.
#include <stdexcept>
#include <string>
#include <vector>

#include "core/model.h"
#include "scene/scene_def.h"

namespace cablefilm::python {

// Thrown for a scene the loader refuses; its message is what `cablefilm check` prints after
// "cablefilm: error: ". The module raises it as cablefilm.SceneError (a ValueError).
struct SceneProblem : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class SceneHandle {
 public:
  // A scene file, read as `cablefilm check SCENE` reads it.
  static SceneHandle FromFile(const std::string& path);
  // TOML text; `path` names it in messages and is where a motion table's relative file is
  // found from (its folder).
  static SceneHandle FromText(const std::string& text, const std::string& path);

  const std::string& text() const { return text_; }
  const std::string& path() const { return path_; }
  const SceneDef& def() const { return def_; }
  // Its model: its lines, points and bodies (a [cable] scene: the line "cable" between the
  // points "start" and "end").
  const Model& model() const { return model_; }

  // Sets keys[i] (dotted scene paths) to the TOML values values[i], all at once; on a problem
  // throws SceneProblem (or Error for a key that does not fit the scene) and changes nothing.
  void Set(const std::vector<std::string>& keys, const std::vector<std::string>& values);
  // The value of a key as a TOML document "v = ..." (see scene/scene_edit.h).
  std::string ValueDocument(const std::string& key) const;

 private:
  SceneHandle(std::string text, std::string path, SceneDef def, Model model)
      : text_(std::move(text)), path_(std::move(path)), def_(std::move(def)),
        model_(std::move(model)) {}
  static SceneHandle Checked(std::string text, std::string path, SceneDef def);
  std::string text_;
  std::string path_;
  SceneDef def_;
  Model model_;
};

}  // namespace cablefilm::python
