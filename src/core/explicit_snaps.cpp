#include "core/explicit_snaps.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/explicit_step.h"

namespace cablefilm {

double SnapWindow(const SnapMonitor& snaps) {
  double crossing = 0, rise = 0;  // [s]
  for (double tau : snaps.snap_times()) {
    if (!std::isfinite(tau)) continue;
    crossing += std::sqrt(2.0) * tau / M_PI;
    rise = std::max(rise, tau);
  }
  return kSnapWindowCrossings * crossing + kSnapWindowRises * rise;
}

bool StepsThroughSnaps(const LineData& d) {
  return d.options.explicit_snaps && d.scratch.max_substep > 0 && d.scratch.snap_window > 0;
}

bool SnapsUnresolved(const LineModel& m, const LineData& d, double h) {
  const State& s = d.state;
  const Scratch& w = d.scratch;
  const LinkGeometry& g = d.forces.geometry;  // the trial step's end
  const Eigen::VectorXd& tau = d.snaps.snap_times();
  double floor = -1;  // kSnapLoadFraction of the largest tension [N], once a snap needs it
  for (int k = 0; k < m.line.links; ++k) {
    const double l = m.line.rest_length[k];  // [m]
    // Slack at the step's start (as the snap monitor saw the state), taut at its end.
    if (d.snaps.taut(k) || !(g.length[k] > l) || !(h > kResolvedSnapFraction * tau[k])) continue;
    const Vec d0 = s.x.col(k + 1) - s.x.col(k);
    // The closing speed along the link [m/s], at the step's start or its end, whichever is
    // larger (a link at rest yanked taut closes within the step).
    const double L0 = d0.norm();
    const Vec t1 = g.tangent.col(k);
    double u = (w.v.col(k + 1) - w.v.col(k)).dot(t1);
    if (L0 > 0) u = std::max(u, (s.v.col(k + 1) - s.v.col(k)).dot(d0) / L0);
    const double K = m.line.axial_stiffness[k] / l;  // [N/m]
    if (floor < 0) floor = kSnapLoadFraction * d.forces.tension.maxCoeff();
    if (u * K * tau[k] / M_PI > floor) return true;
  }
  return false;
}

double ExplicitWindowEnd(double t, double h, double snap_window, double start_time,
                         double max_substep, long explicit_steps, long newton_iterations) {
  const double explicit_alone = (t - start_time) / max_substep;
  const double spent = static_cast<double>(explicit_steps) +
                       kNewtonIterationCost * static_cast<double>(newton_iterations);
  if (spent > explicit_alone) return std::numeric_limits<double>::infinity();
  return t + h + snap_window;
}

ExplicitWindowSpan WindowSpan(double t, double t_end, double snap_window, double max_substep,
                              double* explicit_until) {
  if (*explicit_until < t_end && t_end - *explicit_until < 1e-9 * snap_window)
    *explicit_until = t_end;
  ExplicitWindowSpan w;
  w.stop = std::min(t_end, *explicit_until);
  const double span = w.stop - t;
  if (!(span > 0)) return w;
  const double substeps = std::ceil(span / max_substep - 1e-9);
  w.pieces = std::max(1L, static_cast<long>(substeps));
  w.h = span / static_cast<double>(w.pieces);
  return w;
}

void EnterExplicitWindow(const LineModel& m, LineData& d, const Inputs& in, double h) {
  State& s = d.state;
  // The forces of the state (the trial step left its own in d.forces), and its accelerations,
  // which the explicit step carries.
  ComputeAccelerations(m, in, d.water, s.t, s.x, s.v, d.forces, d.a);
  d.explicit_until =
      ExplicitWindowEnd(s.t, h, d.scratch.snap_window, d.start_time, d.scratch.max_substep,
                        d.stats.explicit_steps, d.stats.newton_iterations);
  d.refinement = 0;
  d.quiet_time = 0;
  ++d.stats.snap_windows;
}

void StepExplicitWindow(const LineModel& m, LineData& d, const Inputs& in, double t_end) {
  State& s = d.state;
  const ExplicitWindowSpan w =
      WindowSpan(s.t, t_end, d.scratch.snap_window, d.scratch.max_substep, &d.explicit_until);
  const long before = d.stats.steps;
  const double t0 = s.t;
  for (long i = 1; i <= w.pieces; ++i) {  // ExplicitStep refines where links go slack or taut
    ExplicitStep(m, d, in, w.h);
    s.t = i == w.pieces ? w.stop : t0 + static_cast<double>(i) * w.h;
  }
  d.stats.explicit_steps += d.stats.steps - before;
  if (s.t < d.explicit_until) return;
  // The implicit scheme starts afresh from the state, as at t = 0 (MakeLineData): its acceleration
  // memory the state's true accelerations (the explicit step's a is at its predicted velocity).
  ComputeAccelerations(m, in, d.water, s.t, s.x, s.v, d.forces, d.a);
  d.abar = d.abar_before = d.a;
  d.last_step = 0;
  d.smooth = false;
  d.explicit_until = -1;
}

}  // namespace cablefilm
