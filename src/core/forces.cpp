#include "core/forces.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/wave_forces.h"

namespace cablefilm {

void ForceWorkspace::Resize(int links) {
  geometry.length.resize(links);
  geometry.tangent.resize(2, links);
  geometry.elevation.resize(links + 1);
  tension.resize(links);
  force.resize(2, links + 1);
}

void ComputeGeometry(const Eigen::Matrix2Xd& x, LinkGeometry& g) {
  const Eigen::Index s = x.cols() - 1;
  g.elevation = x.row(1).transpose();
  for (Eigen::Index j = 0; j < s; ++j) {
    const Eigen::Vector2d d = x.col(j + 1) - x.col(j);
    const double L = d.norm();
    g.length[j] = L;
    g.tangent.col(j) = L > 0 ? Eigen::Vector2d(d / L) : Eigen::Vector2d::Zero();
  }
}

void ComputeGeometry(const CableModel& m, double t, const Eigen::Matrix2Xd& x, LinkGeometry& g) {
  ComputeGeometry(x, g);
  if (m.has_waves()) ComputeSea(m, t, x, g.sea);
}

Eigen::Matrix2d NormalDerivative(const Eigen::Vector2d& t, double L) {
  const Eigen::Matrix2d P = Eigen::Matrix2d::Identity() - t * t.transpose();
  Eigen::Matrix2d dn;
  dn << -P(1, 0), -P(1, 1), P(0, 0), P(0, 1);
  return dn / L;
}

void ComputeHookeTensions(const CableModel& m, const LinkGeometry& g, Eigen::VectorXd& tension) {
  for (int j = 0; j < m.links; ++j) {
    const double strain = g.length[j] / m.rest_length[j] - 1.0;
    tension[j] = strain > 0 ? m.axial_stiffness[j] * strain : 0.0;
  }
}

void AddAxialDamping(const CableModel& m, const LinkGeometry& g, const Eigen::Matrix2Xd& v,
                     Eigen::VectorXd& tension) {
  if (m.axial_damping.size() == 0) return;
  for (int j = 0; j < m.links; ++j) {
    const double c = m.axial_damping[j];  // [N s/m]
    if (c == 0 || !(g.length[j] > m.rest_length[j])) continue;
    const double rate = g.tangent.col(j).dot(v.col(j + 1) - v.col(j));  // dL/dt [m/s]
    tension[j] = std::max(0.0, tension[j] + c * rate);
  }
}

void ComputeTensions(const CableModel& m, const LinkGeometry& g, const Eigen::Matrix2Xd& v,
                     Eigen::VectorXd& tension) {
  ComputeHookeTensions(m, g, tension);
  AddAxialDamping(m, g, v, tension);
}

SeabedReaction SeabedNormal(const CableModel& m, int j, double p, double vy) {
  const double spring = m.seabed_stiffness[j] * p, dashpot = -m.seabed_damping[j] * vy;
  SeabedReaction r;
  if (dashpot <= -spring) return r;  // lifting off faster than the spring lets go: no pull
  if (dashpot >= spring) {           // landing: the dashpot adds at most the spring's force
    r.N = 2.0 * spring;
    r.dN_dp = 2.0 * m.seabed_stiffness[j];
    return r;
  }
  r.N = spring + dashpot;
  r.dN_dp = m.seabed_stiffness[j];
  r.dN_dvy = -m.seabed_damping[j];
  return r;
}

namespace {

// The seabed on the stations below it: N up, -mu N tanh(v_x / v_f) along x (force_jacobian.cpp
// differentiates the same expressions).
void AddSeabedForces(const CableModel& m, const LinkGeometry& g, const Eigen::Matrix2Xd& v,
                     Eigen::Matrix2Xd& force) {
  const SeabedSpec& bed = m.seabed;
  for (int j = 0; j <= m.links; ++j) {
    const double p = bed.y - g.elevation[j];  // penetration [m]
    if (!(p > 0)) continue;
    const double N = SeabedNormal(m, j, p, v(1, j)).N;
    force(1, j) += N;
    if (bed.friction > 0)
      force(0, j) -= bed.friction * N * FrictionShape(v(0, j) / bed.friction_velocity);
  }
}

}  // namespace

void AddExternalForces(const CableModel& m, const LinkGeometry& g, const Eigen::Matrix2Xd& v,
                       Eigen::Matrix2Xd& force) {
  if (m.has_waves()) {  // wave_forces.cpp: drag, inertia, weight and buoyancy in waves
    AddWaveExternalForces(m, g, v, force);
    if (m.seabed.present) AddSeabedForces(m, g, v, force);
    return;
  }
  const bool profile = !m.current_profile.empty();
  Eigen::Vector2d current(m.current, 0.0);  // c, or c(y) at the link's midpoint
  // Normal drag on each link, half to each of its stations: D n / 2 with n = (-sin, cos).
  for (int j = 0; j < m.links; ++j) {
    if (m.drag_factor[j] == 0) continue;
    if (profile) current.x() = m.CurrentAt(0.5 * (g.elevation[j] + g.elevation[j + 1]));
    const Eigen::Vector2d n(-g.tangent(1, j), g.tangent(0, j));
    const Eigen::Vector2d rel = 0.5 * (v.col(j) + v.col(j + 1)) - current;  // relative velocity
    const double q = rel.dot(n);                        // q_{j+1/2} [m/s]
    const double D = -m.drag_factor[j] * q * std::abs(q);  // D_{j+1/2} [N]
    force.col(j) += 0.5 * D * n;
    force.col(j + 1) += 0.5 * D * n;
  }
  for (int j = 0; j <= m.links; ++j) {
    force(1, j) -= m.net_weight[j];  // W_j + W*_j
  }
  // Prism drag X*, Y*: quadratic in the relative speed u_j, each axis with its own factor.
  for (int j : m.weight_stations) {
    if (profile) current.x() = m.CurrentAt(g.elevation[j]);
    const Eigen::Vector2d rel = v.col(j) - current;
    const double u = rel.norm();
    force.col(j) -= u * m.prism_drag.col(j).cwiseProduct(rel);
  }
  if (m.seabed.present) AddSeabedForces(m, g, v, force);
}

void ComputeStationForces(const CableModel& m, const LinkGeometry& g,
                          const Eigen::VectorXd& tension, const Eigen::Matrix2Xd& v,
                          Eigen::Matrix2Xd& force) {
  force.setZero();
  for (int j = 0; j < m.links; ++j) {
    const Eigen::Vector2d f = tension[j] * g.tangent.col(j);
    force.col(j) += f;
    force.col(j + 1) -= f;
  }
  AddExternalForces(m, g, v, force);
}

Eigen::Matrix2d StationInertia(const CableModel& m, const LinkGeometry& g, int j) {
  if (m.has_waves()) return WaveStationInertia(m, g, j);
  // m_j + m^x_j on the diagonal, plus half the entrained-fluid mass e of each adjoining link
  // acting along that link's normal n: e n n^T / 2 gives the I, J and -K terms of eq. (1).
  Eigen::Matrix2d M = Eigen::Vector2d(m.cable_mass[j] + m.prism_mass(0, j),
                                      m.cable_mass[j] + m.prism_mass(1, j))
                          .asDiagonal();
  for (int k = j - 1; k <= j; ++k) {
    if (k < 0 || k >= m.links) continue;
    const Eigen::Vector2d n(-g.tangent(1, k), g.tangent(0, k));
    M.noalias() += (0.5 * m.virtual_mass[k]) * n * n.transpose();
  }
  return M;
}

void ComputeAccelerations(const CableModel& m, double t, const Eigen::Matrix2Xd& x,
                          const Eigen::Matrix2Xd& v, ForceWorkspace& ws, Eigen::Matrix2Xd& a) {
  ComputeGeometry(m, t, x, ws.geometry);
  ComputeTensions(m, ws.geometry, v, ws.tension);
  ComputeStationForces(m, ws.geometry, ws.tension, v, ws.force);
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    const Eigen::Matrix2d M = StationInertia(m, ws.geometry, j);
    a.col(j) = M.inverse() * ws.force.col(j);  // closed-form 2x2 inverse
  }
  if (m.start.prescribed()) a.col(0) = m.start.Acceleration(t);
  if (m.end.prescribed()) a.col(m.links) = m.end.Acceleration(t);
}

double KineticEnergy(const CableModel& m, const LinkGeometry& g, const Eigen::Matrix2Xd& v) {
  double e = 0;
  for (int j = 0; j <= m.links; ++j) {
    const Eigen::Vector2d vj = v.col(j);
    e += 0.5 * vj.dot(StationInertia(m, g, j) * vj);
  }
  return e;
}

double ElasticEnergy(const CableModel& m, const LinkGeometry& g) {
  double e = 0;
  for (int j = 0; j < m.links; ++j) {
    const double stretch = g.length[j] - m.rest_length[j];
    if (stretch > 0) e += 0.5 * m.axial_stiffness[j] / m.rest_length[j] * stretch * stretch;
  }
  return e;
}

double PotentialEnergy(const CableModel& m, const Eigen::Matrix2Xd& x) {
  double e = 0;
  for (int j = 0; j <= m.links; ++j) e += m.net_weight[j] * x(1, j);
  if (m.seabed.present) e += SeabedEnergy(m, x);
  if (m.has_waves()) e += SurfaceBuoyancyEnergy(m, x);
  return e;
}

double SeabedEnergy(const CableModel& m, const Eigen::Matrix2Xd& x) {
  if (!m.seabed.present) return 0.0;
  double e = 0;
  for (int j = 0; j <= m.links; ++j) {
    const double p = m.seabed.y - x(1, j);
    if (p > 0) e += 0.5 * m.seabed_stiffness[j] * p * p;
  }
  return e;
}

}  // namespace cablefilm
