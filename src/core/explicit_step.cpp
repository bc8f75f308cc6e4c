#include "core/explicit_step.h"

#include <cmath>

#include "core/cancel.h"
#include "core/explicit_stages.h"
#include "core/seabed_friction.h"

namespace cablefilm {

bool Drift(const LineModel& m, LineData& d, const Inputs& in, double h) {
  const State& s = d.state;
  Scratch& w = d.scratch;
  for (int j : {0, m.line.links})
    if (m.prescribed(j)) w.x.col(j) = EndPosition(m, in, j, s.t + h);
  // Whether link k is taut at one end of the step and slack at the other.
  auto changes = [&](int k) {
    const double l = m.line.rest_length[k];
    return (d.forces.geometry.length[k] > l) !=
           ((w.x.col(k + 1) - w.x.col(k)).squaredNorm() > l * l);
  };
  const int j0 = m.first_free(), j1 = m.last_free();
  bool any = false;
  for (int j = j0; j <= j1; ++j) {
    const Vec a = d.a.col(j);
    w.v_pred.col(j) = s.v.col(j) + h * a;
    w.v.col(j) = s.v.col(j) + 0.5 * h * a;  // v_{n+1/2}
    w.x.col(j) = s.x.col(j) + h * w.v.col(j);
    if (j > 0) any |= changes(j - 1);
  }
  if (j1 < m.line.links) any |= changes(j1);
  return any;
}

bool SnapsResolved(const LineModel& m, const LineData& d, double h) {
  const State& s = d.state;
  const Scratch& w = d.scratch;
  const LinkGeometry& g = d.forces.geometry;
  double negligible = -1;  // the cable's energy share, computed only when a change needs it [J]
  for (int k = 0; k < m.line.links; ++k) {
    const double l = m.line.rest_length[k];
    const Vec d1 = w.x.col(k + 1) - w.x.col(k);
    const bool taut0 = g.length[k] > l;  // stretched (with damping T may be 0)
    const bool taut1 = d1.squaredNorm() > l * l;
    if (taut0 == taut1) continue;
    if (m.prescribed(k) && m.prescribed(k + 1)) continue;  // a link that moves no station
    const double stiffness = m.line.axial_stiffness[k] / l;  // sigma E / l [N/m]
    const Vec d0 = s.x.col(k + 1) - s.x.col(k);
    const double L0 = g.length[k], L1 = d1.norm();
    double delta, strain_energy;  // [J]
    if (taut1) {  // snapping taut: T_n = 0
      const double T1 = stiffness * (L1 - l);
      delta = -0.5 * T1 * (l - d1.dot(d0) / L1);
      strain_energy = 0.5 * T1 * (L1 - l);
    } else {      // going slack: T_{n+1} = 0 (the elastic part: the damping does no such work)
      const double T0 = stiffness * (L0 - l);
      delta = 0.5 * T0 * (l - g.tangent.col(k).dot(d1));
      strain_energy = 0.5 * T0 * (L0 - l);
    }
    // The energy of the link's own motion: its stations' relative speed along it, at the start
    // of the step or (as the accelerations carry it) at its end, whichever is larger, with their
    // reduced mass (a prescribed station is infinitely heavy).
    const Eigen::VectorXd& inertia = w.least_inertia;
    const double reduced = m.prescribed(k)       ? inertia[k + 1]
                           : m.prescribed(k + 1) ? inertia[k]
                                                 : inertia[k] * inertia[k + 1] /
                                                       (inertia[k] + inertia[k + 1]);
    const Vec rel = s.v.col(k + 1) - s.v.col(k);
    const Vec drel = h * (d.a.col(k + 1) - d.a.col(k));
    const double closing =
        L0 > 0 ? std::max(std::abs(rel.dot(d0)), std::abs((rel + drel).dot(d0))) / L0 : 0.0;
    const double own = 0.5 * reduced * closing * closing + strain_energy;
    if (std::abs(delta) <= kSnapEnergyFraction * own) continue;
    if (negligible < 0)
      negligible = kCableEnergyFloor * (KineticEnergy(m, g, s.v) + ElasticEnergy(m, g));
    if (std::abs(delta) > negligible) return false;
  }
  return true;
}

void MoveToDrift(const LineModel& m, LineData& d, const Inputs& in, double h) {
  State& s = d.state;
  Scratch& w = d.scratch;
  const double t1 = s.t + h;
  s.x.swap(w.x);  // x_{n+1}
  s.v.swap(w.v);  // v_{n+1/2} at the free stations
  for (int j : {0, m.line.links}) {
    if (!m.prescribed(j)) continue;
    s.v.col(j) = EndVelocity(m, in, j, t1);
    w.v_pred.col(j) = s.v.col(j);
  }
  ComputeAccelerations(m, in, d.water, t1, s.x, w.v_pred, d.forces, d.a);
}

void SettleRefinement(double dt, double max_substep, int* refinement, double* quiet_time) {
  int stable_level = 0;
  while (stable_level < kMaxRefinement &&
         dt / static_cast<double>(1L << stable_level) > max_substep * (1 + 1e-9))
    ++stable_level;
  if (*refinement < stable_level) {
    *refinement = stable_level;
  } else if (*refinement > stable_level && *quiet_time >= kQuietSteps * dt) {
    --*refinement;
    *quiet_time = 0;
  }
}

void FinishDrift(const LineModel& m, LineData& d, double h) {
  State& s = d.state;
  const double t1 = s.t + h;
  for (int j = m.first_free(); j <= m.last_free(); ++j) s.v.col(j) += 0.5 * h * d.a.col(j);
  UpdateFrictionAnchors(m, s.x, s.v, d.forces.geometry);
  s.t = t1;
  ++d.stats.steps;
  d.snaps.Observe(t1, h, d.forces.geometry.length);
}

namespace {

// Completes the drifted step: velocities, accelerations at t + h.
void Commit(const LineModel& m, LineData& d, const Inputs& in, double h) {
  MoveToDrift(m, d, in, h);
  FinishDrift(m, d, h);
}

// A fixed step dt as it is (a dt above the stability limit blows up).
void FixedStep(const LineModel& m, LineData& d, const Inputs& in, double dt) {
  State& s = d.state;
  Points& v_pred = d.scratch.v_pred;
  const double t1 = s.t + dt;
  const int j0 = m.first_free(), j1 = m.last_free();
  for (int j = j0; j <= j1; ++j) {
    const Vec a = d.a.col(j);
    v_pred.col(j) = s.v.col(j) + dt * a;
    s.v.col(j) += 0.5 * dt * a;  // v_{n+1/2}
    s.x.col(j) += dt * s.v.col(j);
  }
  // Prescribed ends: exact position and velocity at t_{n+1}.
  for (int j : {0, m.line.links}) {
    if (!m.prescribed(j)) continue;
    s.x.col(j) = EndPosition(m, in, j, t1);
    s.v.col(j) = EndVelocity(m, in, j, t1);
    v_pred.col(j) = s.v.col(j);
  }
  ComputeAccelerations(m, in, d.water, t1, s.x, v_pred, d.forces, d.a);
  for (int j = j0; j <= j1; ++j) s.v.col(j) += 0.5 * dt * d.a.col(j);
  UpdateFrictionAnchors(m, s.x, s.v, d.forces.geometry);
  s.t = t1;
  ++d.stats.steps;
  d.snaps.Observe(t1, dt, d.forces.geometry.length);
}

}  // namespace

void ExplicitStep(const LineModel& m, LineData& d, const Inputs& in, double dt) {
  State& s = d.state;
  if (!(d.options.safety_factor > 0)) {
    FixedStep(m, d, in, dt);
    CheckStateSane(m, s, d.forces.geometry.length);
    return;
  }
  SettleRefinement(dt, d.scratch.max_substep, &d.refinement, &d.quiet_time);
  const double t0 = s.t;
  long done = 0;  // substeps of dt / 2^refinement taken
  while (done < (1L << d.refinement)) {
    ThrowIfCancelled(in.stop, "the explicit step");
    double h = dt / static_cast<double>(1L << d.refinement);
    bool changed = Drift(m, d, in, h);
    while (changed && !SnapsResolved(m, d, h) && d.refinement < kMaxRefinement) {
      ++d.stats.rejected;
      ++d.refinement;
      done *= 2;
      h *= 0.5;
      changed = Drift(m, d, in, h);
    }
    if (d.refinement > d.stats.finest_refinement) d.stats.finest_refinement = d.refinement;
    Commit(m, d, in, h);
    ++done;
    s.t = t0 + static_cast<double>(done) * h;
    d.quiet_time = changed ? 0.0 : d.quiet_time + h;
  }
  s.t = t0 + dt;
  CheckStateSane(m, s, d.forces.geometry.length);
}

}  // namespace cablefilm
