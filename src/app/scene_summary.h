#pragma once
// What `check` and `run` say of a scene before it runs, and of its initial state: its lines
// (a line alone: its stations, mass and net weight; several: each line, point and body), the
// materials' terms beyond the paper's, the current, the seabed, the waves, the scheme and its
// step, the recorded motions; then the static equilibrium as it was found.
#include "core/equilibrium.h"
#include "core/model.h"
#include "run/run.h"
#include "run/time_grid.h"
#include "scene/scene_def.h"

namespace cablefilm {

void PrintScene(const SceneDef& scene, const Model& model, const TimeGrid& grid);

// The initial state of `run` (written to equilibrium<suffix>.csv): the static equilibrium's
// iterations and residual, or the straight chords; a line alone's end tensions.
void PrintInitialState(const SceneDef& scene, const Run& run, const std::string& suffix);

}  // namespace cablefilm
