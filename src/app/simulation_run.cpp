#include "app/simulation_run.h"

#include <cmath>

namespace cablefilm {

TimeGrid ChooseTimeGrid(const CableModel& m, const SimulationDef& sim, double interval) {
  TimeGrid g;
  g.interval = interval;
  g.limit = ComputeStabilityLimit(m);
  g.safety_factor = sim.safety_factor;
  g.automatic = sim.time_step <= 0;
  const double wanted = g.automatic ? sim.safety_factor * g.limit.time_step : sim.time_step;
  g.steps_per_output = std::max(1, static_cast<int>(std::ceil(interval / wanted - 1e-9)));
  g.dt = interval / g.steps_per_output;
  g.outputs = static_cast<long>(std::floor(sim.duration / interval + 1e-9));
  return g;
}

CableState MakeInitialState(const SceneDef& scene, const CableModel& m,
                            EquilibriumReport* report) {
  if (scene.initial == InitialStateKind::kEquilibrium) return SolveEquilibrium(m, report);
  CableState s;
  s.x = StraightChord(m);
  s.v = Eigen::Matrix2Xd::Zero(2, m.stations());
  return s;
}

bool Simulate(const CableModel& m, Integrator& integrator, CableState& state,
              const TimeGrid& grid, const OutputCallback& on_output) {
  integrator.Initialize(m, state);
  if (!on_output(state, integrator.tensions())) return false;
  for (long k = 1; k <= grid.outputs; ++k) {
    for (int i = 0; i < grid.steps_per_output; ++i) integrator.Step(m, state, grid.dt);
    state.t = k * grid.interval;  // no round-off drift over long runs
    if (!on_output(state, integrator.tensions())) return false;
  }
  return true;
}

}  // namespace cablefilm
