#include "run/simulation_run.h"

#include <cmath>
#include <limits>

#include "core/explicit_integrator.h"
#include "core/inextensible.h"

namespace cablefilm {

TimeGrid ChooseTimeGrid(const CableModel& m, const SimulationDef& sim, double interval) {
  TimeGrid g;
  g.kind = sim.integrator == IntegratorChoice::kExplicit ? IntegratorKind::kExplicit
                                                         : IntegratorKind::kImplicit;
  if (m.law == LinkLaw::kInextensible) g.kind = IntegratorKind::kInextensible;
  g.rho_inf = sim.rho_infinity;
  g.interval = interval;
  g.limit = ComputeStabilityLimit(m);
  g.safety_factor = sim.safety_factor;
  g.automatic = sim.time_step <= 0;
  double wanted = sim.time_step;
  if (g.automatic && g.kind == IntegratorKind::kExplicit)
    wanted = sim.safety_factor * g.limit.time_step;
  if (g.automatic && g.kind == IntegratorKind::kImplicit) {
    wanted = interval;  // the largest step; the error control takes smaller ones as needed
    g.error_tolerance =
        sim.tolerance > 0 ? sim.tolerance : kDefaultRelativeTolerance * m.total_length();
  }
  if (g.automatic && g.kind == IntegratorKind::kInextensible) {
    // Substeps below its (tension-dependent) transverse-wave limit and under the same local
    // error control as the implicit scheme's, within each output interval.
    wanted = interval;
    g.error_tolerance =
        sim.tolerance > 0 ? sim.tolerance : kDefaultRelativeTolerance * m.total_length();
  }
  g.steps_per_output = std::max(1, static_cast<int>(std::ceil(interval / wanted - 1e-9)));
  g.dt = interval / g.steps_per_output;
  g.outputs = static_cast<long>(std::floor(sim.duration / interval + 1e-9));
  return g;
}

CableState MakeInitialState(const SceneDef& scene, const CableModel& m,
                            EquilibriumReport* report, const CancelFlag* cancel) {
  EquilibriumOptions options;
  options.cancel = cancel;
  if (scene.initial == InitialStateKind::kEquilibrium)
    return m.law == LinkLaw::kInextensible ? SolveInextensibleEquilibrium(m, report)
                                           : SolveEquilibrium(m, report, options);
  CableState s;
  s.x = StraightChord(m);
  s.v = Eigen::Matrix2Xd::Zero(2, m.stations());
  return s;
}

std::unique_ptr<Integrator> MakeIntegrator(const CableModel& m, const TimeGrid& grid) {
  // The explicit scheme's "auto": substeps of at most safety x the limit, refined where a link
  // goes slack or snaps taut (see explicit_integrator.h).
  if (grid.kind == IntegratorKind::kExplicit && grid.automatic)
    return std::make_unique<ExplicitIntegrator>(m, grid.safety_factor);
  return MakeIntegrator(grid.kind, m, grid.rho_inf, grid.error_tolerance);
}

bool Simulate(const CableModel& m, Integrator& integrator, CableState& state,
              const TimeGrid& grid, const OutputCallback& on_output, const CancelFlag* cancel) {
  integrator.set_cancel(cancel);
  integrator.Initialize(m, state);
  if (!on_output(state, integrator.tensions())) return false;
  for (long k = 1; k <= grid.outputs; ++k) {
    try {
      for (int i = 0; i < grid.steps_per_output; ++i) {
        ThrowIfCancelled(cancel, "the simulation");
        integrator.Step(m, state, grid.dt);
      }
    } catch (const CancelledError&) {
      return false;  // the rows so far stand; the state is part way to the next output
    }
    state.t = k * grid.interval;  // no round-off drift over long runs
    if (!on_output(state, integrator.tensions())) return false;
  }
  return true;
}

}  // namespace cablefilm
