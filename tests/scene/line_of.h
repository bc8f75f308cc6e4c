#pragma once
// The one line of a scene of one line, as BuildModel makes it.
#include "scene/build_model.h"

namespace cablefilm {

inline LineModel LineOf(const SceneDef& scene) { return BuildModel(scene).lines.front(); }

}  // namespace cablefilm
