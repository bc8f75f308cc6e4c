#include "core/explicit_integrator.h"

namespace cablefilm {

ExplicitIntegrator::ExplicitIntegrator(const CableModel& m)
    : ws_(m.links), a_(2, m.links + 1), v_pred_(2, m.links + 1) {}

void ExplicitIntegrator::Initialize(const CableModel& m, const CableState& state) {
  ComputeAccelerations(m, state.t, state.x, state.v, ws_, a_);
  CheckStateSane(m, state, ws_.geometry.length);
  initialized_ = true;
}

void ExplicitIntegrator::Step(const CableModel& m, CableState& s, double dt) {
  if (!initialized_) Initialize(m, s);
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
  CheckStateSane(m, s, ws_.geometry.length);
}

}  // namespace cablefilm
