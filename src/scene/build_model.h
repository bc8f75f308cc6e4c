#pragma once
// From the scene's plain data to the physics model (parse, then build).
#include "core/model.h"
#include "scene/scene_def.h"

namespace cablefilm {

Model BuildModel(const SceneDef& scene);

// The scene's [waves] for the core (phase in rad); not present without the table.
WaveSpec MakeWaveSpec(const SceneDef& scene);

// The station a weight's arc length falls on (the loader has checked that it does).
int StationAt(const SceneDef& scene, double arc_length);

}  // namespace cablefilm
