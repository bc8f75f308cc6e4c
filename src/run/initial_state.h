#pragma once
// A run's initial state, as its scene says: the static equilibrium with the ends at rest (the
// paper's) or the straight chord at rest; and the LineData a run starts from.
#include "core/cancel.h"
#include "core/line_data.h"
#include "core/line_equilibrium.h"
#include "core/model.h"
#include "run/time_grid.h"
#include "scene/scene_def.h"

namespace cablefilm {

// The scene's initial state: static equilibrium (the report is filled) or the straight chord.
// Throws Error when the equilibrium is not found, CancelledError when `cancel` is raised.
State MakeInitialState(const SceneDef& scene, const LineModel& m, LineEquilibriumReport* report,
                       const CancelFlag* cancel = nullptr);

// Throws Error naming the key at fault when a system's static equilibrium (`states`, a line
// each) stretches a link beyond kMaxStartStretch, as MakeInitialState does for one line: the
// integrators would stop at t = 0 with a numerical blow-up.
void CheckSystemInitialStretch(const SceneDef& scene, const Model& sys,
                               const std::vector<State>& states);

}  // namespace cablefilm
