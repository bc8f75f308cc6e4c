#include "core/constraints.h"

#include <Eigen/LU>
#include <cmath>

#include "core/error.h"

namespace cablefilm {

ConstraintSolver::ConstraintSolver(const LineModel& m)
    : inverse_inertia_(m.stations(), Mat::Zero()), lower_(m.line.links), diag_(m.line.links),
      upper_(m.line.links), rhs_(m.line.links), c_prime_(m.line.links), correction_(kDim, m.stations()) {
  geometry_.length.resize(m.line.links);
  geometry_.tangent.resize(kDim, m.line.links);
}

void ConstraintSolver::Assemble(const LineModel& m, const LinkGeometry& g) {
  for (int j = 0; j <= m.line.links; ++j)
    inverse_inertia_[j] =
        m.prescribed(j) ? Mat::Zero() : Mat(StationInertia(m, g, j).inverse());
  // Row k: t_k . (a_{k+1} - a_k) in terms of T_{k-1}, T_k, T_{k+1}; prescribed stations have
  // W = 0 and so drop out.
  for (int k = 0; k < m.line.links; ++k) {
    const Vec t = g.tangent.col(k);
    const Mat& wa = inverse_inertia_[k];
    const Mat& wb = inverse_inertia_[k + 1];
    diag_[k] = -t.dot(wb * t) - t.dot(wa * t);
    upper_[k] = k + 1 < m.line.links ? t.dot(wb * g.tangent.col(k + 1)) : 0.0;
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

void ConstraintSolver::Distribute(const LineModel& m, const LinkGeometry& g,
                                  const Eigen::VectorXd& lambda, Points& dx) const {
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    Vec f = Vec::Zero();
    if (j < m.line.links) f += lambda[j] * g.tangent.col(j);
    if (j > 0) f -= lambda[j - 1] * g.tangent.col(j - 1);
    dx.col(j) = inverse_inertia_[j] * f;
  }
}

void ConstraintSolver::Accelerations(const LineModel& m, const Inputs& in, const Water& water,
                                     double t, const Points& x, const Points& v,
                                     ForceWorkspace& ws, Points& a) {
  ComputeGeometry(m, water, t, x, ws.geometry);
  Assemble(m, ws.geometry);
  ws.force.setZero();
  AddExternalForces(m, water, ws.geometry, v, ws.force);
  // a^F: the acceleration without the link tensions (exact for prescribed ends).
  for (int j = 0; j <= m.line.links; ++j)
    a.col(j) = m.prescribed(j) ? EndAcceleration(m, in, j, t)
                               : Vec(inverse_inertia_[j] * ws.force.col(j));
  for (int k = 0; k < m.line.links; ++k) {
    const Vec w = v.col(k + 1) - v.col(k);
    rhs_[k] = -w.squaredNorm() / ws.geometry.length[k] -
              ws.geometry.tangent.col(k).dot(a.col(k + 1) - a.col(k));
  }
  if (!Solve()) throw Error("the inextensible cable's constraint tensions are undetermined");
  ws.tension = rhs_;
  Distribute(m, ws.geometry, ws.tension, correction_);
  for (int j = m.first_free(); j <= m.last_free(); ++j) a.col(j) += correction_.col(j);
  // The station forces with the tensions, for anyone who looks at ws.force.
  for (int k = 0; k < m.line.links; ++k) {
    const Vec f = ws.tension[k] * ws.geometry.tangent.col(k);
    ws.force.col(k) += f;
    ws.force.col(k + 1) -= f;
  }
}

bool ConstraintSolver::ProjectPositions(const LineModel& m, Points& x,
                                        double tolerance) {
  for (int it = 0; it < 50; ++it) {
    ComputeGeometry(x, geometry_);
    double worst = 0;
    for (int k = 0; k < m.line.links; ++k) {
      const double g = geometry_.length[k] - m.line.rest_length[k];
      worst = std::max(worst, std::abs(g) / m.line.rest_length[k]);
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

void ConstraintSolver::ProjectVelocities(const LineModel& m, const Points& x,
                                         Points& v) {
  ComputeGeometry(x, geometry_);
  Assemble(m, geometry_);
  for (int k = 0; k < m.line.links; ++k)
    rhs_[k] = -geometry_.tangent.col(k).dot(v.col(k + 1) - v.col(k));
  if (!Solve()) return;
  Distribute(m, geometry_, rhs_, correction_);
  for (int j = m.first_free(); j <= m.last_free(); ++j) v.col(j) += correction_.col(j);
}

}  // namespace cablefilm
