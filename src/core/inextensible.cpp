#include "core/inextensible.h"

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <sstream>

namespace cablefilm {

ConstraintSolver::ConstraintSolver(const CableModel& m)
    : inverse_inertia_(m.stations(), Eigen::Matrix2d::Zero()), lower_(m.links), diag_(m.links),
      upper_(m.links), rhs_(m.links), c_prime_(m.links), correction_(2, m.stations()) {
  geometry_.length.resize(m.links);
  geometry_.tangent.resize(2, m.links);
}

void ConstraintSolver::Assemble(const CableModel& m, const LinkGeometry& g) {
  for (int j = 0; j <= m.links; ++j)
    inverse_inertia_[j] =
        m.prescribed(j) ? Eigen::Matrix2d::Zero() : Eigen::Matrix2d(StationInertia(m, g, j).inverse());
  // Row k: t_k . (a_{k+1} - a_k) in terms of T_{k-1}, T_k, T_{k+1}; prescribed stations have
  // W = 0 and so drop out.
  for (int k = 0; k < m.links; ++k) {
    const Eigen::Vector2d t = g.tangent.col(k);
    const Eigen::Matrix2d& wa = inverse_inertia_[k];
    const Eigen::Matrix2d& wb = inverse_inertia_[k + 1];
    diag_[k] = -t.dot(wb * t) - t.dot(wa * t);
    upper_[k] = k + 1 < m.links ? t.dot(wb * g.tangent.col(k + 1)) : 0.0;
    lower_[k] = k > 0 ? t.dot(wa * g.tangent.col(k - 1)) : 0.0;
  }
}

bool ConstraintSolver::Solve() {
  const int n = static_cast<int>(diag_.size());
  for (int i = 0; i < n; ++i) {
    double pivot = diag_[i];
    if (i > 0) {
      pivot -= lower_[i] * c_prime_[i - 1];
      rhs_[i] -= lower_[i] * rhs_[i - 1];
    }
    if (!(std::abs(pivot) > 0)) return false;
    c_prime_[i] = upper_[i] / pivot;
    rhs_[i] /= pivot;
  }
  for (int i = n - 2; i >= 0; --i) rhs_[i] -= c_prime_[i] * rhs_[i + 1];
  return true;
}

void ConstraintSolver::Distribute(const CableModel& m, const LinkGeometry& g,
                                  const Eigen::VectorXd& lambda, Eigen::Matrix2Xd& dx) const {
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    Eigen::Vector2d f = Eigen::Vector2d::Zero();
    if (j < m.links) f += lambda[j] * g.tangent.col(j);
    if (j > 0) f -= lambda[j - 1] * g.tangent.col(j - 1);
    dx.col(j) = inverse_inertia_[j] * f;
  }
}

void ConstraintSolver::Accelerations(const CableModel& m, double t, const Eigen::Matrix2Xd& x,
                                     const Eigen::Matrix2Xd& v, ForceWorkspace& ws,
                                     Eigen::Matrix2Xd& a) {
  ComputeGeometry(m, t, x, ws.geometry);
  Assemble(m, ws.geometry);
  ws.force.setZero();
  AddExternalForces(m, ws.geometry, v, ws.force);
  // a^F: the acceleration without the link tensions (exact for prescribed ends).
  for (int j = 0; j <= m.links; ++j)
    a.col(j) = m.prescribed(j) ? m.end_motion(j).Acceleration(t)
                               : Eigen::Vector2d(inverse_inertia_[j] * ws.force.col(j));
  for (int k = 0; k < m.links; ++k) {
    const Eigen::Vector2d w = v.col(k + 1) - v.col(k);
    rhs_[k] = -w.squaredNorm() / ws.geometry.length[k] -
              ws.geometry.tangent.col(k).dot(a.col(k + 1) - a.col(k));
  }
  if (!Solve()) throw Error("the inextensible cable's constraint tensions are undetermined");
  ws.tension = rhs_;
  Distribute(m, ws.geometry, ws.tension, correction_);
  for (int j = m.first_free(); j <= m.last_free(); ++j) a.col(j) += correction_.col(j);
  // The station forces with the tensions, for anyone who looks at ws.force.
  for (int k = 0; k < m.links; ++k) {
    const Eigen::Vector2d f = ws.tension[k] * ws.geometry.tangent.col(k);
    ws.force.col(k) += f;
    ws.force.col(k + 1) -= f;
  }
}

bool ConstraintSolver::ProjectPositions(const CableModel& m, Eigen::Matrix2Xd& x,
                                        double tolerance) {
  for (int it = 0; it < 50; ++it) {
    ComputeGeometry(x, geometry_);
    double worst = 0;
    for (int k = 0; k < m.links; ++k) {
      const double g = geometry_.length[k] - m.rest_length[k];
      worst = std::max(worst, std::abs(g) / m.rest_length[k]);
      rhs_[k] = -g;
    }
    if (worst <= tolerance) return true;
    Assemble(m, geometry_);
    if (!Solve()) return false;
    Distribute(m, geometry_, rhs_, correction_);
    for (int j = m.first_free(); j <= m.last_free(); ++j) x.col(j) += correction_.col(j);
  }
  return false;
}

void ConstraintSolver::ProjectVelocities(const CableModel& m, const Eigen::Matrix2Xd& x,
                                         Eigen::Matrix2Xd& v) {
  ComputeGeometry(x, geometry_);
  Assemble(m, geometry_);
  for (int k = 0; k < m.links; ++k)
    rhs_[k] = -geometry_.tangent.col(k).dot(v.col(k + 1) - v.col(k));
  if (!Solve()) return;
  Distribute(m, geometry_, rhs_, correction_);
  for (int j = m.first_free(); j <= m.last_free(); ++j) v.col(j) += correction_.col(j);
}

InextensibleIntegrator::InextensibleIntegrator(const CableModel& m, double error_tolerance)
    : solver_(m), ws_(m.links), trial_ws_(m.links), a_(2, m.stations()), v_pred_(2, m.stations()),
      trial_x_(2, m.stations()), trial_v_(2, m.stations()), trial_a_(2, m.stations()),
      error_tolerance_(error_tolerance), steps_(m) {}

std::string InextensibleIntegrator::name() const {
  if (!(error_tolerance_ > 0)) return "inextensible (constraint tensions)";
  std::ostringstream os;
  os << "inextensible (constraint tensions, local position error per step below "
     << error_tolerance_ << " m)";
  return os.str();
}

void InextensibleIntegrator::Initialize(const CableModel& m, const CableState& state) {
  solver_.Accelerations(m, state.t, state.x, state.v, ws_, a_);
  CheckStateSane(m, state, ws_.geometry.length);
  initialized_ = true;
}

double InextensibleIntegrator::StableSubstep(const CableModel& m) const {
  // Transverse waves: a station between links under tension T has stiffness T/L across them.
  // Gershgorin: omega^2 <= max_j 2 (|T_{j-1}| + |T_j|) / (m_j l); half the resulting step, as
  // the tension may rise within it.
  double lambda = 0;
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    const double mj = m.cable_mass[j] + m.SmallestPrismMass(j);
    double stiffness = 0;
    if (j > 0) stiffness += std::abs(ws_.tension[j - 1]) / m.rest_length[j - 1];
    if (j < m.links) stiffness += std::abs(ws_.tension[j]) / m.rest_length[j];
    lambda = std::max(lambda, 2.0 * stiffness / mj);
  }
  if (m.seabed.present) {
    // The seabed's spring and dashpot on each station (any may land within the substep), with
    // the transverse stiffness: the bound of the explicit scheme with damping (stability.cpp),
    // omega h <= 2 (sqrt(1 + 4 zeta^2) - 2 zeta), halved as above.
    double gamma = 0;
    for (int j = m.first_free(); j <= m.last_free(); ++j) {
      const double mj = m.cable_mass[j] + m.SmallestPrismMass(j);
      double stiffness = 2.0 * m.seabed_stiffness[j];  // at most twice the spring's (forces.cpp)
      if (j > 0) stiffness += 2.0 * std::abs(ws_.tension[j - 1]) / m.rest_length[j - 1];
      if (j < m.links) stiffness += 2.0 * std::abs(ws_.tension[j]) / m.rest_length[j];
      lambda = std::max(lambda, stiffness / mj);
      gamma = std::max(gamma, m.seabed_damping[j] / mj);
    }
    if (!(lambda > 0)) return std::numeric_limits<double>::infinity();
    const double omega = std::sqrt(lambda), zeta = gamma / (2.0 * omega);
    return 0.5 * 2.0 * (std::sqrt(1.0 + 4.0 * zeta * zeta) - 2.0 * zeta) / omega;
  }
  return lambda > 0 ? 0.5 * 2.0 / std::sqrt(lambda) : std::numeric_limits<double>::infinity();
}

bool InextensibleIntegrator::Trial(const CableModel& m, const CableState& s, double h) {
  const double t1 = s.t + h;
  const int j0 = m.first_free(), j1 = m.last_free();
  trial_x_ = s.x;
  trial_v_ = s.v;
  for (int j = j0; j <= j1; ++j) {
    v_pred_.col(j) = s.v.col(j) + h * a_.col(j);
    trial_v_.col(j) += 0.5 * h * a_.col(j);
    trial_x_.col(j) += h * trial_v_.col(j);
  }
  for (int j : {0, m.links}) {
    if (!m.prescribed(j)) continue;
    trial_x_.col(j) = m.end_motion(j).Position(t1);
    trial_v_.col(j) = m.end_motion(j).Velocity(t1);
    v_pred_.col(j) = trial_v_.col(j);
  }
  if (!solver_.ProjectPositions(m, trial_x_, 1e-13)) return false;
  solver_.Accelerations(m, t1, trial_x_, v_pred_, trial_ws_, trial_a_);
  for (int j = j0; j <= j1; ++j) trial_v_.col(j) += 0.5 * h * trial_a_.col(j);
  solver_.ProjectVelocities(m, trial_x_, trial_v_);
  return true;
}

double InextensibleIntegrator::LocalError(const CableModel& m, double h) const {
  double da = 0;
  for (int j = m.first_free(); j <= m.last_free(); ++j)
    da = std::max(da, (trial_a_.col(j) - a_.col(j)).lpNorm<Eigen::Infinity>());
  return h * h / 6.0 * da;
}

void InextensibleIntegrator::Accept(CableState& s, double h) {
  s.x.swap(trial_x_);
  s.v.swap(trial_v_);
  a_.swap(trial_a_);
  ws_.geometry.length.swap(trial_ws_.geometry.length);
  ws_.geometry.tangent.swap(trial_ws_.geometry.tangent);
  ws_.tension.swap(trial_ws_.tension);
  ws_.force.swap(trial_ws_.force);
  s.t += h;
  ++stats_.steps;
  steps_.ObserveStep(h);
}

void InextensibleIntegrator::Step(const CableModel& m, CableState& s, double dt) {
  if (!initialized_) Initialize(m, s);
  const double t_end = s.t + dt;
  if (!(error_tolerance_ > 0)) {
    while (s.t < t_end - 1e-12 * dt) {
      ThrowIfCancelled(cancel_, "the inextensible step");
      const double remaining = t_end - s.t;
      const int pieces = static_cast<int>(std::ceil(remaining / StableSubstep(m) - 1e-9));
      const double h = remaining / std::max(1, pieces);
      if (!Trial(m, s, h)) {
        std::ostringstream os;
        os << "the inextensible cable cannot keep its length at t = " << s.t + h
           << " s: its ends are pulled further apart than the cable is long";
        throw BlowUpError(os.str(), s.t + h, m.links);
      }
      Accept(s, h);
    }
    s.t = t_end;
    CheckStateSane(m, s, ws_.geometry.length);
    return;
  }
  if (!(proposed_ > 0) || proposed_ > dt) proposed_ = dt;
  const double smallest = kSmallestSubstep * dt;
  int failures = 0;  // rejections in a row
  while (s.t < t_end - 1e-12 * dt) {
    ThrowIfCancelled(cancel_, "the inextensible step");
    const double longest = std::min(proposed_, StableSubstep(m));
    const double h = std::min(longest, t_end - s.t);
    const bool limited = h < proposed_;  // by the wave limit or the end of the step asked
    const bool projected = longest >= smallest && Trial(m, s, h);
    double error = 0;
    if (projected) {
      error = LocalError(m, h);
      if (error <= error_tolerance_) {
        Accept(s, h);
        failures = 0;
        // A substep cut short says nothing about the size the error allows.
        if (!limited)
          proposed_ = std::min(
              dt, h * std::min(2.0, 0.9 * std::cbrt(error_tolerance_ / std::max(error, 1e-300))));
        continue;
      }
    }
    ++stats_.rejected;
    ++failures;
    // Error too large: the substep that would just meet the tolerance (the error grows as h^3),
    // with a margin. Projection failed: half the substep.
    const double next = projected ? h * std::max(0.2, 0.9 * std::cbrt(error_tolerance_ / error))
                                  : 0.5 * h;
    if (longest < smallest || next < smallest || failures > kMaxRejections) {
      std::ostringstream os;
      os << "the inextensible step cannot be made accurate at t = " << s.t << " s: ";
      if (longest < smallest)
        os << "its tensions (up to " << ws_.tension.cwiseAbs().maxCoeff()
           << " N) allow substeps of only " << longest << " s (are the ends pulled as far apart "
           << "as the cable is long?)";
      else if (projected)
        os << "a substep of " << h << " s has a local position error of " << error
           << " m against the tolerance of " << error_tolerance_ << " m";
      else
        os << "a substep of " << h << " s cannot keep the link lengths (are the ends pulled "
           << "further apart than the cable is long?)";
      if (longest >= smallest) os << ", " << failures << " rejections in a row";
      os << "; the smallest substep is " << smallest << " s (" << kSmallestSubstep
         << " of the step asked)";
      throw BlowUpError(os.str(), s.t, m.links);
    }
    proposed_ = next;
  }
  s.t = t_end;
  CheckStateSane(m, s, ws_.geometry.length);
}

CableState SolveInextensibleEquilibrium(const CableModel& m, EquilibriumReport* report) {
  if (m.start.prescribed() && m.end.prescribed()) {
    const double chord = (m.end.Position(0) - m.start.Position(0)).norm();
    if (chord >= m.total_length()) {
      std::ostringstream os;
      os << "the ends are " << chord << " m apart but the inextensible cable is only "
         << m.total_length() << " m long";
      throw Error(os.str());
    }
  }
  // A penalty stiffness that stretches the cable by about 1e-6 under its loads: stiff enough
  // for Richardson extrapolation in 1/EA to be exact to O(1e-12), soft enough for the Newton
  // residual to stay above round-off.
  const double load = StaticForceScale(m);
  CableModel stiff = m;
  stiff.law = LinkLaw::kElastic;
  stiff.axial_stiffness.setConstant(1e6 * load);
  EquilibriumReport first;
  const CableState soft = SolveEquilibrium(stiff, &first);
  stiff.axial_stiffness *= 2.0;
  CableState hard = SolveEquilibrium(stiff, soft.x, report);
  if (report) report->iterations += first.iterations;
  hard.x = 2.0 * hard.x - soft.x;  // the limit EA -> infinity, error O(1/EA^2)
  ConstraintSolver solver(m);
  if (!solver.ProjectPositions(m, hard.x, 1e-13))
    throw Error("cannot place the inextensible cable at its rest lengths between its ends");
  return hard;
}

}  // namespace cablefilm
