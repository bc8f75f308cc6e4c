#include "core/generalized_alpha.h"

#include <Eigen/LU>
#include <cmath>
#include <sstream>

#include "core/force_jacobian.h"

namespace cablefilm {
namespace {
constexpr int kMaxNewtonIterations = 12;
constexpr int kMaxRejections = 40;
constexpr double kSmallestStepFraction = 1e-9;  // of the interval asked of Step()
}  // namespace

GeneralizedAlphaIntegrator::GeneralizedAlphaIntegrator(const CableModel& m, double rho_inf,
                                                       double error_tolerance)
    : rho_inf_(rho_inf), ws_(m.links), system_(m.last_free() - m.first_free() + 1),
      a_(2, m.stations()), abar_(2, m.stations()), x_(2, m.stations()), v_(2, m.stations()),
      a1_(2, m.stations()), abar1_(2, m.stations()), snaps_(m) {
  error_tolerance_ = error_tolerance;
  am_ = (2.0 * rho_inf - 1.0) / (rho_inf + 1.0);
  af_ = rho_inf / (rho_inf + 1.0);
  gamma_ = 0.5 + af_ - am_;
  beta_ = 0.25 * (gamma_ + 0.5) * (gamma_ + 0.5);
  // A displacement this small changes a link's tension by a negligible fraction of its
  // stiffness times its length: 1e-9 of the shortest link.
  newton_tolerance_ = 1e-9 * m.rest_length.minCoeff();
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
  snaps_.Start(ws_.geometry.length);
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

bool GeneralizedAlphaIntegrator::Solve(const CableModel& m, const CableState& s, double h) {
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
    ComputeGeometry(m, t1, x_, ws_.geometry);
    ComputeTensions(m, ws_.geometry, v_, ws_.tension);
    ComputeStationForces(m, ws_.geometry, ws_.tension, v_, ws_.force);
    system_.SetZero();
    AddInertiaJacobian(m, ws_.geometry, a1_, ka, system_);
    AddForceJacobian(m, ws_.geometry, ws_.tension, v_, kv, system_);
    for (int j = j0; j <= j1; ++j)
      system_.rhs[j - j0] = ws_.force.col(j) - StationInertia(m, ws_.geometry, j) * a1_.col(j);
    if (!system_.Solve()) return false;
    double dx_max = 0;
    for (int j = j0; j <= j1; ++j) {
      const bool above_bed = m.seabed.present && x_(1, j) >= m.seabed.y;
      x_.col(j) += system_.rhs[j - j0];
      dx_max = std::max(dx_max, system_.rhs[j - j0].lpNorm<Eigen::Infinity>());
      // A station above the seabed that the iteration would drive into it (its linear model
      // knows nothing of the bed) lands at its resting penetration instead: otherwise the next
      // iteration, in the bed's stiff spring and dashpot, throws it back above and Newton
      // cycles between the two (a touchdown at a fixed step of 0.05 s blew up so).
      if (above_bed && x_(1, j) < m.seabed.y - m.seabed_rest_depth[j])
        x_(1, j) = m.seabed.y - m.seabed_rest_depth[j];
    }
    if (!std::isfinite(dx_max)) return false;
    if (dx_max <= newton_tolerance_) {
      Kinematics(m, s, h, x_);
      ComputeGeometry(m, t1, x_, ws_.geometry);
      ComputeTensions(m, ws_.geometry, v_, ws_.tension);
      return true;
    }
  }
  return false;
}

double GeneralizedAlphaIntegrator::LocalError(const CableModel& m, double h) const {
  // Zienkiewicz & Xie's estimate for Newmark-type schemes: the step's position error is the
  // cubic term the scheme misses, h^2 |beta - 1/6| |a_{n+1} - a_n|.
  double da = 0;
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    // A station in the seabed at the step's end: its vertical acceleration jumps as the bed
    // takes its weight (a landing). How the step resolves that does not carry on: the bed's
    // critically damped spring leaves the station at rest at its resting penetration either
    // way, so the error there is of the penetration's scale (millimetres) and does not grow.
    // Resolving it cost 1.5 times the steps near a moving touchdown, for a larger tension error
    // (README, "Seabed and current profile"). Along the bed it is measured as anywhere.
    if (m.seabed.present && x_(1, j) < m.seabed.y) {
      da = std::max(da, std::abs(a1_(0, j) - a_(0, j)));
      continue;
    }
    da = std::max(da, (a1_.col(j) - a_.col(j)).lpNorm<Eigen::Infinity>());
  }
  return h * h * std::abs(beta_ - 1.0 / 6.0) * da;
}

void GeneralizedAlphaIntegrator::SettleLandings(const CableModel& m, const CableState& s,
                                                double h) {
  // A bed damped at least critically stops a landing station within about its landing time
  // sqrt(m_j / k_j) (1 ms for steel wire, 2 ms for chain on the default bed, at any link
  // length). A step longer than that cannot resolve the stop: the scheme's answer to the
  // unresolved stiff contact threw the station back up by millimetres, to land again and again,
  // each landing a short step (2.5 times the resolved run's landings on a ship-driven line). So
  // a landing step ends with the station at rest vertically, the state a resolved landing
  // reaches within the step; the line's own motion still lifts it when it does
  // (SeabedDynamics.LandingsStopWithoutRebound). On the grounded mooring scene: 20 % fewer
  // steps, a third of the rejections, tensions as close to the converged explicit run's.
  if (!m.seabed.present) return;
  bool settled = false;
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    const bool landed = s.x(1, j) >= m.seabed.y && x_(1, j) < m.seabed.y;
    if (!landed || !(h > m.seabed_landing_time[j])) continue;
    v_(1, j) = 0;
    a1_(1, j) = 0;
    abar1_(1, j) = 0;
    settled = true;
  }
  // The tensions' axial damping sees the velocities.
  if (settled) ComputeTensions(m, ws_.geometry, v_, ws_.tension);
}

void GeneralizedAlphaIntegrator::Commit(const CableModel& m, CableState& s, double h) {
  s.x.swap(x_);
  s.v.swap(v_);
  // A station at rest (on the seabed) sees its velocity and acceleration decay geometrically
  // step by step, down to subnormal numbers, whose arithmetic (in drag's q |q|, say) is a hundred
  // times slower: a grounded line ran 25 % slower from the minute its anchor end came to rest.
  // Below 1e-100 (m/s, m/s^2) they are zero.
  auto flush = [](double& q) {
    if (std::abs(q) < 1e-100) q = 0;
  };
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    for (int i = 0; i < 2; ++i) {
      flush(s.v(i, j));
      flush(a1_(i, j));
      flush(abar1_(i, j));
    }
    a_.col(j) = a1_.col(j);
    abar_.col(j) = abar1_.col(j);
  }
  s.t += h;
  ++stats_.steps;
  snaps_.Observe(s.t, h, ws_.geometry.length);
}

void GeneralizedAlphaIntegrator::Step(const CableModel& m, CableState& s, double dt) {
  if (!initialized_) Initialize(m, s);
  const double t_end = s.t + dt;
  if (!(proposed_ > 0) || proposed_ > dt) proposed_ = dt;
  int failures = 0;  // consecutive rejections
  // A step this much smaller than the one asked for makes no useful progress: the motion (an
  // end's acceleration, a snap) is faster than any step can follow; say so rather than crawl.
  const double smallest = kSmallestStepFraction * dt;
  while (s.t < t_end - 1e-12 * dt) {
    ThrowIfCancelled(cancel_, "the implicit step");
    const double h = std::min(proposed_, t_end - s.t);
    if (h < smallest && h < t_end - s.t) {
      std::ostringstream os;
      os << "the implicit step fell to " << h << " s at t = " << s.t << " s (below "
         << kSmallestStepFraction << " of the " << dt
         << " s asked for, " << stats_.rejected
         << " steps rejected in all): the motion is faster than the scheme can follow (an "
            "end's motion too violent, or an unresolvable snap)";
      int worst = 0;
      ws_.geometry.length.cwiseQuotient(m.rest_length).maxCoeff(&worst);
      throw BlowUpError(os.str(), s.t, worst);
    }
    const bool truncated = h < proposed_;
    double error = 0;
    bool ok = Solve(m, s, h);
    if (ok && error_tolerance_ > 0) {
      error = LocalError(m, h);
      ok = error <= error_tolerance_;
    }
    if (!ok) {
      ++stats_.rejected;
      if (++failures > kMaxRejections) {
        std::ostringstream os;
        os << "the implicit step failed " << failures << " times in a row at t = " << s.t
           << " s, down to a step of " << h << " s";
        int worst = 0;
        ws_.geometry.length.cwiseQuotient(m.rest_length).maxCoeff(&worst);
        throw BlowUpError(os.str() + "; the most stretched link is " + std::to_string(worst),
                          s.t, worst);
      }
      // Newton failed: halve. Error too large: the step that would just meet the tolerance
      // (the error grows as h^3), with a margin.
      proposed_ = error > 0 ? h * std::max(0.2, 0.9 * std::cbrt(error_tolerance_ / error))
                            : 0.5 * h;
      continue;
    }
    SettleLandings(m, s, h);
    Commit(m, s, h);
    failures = 0;
    if (truncated) continue;  // a short last piece says nothing about the step size
    const double growth =
        error_tolerance_ > 0
            ? std::min(2.0, 0.9 * std::cbrt(error_tolerance_ / std::max(error, 1e-300)))
            : 2.0;
    proposed_ = std::min(dt, h * growth);
  }
  s.t = t_end;
  CheckStateSane(m, s, ws_.geometry.length);
}

}  // namespace cablefilm
