#pragma once
// A scene of one line as the tests take it: its line's model and its initial state, as a run
// builds and finds them (BuildModel, MakeInitialState).
#include "core/equilibrium.h"
#include "run/initial_state.h"
#include "run/time_grid.h"
#include "scene/build_model.h"
#include "../scene/line_of.h"

namespace cablefilm {

// A scene of one line's initial state as a run makes it (MakeInitialState), its line's statics'
// report in `report`.
inline State InitialStateOf(const SceneDef& scene, LineEquilibriumReport* report = nullptr,
                            const CancelFlag* cancel = nullptr) {
  Model model = BuildModel(scene);
  const TimeGrid grid = ChooseTimeGrid(model, scene.simulation, scene.output.interval);
  EquilibriumReport r;
  const State s = MakeInitialState(scene, model, grid, &r, cancel).front();
  if (report) *report = r.lines.front();
  return s;
}

}  // namespace cablefilm
