#include "core/generalized_alpha.h"

#include <Eigen/LU>
#include <cmath>
#include <sstream>

#include "core/force_jacobian.h"

namespace cablefilm {
namespace {
constexpr int kMaxNewtonIterations = 12;
constexpr int kMaxHalvings = 12;
}  // namespace

GeneralizedAlphaIntegrator::GeneralizedAlphaIntegrator(const CableModel& m, double rho_inf)
    : rho_inf_(rho_inf), ws_(m.links), system_(m.last_free() - m.first_free() + 1),
      a_(2, m.stations()), abar_(2, m.stations()), x_(2, m.stations()), v_(2, m.stations()),
      a1_(2, m.stations()), abar1_(2, m.stations()) {
  am_ = (2.0 * rho_inf - 1.0) / (rho_inf + 1.0);
  af_ = rho_inf / (rho_inf + 1.0);
  gamma_ = 0.5 + af_ - am_;
  beta_ = 0.25 * (gamma_ + 0.5) * (gamma_ + 0.5);
  // A displacement this small changes a link's tension by a negligible fraction of its
  // stiffness times its length: 1e-9 of the shortest link.
  tolerance_ = 1e-9 * m.rest_length.minCoeff();
}

std::string GeneralizedAlphaIntegrator::name() const {
  std::ostringstream os;
  os << "implicit (generalized-alpha, rho_inf = " << rho_inf_ << ")";
  return os.str();
}

void GeneralizedAlphaIntegrator::Initialize(const CableModel& m, const CableState& state) {
  ComputeAccelerations(m, state.t, state.x, state.v, ws_, a_);
  CheckStateSane(m, state, ws_.geometry.length);
  abar_ = a_;
  initialized_ = true;
}

void GeneralizedAlphaIntegrator::Kinematics(const CableModel& m, const CableState& s, double h,
                                            const Eigen::Matrix2Xd& x) {
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    abar1_.col(j) = (x.col(j) - s.x.col(j) - h * s.v.col(j) -
                     h * h * (0.5 - beta_) * abar_.col(j)) /
                    (h * h * beta_);
    a1_.col(j) = ((1.0 - am_) * abar1_.col(j) + am_ * abar_.col(j) - af_ * a_.col(j)) /
                 (1.0 - af_);
    v_.col(j) = s.v.col(j) + h * (1.0 - gamma_) * abar_.col(j) + h * gamma_ * abar1_.col(j);
  }
}

bool GeneralizedAlphaIntegrator::TryStep(const CableModel& m, CableState& s, double h) {
  const int j0 = m.first_free(), j1 = m.last_free();
  const double t1 = s.t + h;
  // Predictor: the pseudo-acceleration carried over.
  x_ = s.x;
  for (int j = j0; j <= j1; ++j)
    x_.col(j) += h * s.v.col(j) + 0.5 * h * h * abar_.col(j);
  for (int j : {0, m.links}) {
    if (!m.prescribed(j)) continue;
    x_.col(j) = m.end_motion(j).Position(t1);
    v_.col(j) = m.end_motion(j).Velocity(t1);
  }
  const double ka = (1.0 - am_) / ((1.0 - af_) * beta_ * h * h);  // d a_{n+1} / d x_{n+1}
  const double kv = gamma_ / (beta_ * h);                          // d v_{n+1} / d x_{n+1}
  for (int it = 1; it <= kMaxNewtonIterations; ++it) {
    ++stats_.newton_iterations;
    Kinematics(m, s, h, x_);
    ComputeGeometry(x_, ws_.geometry);
    ComputeHookeTensions(m, ws_.geometry, ws_.tension);
    ComputeStationForces(m, ws_.geometry, ws_.tension, v_, ws_.force);
    system_.SetZero();
    AddInertiaJacobian(m, ws_.geometry, a1_, ka, system_);
    AddForceJacobian(m, ws_.geometry, ws_.tension, v_, kv, system_);
    for (int j = j0; j <= j1; ++j)
      system_.rhs[j - j0] = ws_.force.col(j) - StationInertia(m, ws_.geometry, j) * a1_.col(j);
    if (!system_.Solve()) return false;
    double dx_max = 0;
    for (int j = j0; j <= j1; ++j) {
      x_.col(j) += system_.rhs[j - j0];
      dx_max = std::max(dx_max, system_.rhs[j - j0].lpNorm<Eigen::Infinity>());
    }
    if (!std::isfinite(dx_max)) return false;
    if (dx_max <= tolerance_) {
      Kinematics(m, s, h, x_);
      ComputeGeometry(x_, ws_.geometry);
      ComputeHookeTensions(m, ws_.geometry, ws_.tension);
      s.x.swap(x_);
      s.v.swap(v_);
      for (int j = j0; j <= j1; ++j) {
        a_.col(j) = a1_.col(j);
        abar_.col(j) = abar1_.col(j);
      }
      s.t = t1;
      return true;
    }
  }
  return false;
}

void GeneralizedAlphaIntegrator::Step(const CableModel& m, CableState& s, double dt) {
  if (!initialized_) Initialize(m, s);
  const double t_end = s.t + dt;
  double h = substep_ > 0 && substep_ < dt ? substep_ : dt;
  while (s.t < t_end - 1e-12 * dt) {
    h = std::min(h, t_end - s.t);
    int halvings = 0;
    while (!TryStep(m, s, h)) {
      ++stats_.rejected;
      if (++halvings > kMaxHalvings) {
        std::ostringstream os;
        os << "the implicit step did not converge at t = " << s.t << " s even with a step of "
           << h << " s";
        int worst = 0;
        ws_.geometry.length.cwiseQuotient(m.rest_length).maxCoeff(&worst);
        throw BlowUpError(os.str() + "; the most stretched link is " + std::to_string(worst),
                          s.t, worst);
      }
      h *= 0.5;
    }
    ++stats_.steps;
    // After a rejection, creep back up to the requested step.
    substep_ = halvings > 0 ? h : std::min(dt, 2.0 * h);
    h = substep_;
  }
  s.t = t_end;
  CheckStateSane(m, s, ws_.geometry.length);
}

}  // namespace cablefilm
