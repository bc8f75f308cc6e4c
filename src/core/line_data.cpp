#include "core/line_data.h"

#include <cmath>
#include <sstream>

#include "core/explicit_snaps.h"
#include "core/seabed_friction.h"
#include "core/stability.h"

namespace cablefilm {

namespace {

// The explicit scheme's constants (explicit_step.h).
void PrepareExplicitSteps(const LineModel& m, const StepOptions& options, Scratch& w) {
  const int n = m.stations();
  w.least_inertia.resize(n);
  for (int j = 0; j < n; ++j)
    w.least_inertia[j] = m.line.cable_mass[j] + m.line.prism_mass.col(j).minCoeff();
  if (options.safety_factor > 0)
    w.max_substep = options.safety_factor * ComputeStabilityLimit(m).time_step;
}

}  // namespace

LineData MakeLineData(const LineModel& m, const Inputs& in, const StepOptions& options,
                      const State& state, const Points* friction_anchor) {
  const int n = m.stations(), links = m.line.links;
  LineData d;
  d.options = options;
  d.state = state;
  d.start_time = state.t;
  d.forces.Resize(links);
  ResetFrictionAnchors(m, state.x, d.forces.geometry);  // the state starts at rest on the bed
  Points& anchor = d.forces.geometry.friction_anchor;   // or where a run had them
  if (friction_anchor && friction_anchor->cols() == anchor.cols()) anchor = *friction_anchor;
  d.water = SceneWater(m);
  UpdateWater(m, in, state.t, &d.water);
  d.a = Points::Zero(kDim, n);
  d.snaps = SnapMonitor(m);
  Scratch& w = d.scratch;
  w.x = w.v = w.a = w.abar = w.v_pred = Points::Zero(kDim, n);
  switch (options.scheme) {
    case Scheme::kExplicit:
      ComputeAccelerations(m, in, d.water, state.t, state.x, state.v, d.forces, d.a);
      PrepareExplicitSteps(m, options, w);
      break;
    case Scheme::kImplicit:
      ComputeAccelerations(m, in, d.water, state.t, state.x, state.v, d.forces, d.a);
      d.abar = d.abar_before = d.a;
      w.system.Resize(m.last_free() - m.first_free() + 1);
      w.matrix_taut.assign(m.line.links, 0);
      w.snapping.assign(m.line.links, 0);
      w.residual.assign(w.system.size(), Vec::Zero());
      // A displacement this small changes a link's tension by a negligible fraction of its
      // stiffness times its length: 1e-9 of the shortest link.
      w.newton_tolerance = 1e-9 * m.line.rest_length.minCoeff();
      if (options.explicit_snaps) {
        PrepareExplicitSteps(m, options, w);
        w.snap_window = SnapWindow(d.snaps);
      }
      break;
    case Scheme::kInextensible:
      w.constraints = ConstraintSolver(m);
      w.trial.Resize(links);
      w.trial.geometry.friction_anchor = d.forces.geometry.friction_anchor;
      w.constraints.Accelerations(m, in, d.water, state.t, state.x, state.v, d.forces, d.a);
      break;
  }
  CheckStateSane(m, d.state, d.forces.geometry.length);
  if (options.scheme != Scheme::kInextensible) d.snaps.Start(d.forces.geometry.length);
  return d;
}

StepOptions LineStepOptions(const StepOptions& model, const LineModel& m) {
  StepOptions o = model;
  if (m.line.law == LinkLaw::kInextensible) {
    o.scheme = Scheme::kInextensible;
    o.safety_factor = 0;
    o.explicit_snaps = false;
    o.start_tolerance = 0;
    o.start_end = 0;
  } else if (o.scheme == Scheme::kInextensible) {
    o.scheme = Scheme::kImplicit;
  }
  return o;
}

std::string SchemeName(const LineModel& m, const StepOptions& o) {
  std::ostringstream os;
  switch (o.scheme) {
    case Scheme::kExplicit:
      if (!(o.safety_factor > 0)) return "explicit (central differences)";
      os << "explicit (central differences, automatic steps up to "
         << o.safety_factor * ComputeStabilityLimit(m).time_step
         << " s, refined at slack-taut changes)";
      return os.str();
    case Scheme::kImplicit:
      os << "implicit (generalized-alpha, rho_inf = " << o.rho_inf << ")";
      return os.str();
    case Scheme::kInextensible:
      if (!(o.tolerance > 0)) return "inextensible (constraint tensions)";
      os << "inextensible (constraint tensions, local position error per step below "
         << o.tolerance << " m)";
      return os.str();
  }
  return "";
}

void CheckStateSane(const LineModel& m, const State& state, const Eigen::VectorXd& length) {
  // A strain of 100 % is far past the breaking strain of any rope or wire: if the solution gets
  // there, it is a numerical blow-up, not physics.
  constexpr double kMaxStretch = 2.0;  // L / l
  for (int j = 0; j <= m.line.links; ++j) {
    if (!state.x.col(j).allFinite() || !state.v.col(j).allFinite()) {
      std::ostringstream os;
      os << "numerical blow-up at t = " << state.t << " s: station " << j
         << " has a non-finite position or velocity";
      throw BlowUpError(os.str(), state.t, j);
    }
  }
  for (int j = 0; j < m.line.links; ++j) {
    if (length[j] > kMaxStretch * m.line.rest_length[j]) {
      std::ostringstream os;
      os << "numerical blow-up at t = " << state.t << " s: link " << j << " (stations " << j
         << "-" << j + 1 << ") stretched to " << length[j] / m.line.rest_length[j]
         << " times its rest length";
      throw BlowUpError(os.str(), state.t, j);
    }
  }
}

}  // namespace cablefilm
