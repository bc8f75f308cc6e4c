#include "core/explicit_integrator.h"

#include <cmath>
#include <sstream>

#include "core/stability.h"

namespace cablefilm {

ExplicitIntegrator::ExplicitIntegrator(const CableModel& m)
    : ws_(m.links), a_(2, m.links + 1), v_pred_(2, m.links + 1), snaps_(m) {}

ExplicitIntegrator::ExplicitIntegrator(const CableModel& m, double safety_factor)
    : ws_(m.links), a_(2, m.links + 1), v_pred_(2, m.links + 1), next_x_(2, m.links + 1),
      next_v_(2, m.links + 1), inertia_(m.links + 1), snaps_(m), automatic_(true) {
  max_step_ = safety_factor * ComputeStabilityLimit(m).time_step;
  for (int j = 0; j <= m.links; ++j)
    inertia_[j] = m.cable_mass[j] + m.prism_mass.col(j).minCoeff();
}

std::string ExplicitIntegrator::name() const {
  if (!automatic_) return "explicit (central differences)";
  std::ostringstream os;
  os << "explicit (central differences, automatic steps up to " << max_step_
     << " s, refined at slack-taut changes)";
  return os.str();
}

void ExplicitIntegrator::Initialize(const CableModel& m, const CableState& state) {
  ComputeAccelerations(m, state.t, state.x, state.v, ws_, a_);
  CheckStateSane(m, state, ws_.geometry.length);
  snaps_.Start(ws_.geometry.length);
  initialized_ = true;
}

bool ExplicitIntegrator::Drift(const CableModel& m, const CableState& s, double h) {
  for (int j : {0, m.links})
    if (m.prescribed(j)) next_x_.col(j) = m.end_motion(j).Position(s.t + h);
  // Whether link k is taut at one end of the step and slack at the other.
  auto changes = [&](int k) {
    const double l = m.rest_length[k];
    return (ws_.geometry.length[k] > l) !=
           ((next_x_.col(k + 1) - next_x_.col(k)).squaredNorm() > l * l);
  };
  const int j0 = m.first_free(), j1 = m.last_free();
  bool any = false;
  for (int j = j0; j <= j1; ++j) {
    const Eigen::Vector2d a = a_.col(j);
    v_pred_.col(j) = s.v.col(j) + h * a;
    next_v_.col(j) = s.v.col(j) + 0.5 * h * a;  // v_{n+1/2}
    next_x_.col(j) = s.x.col(j) + h * next_v_.col(j);
    if (j > 0) any |= changes(j - 1);
  }
  if (j1 < m.links) any |= changes(j1);
  return any;
}

bool ExplicitIntegrator::SnapsResolved(const CableModel& m, const CableState& s,
                                       double h) const {
  double negligible = -1;  // the cable's energy share, computed only when a change needs it [J]
  for (int k = 0; k < m.links; ++k) {
    const double l = m.rest_length[k];
    const Eigen::Vector2d d1 = next_x_.col(k + 1) - next_x_.col(k);
    const bool taut0 = ws_.geometry.length[k] > l;  // stretched (with damping T may be 0)
    const bool taut1 = d1.squaredNorm() > l * l;
    if (taut0 == taut1) continue;
    if (m.prescribed(k) && m.prescribed(k + 1)) continue;  // a link that moves no station
    const double stiffness = m.axial_stiffness[k] / l;     // sigma E / l [N/m]
    const Eigen::Vector2d d0 = s.x.col(k + 1) - s.x.col(k);
    const double L0 = ws_.geometry.length[k], L1 = d1.norm();
    double delta, strain_energy;  // [J]
    if (taut1) {  // snapping taut: T_n = 0
      const double T1 = stiffness * (L1 - l);
      delta = -0.5 * T1 * (l - d1.dot(d0) / L1);
      strain_energy = 0.5 * T1 * (L1 - l);
    } else {      // going slack: T_{n+1} = 0 (the elastic part: the damping does no such work)
      const double T0 = stiffness * (L0 - l);
      delta = 0.5 * T0 * (l - ws_.geometry.tangent.col(k).dot(d1));
      strain_energy = 0.5 * T0 * (L0 - l);
    }
    // The energy of the link's own motion: its stations' relative speed along it, at the start
    // of the step or (as the accelerations carry it) at its end, whichever is larger, with their
    // reduced mass (a prescribed station is infinitely heavy).
    const double reduced = m.prescribed(k)       ? inertia_[k + 1]
                           : m.prescribed(k + 1) ? inertia_[k]
                                                 : inertia_[k] * inertia_[k + 1] /
                                                       (inertia_[k] + inertia_[k + 1]);
    const Eigen::Vector2d w = s.v.col(k + 1) - s.v.col(k);
    const Eigen::Vector2d dw = h * (a_.col(k + 1) - a_.col(k));
    const double closing =
        L0 > 0 ? std::max(std::abs(w.dot(d0)), std::abs((w + dw).dot(d0))) / L0 : 0.0;
    const double own = 0.5 * reduced * closing * closing + strain_energy;
    if (std::abs(delta) <= kSnapEnergyFraction * own) continue;
    if (negligible < 0)
      negligible = kCableEnergyFloor *
                   (KineticEnergy(m, ws_.geometry, s.v) + ElasticEnergy(m, ws_.geometry));
    if (std::abs(delta) > negligible) return false;
  }
  return true;
}

void ExplicitIntegrator::Commit(const CableModel& m, CableState& s, double h) {
  const double t1 = s.t + h;
  const int j0 = m.first_free(), j1 = m.last_free();
  s.x.swap(next_x_);  // x_{n+1}
  s.v.swap(next_v_);  // v_{n+1/2} at the free stations
  for (int j : {0, m.links}) {
    if (!m.prescribed(j)) continue;
    s.v.col(j) = m.end_motion(j).Velocity(t1);
    v_pred_.col(j) = s.v.col(j);
  }
  ComputeAccelerations(m, t1, s.x, v_pred_, ws_, a_);
  for (int j = j0; j <= j1; ++j) s.v.col(j) += 0.5 * h * a_.col(j);
  s.t = t1;
  ++stats_.steps;
  snaps_.Observe(t1, h, ws_.geometry.length);
}

void ExplicitIntegrator::Step(const CableModel& m, CableState& s, double dt) {
  if (!initialized_) Initialize(m, s);
  if (!automatic_) {
    const double t1 = s.t + dt;
    const int j0 = m.first_free(), j1 = m.last_free();
    for (int j = j0; j <= j1; ++j) {
      const Eigen::Vector2d a = a_.col(j);
      v_pred_.col(j) = s.v.col(j) + dt * a;
      s.v.col(j) += 0.5 * dt * a;  // v_{n+1/2}
      s.x.col(j) += dt * s.v.col(j);
    }
    // Prescribed ends: exact position and velocity at t_{n+1}.
    for (int j : {0, m.links}) {
      if (!m.prescribed(j)) continue;
      const EndMotion& e = m.end_motion(j);
      s.x.col(j) = e.Position(t1);
      s.v.col(j) = e.Velocity(t1);
      v_pred_.col(j) = s.v.col(j);
    }
    ComputeAccelerations(m, t1, s.x, v_pred_, ws_, a_);
    for (int j = j0; j <= j1; ++j) s.v.col(j) += 0.5 * dt * a_.col(j);
    s.t = t1;
    ++stats_.steps;
    snaps_.Observe(t1, dt, ws_.geometry.length);
    CheckStateSane(m, s, ws_.geometry.length);
    return;
  }
  // The least subdivision that keeps substeps below safety x the limit (a step asked just
  // above it by round-off is not cut).
  int stable_level = 0;
  while (stable_level < kMaxRefinement &&
         dt / static_cast<double>(1L << stable_level) > max_step_ * (1 + 1e-9))
    ++stable_level;
  if (level_ < stable_level) {
    level_ = stable_level;
  } else if (level_ > stable_level && quiet_time_ >= kQuietSteps * dt) {
    --level_;
    quiet_time_ = 0;
  }
  const double t0 = s.t;
  long done = 0;  // substeps of dt / 2^level_ taken
  while (done < (1L << level_)) {
    ThrowIfCancelled(cancel_, "the explicit step");
    double h = dt / static_cast<double>(1L << level_);
    bool changed = Drift(m, s, h);
    while (changed && !SnapsResolved(m, s, h) && level_ < kMaxRefinement) {
      ++stats_.rejected;
      ++level_;
      done *= 2;
      h *= 0.5;
      changed = Drift(m, s, h);
    }
    if (level_ > finest_level_) finest_level_ = level_;
    Commit(m, s, h);
    ++done;
    s.t = t0 + static_cast<double>(done) * h;
    quiet_time_ = changed ? 0.0 : quiet_time_ + h;
  }
  s.t = t0 + dt;
  CheckStateSane(m, s, ws_.geometry.length);
}

}  // namespace cablefilm
