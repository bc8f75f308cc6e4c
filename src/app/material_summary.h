#pragma once
// What `check` says of the materials beyond the paper's model: the tangential (axial) drag and
// added mass, one line per material that has them (nothing for the others).
#include "scene/scene_def.h"

namespace cablefilm {

void PrintTangentialMaterials(const SceneDef& scene);

}  // namespace cablefilm
