#pragma once
// A run's initial state, as its scene says: the static equilibrium with the ends at rest (the
// paper's) or every line on its chord at rest; the free bodies where it puts them, or at their
// initial offsets from there (a decay test).
#include <functional>
#include <vector>

#include "core/cancel.h"
#include "core/equilibrium.h"
#include "core/model.h"
#include "run/time_grid.h"
#include "scene/scene_def.h"

namespace cablefilm {

// The callbacks of the statics' progress (EquilibriumOptions::solving, ::relaxing).
struct StaticsCallbacks {
  std::function<void(double)> relaxing, solving;
};

// The scene's initial state of every line of `model` (built from `scene`): its static
// equilibrium (the report filled; where Newton fails on a coupled island, the relaxation's
// with the grid's step options), or the straight chords. Each free body is placed (PlaceBody)
// where its run starts: its equilibrium, or its initial offset from there with its lines in
// equilibrium with it held. Throws Error naming the key at fault when the equilibrium is not
// found or stretches a link beyond kMaxStartStretch (the integrators would stop at t = 0 with
// a numerical blow-up), CancelledError when `cancel` is raised.
std::vector<State> MakeInitialState(const SceneDef& scene, Model& model, const TimeGrid& grid,
                                    EquilibriumReport* report, const CancelFlag* cancel,
                                    const StaticsCallbacks& progress = {});

}  // namespace cablefilm
