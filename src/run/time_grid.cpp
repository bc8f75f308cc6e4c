#include "run/time_grid.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {

double StartDuration(const LineModel& m) {
  constexpr double kRampsToStart = 5;  // nu t at which R(t) = 1 - 6 exp(-5) = 0.96
  const auto start = [&](double ramp_rate, double period) {
    return ramp_rate > 0 ? kRampsToStart / ramp_rate : period;
  };
  double end = 0;
  for (const EndMotion* e : {&m.ends.start, &m.ends.end})
    if (e->kind() == EndKind::kTrochoid) end = std::max(end, start(e->ramp_rate(), e->period()));
  // (Still water, height 0, has no start: a MoorDyn file's converted surface.)
  if (m.has_waves() && m.env.wave.spec.height > 0)
    end = std::max(end, start(m.env.wave.spec.ramp_rate, m.env.wave.spec.period));
  return end;
}

TimeGrid ChooseLineGrid(const LineModel& m, const SimulationDef& sim, double interval) {
  TimeGrid g;
  StepOptions& o = g.options;
  o.scheme = sim.integrator == IntegratorChoice::kExplicit ? Scheme::kExplicit : Scheme::kImplicit;
  if (m.line.law == LinkLaw::kInextensible) o.scheme = Scheme::kInextensible;
  o.rho_inf = sim.rho_infinity;
  g.interval = interval;
  g.limit = ComputeStabilityLimit(m);
  g.safety_factor = sim.safety_factor;
  g.automatic = sim.time_step <= 0;
  double wanted = sim.time_step;
  if (g.automatic && o.scheme == Scheme::kExplicit) {
    // Substeps of at most safety x the limit, refined where a link goes slack or snaps taut
    // (see core/explicit_step.h).
    wanted = sim.safety_factor * g.limit.time_step;
    o.safety_factor = sim.safety_factor;
  }
  if (g.automatic && o.scheme != Scheme::kExplicit) {
    // The largest step the output interval; the error control takes smaller ones as needed
    // (the inextensible one also below its tension-dependent transverse-wave limit).
    wanted = interval;
    o.tolerance =
        sim.tolerance > 0 ? sim.tolerance : kDefaultRelativeTolerance * m.line.total_length();
    if (o.scheme == Scheme::kImplicit) {
      // Snaps that the steps would jump over: explicit steps through them (explicit_snaps.h).
      o.explicit_snaps = sim.explicit_snaps;
      o.safety_factor = sim.safety_factor;
      o.start_end = sim.start_duration >= 0 ? sim.start_duration : StartDuration(m);
      o.start_tolerance =
          sim.start_tolerance > 0 ? sim.start_tolerance : o.tolerance / kStartToleranceDivisor;
    }
  }
  g.steps_per_output = std::max(1, static_cast<int>(std::ceil(interval / wanted - 1e-9)));
  g.dt = interval / g.steps_per_output;
  g.outputs = static_cast<long>(std::floor(sim.duration / interval + 1e-9));
  return g;
}

TimeGrid ChooseTimeGrid(const Model& model, const SimulationDef& sim, double interval) {
  TimeGrid grid;
  double longest = -1, tolerance = 0, start_tolerance = 0, start_end = 0;
  StepOptions elastic;  // an elastic line's scheme, if it has one (an inextensible line takes
  bool any_elastic = false;  // its own: LineStepOptions)
  for (size_t i = 0; i < model.lines.size(); ++i) {
    const TimeGrid g = ChooseLineGrid(model.lines[i], sim, interval);
    if (i == 0 || g.dt < grid.dt) grid = g;
    if (!any_elastic && g.options.scheme != Scheme::kInextensible) {
      elastic = g.options;
      any_elastic = true;
    }
    if (model.lines[i].line.total_length() > longest) {
      longest = model.lines[i].line.total_length();
      tolerance = g.options.tolerance;
    }
    start_end = std::max(start_end, g.options.start_end);  // every line's moving ends
  }
  if (any_elastic) grid.options = elastic;
  grid.options.tolerance = tolerance;
  // The start's tighter tolerance is the implicit step's, from the model's tolerance (the
  // longest line's, whatever its model: an inextensible line has none of its own).
  if (grid.options.scheme == Scheme::kImplicit && grid.automatic)
    start_tolerance =
        sim.start_tolerance > 0 ? sim.start_tolerance : tolerance / kStartToleranceDivisor;
  grid.options.start_tolerance = start_tolerance;
  grid.options.start_end = start_end;
  return grid;
}

}  // namespace cablefilm
