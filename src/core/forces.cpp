#include "core/forces.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/seabed_friction.h"
#include "core/wave_forces.h"

namespace cablefilm {

void ForceWorkspace::Resize(int links) {
  geometry.length.resize(links);
  geometry.tangent.resize(kDim, links);
  geometry.elevation.resize(links + 1);
  tension.resize(links);
  force.resize(kDim, links + 1);
}

void ComputeGeometry(const Points& x, LinkGeometry& g) {
  const Eigen::Index s = x.cols() - 1;
  g.elevation = x.row(1).transpose();
  for (Eigen::Index j = 0; j < s; ++j) {
    const Vec d = x.col(j + 1) - x.col(j);
    const double L = d.norm();
    g.length[j] = L;
    g.tangent.col(j) = L > 0 ? Vec(d / L) : Vec::Zero();
  }
}

void ComputeGeometry(const LineModel& m, const Water& water, double t, const Points& x,
                     LinkGeometry& g) {
  ComputeGeometry(x, g);
  if (m.has_waves()) ComputeSea(m, water, t, x, g.sea);
  ComputeStick(x, g);
}


void ComputeHookeTensions(const LineModel& m, const LinkGeometry& g, Eigen::VectorXd& tension) {
  for (int j = 0; j < m.line.links; ++j) {
    const double strain = g.length[j] / m.line.rest_length[j] - 1.0;
    tension[j] = strain > 0 ? m.line.axial_stiffness[j] * strain : 0.0;
  }
}

void AddAxialDamping(const LineModel& m, const LinkGeometry& g, const Points& v,
                     Eigen::VectorXd& tension) {
  if (m.line.axial_damping.size() == 0) return;
  for (int j = 0; j < m.line.links; ++j) {
    const double c = m.line.axial_damping[j];  // [N s/m]
    if (c == 0 || !(g.length[j] > m.line.rest_length[j])) continue;
    const double rate = g.tangent.col(j).dot(v.col(j + 1) - v.col(j));  // dL/dt [m/s]
    tension[j] = std::max(0.0, tension[j] + c * rate);
  }
}

void ComputeTensions(const LineModel& m, const LinkGeometry& g, const Points& v,
                     Eigen::VectorXd& tension) {
  ComputeHookeTensions(m, g, tension);
  AddAxialDamping(m, g, v, tension);
}

SeabedReaction SeabedNormal(const LineModel& m, int j, double p, double vy) {
  const double spring = m.line.seabed_stiffness[j] * p, dashpot = -m.line.seabed_damping[j] * vy;
  SeabedReaction r;
  if (dashpot <= -spring) return r;  // lifting off faster than the spring lets go: no pull
  if (dashpot >= spring) {           // landing: the dashpot adds at most the spring's force
    r.N = 2.0 * spring;
    r.dN_dp = 2.0 * m.line.seabed_stiffness[j];
    return r;
  }
  r.N = spring + dashpot;
  r.dN_dp = m.line.seabed_stiffness[j];
  r.dN_dvy = -m.line.seabed_damping[j];
  return r;
}

namespace {

// The seabed on the stations below it: N up, and the friction along it: stick-slip
// (seabed_friction.h; none without anchors: a state at rest, statics) or smoothed,
// -mu N tanh(|v_h| / v_f) v_h / |v_h| against the sliding velocity v_h (force_jacobian.cpp
// differentiates the same expressions).
void AddSeabedForces(const LineModel& m, const LinkGeometry& g, const Points& v, Points& force) {
  const SeabedSpec& bed = m.env.seabed;
  const bool sticks = HasStickSlip(m);
  for (int j = 0; j <= m.line.links; ++j) {
    const double p = bed.y - g.elevation[j];  // penetration [m]
    if (!(p > 0)) continue;
    const double N = SeabedNormal(m, j, p, v(kVertical, j)).N;
    force(kVertical, j) += N;
    if (sticks) {
      if (g.stick.cols() > 0)  // no anchors, no friction: statics
        force.col(j) += StickSlipFriction(bed.friction, N, m.line.friction_stiffness[j],
                                          m.line.friction_damping[j], g.stick.col(j),
                                          HorizontalPart(v.col(j)))
                            .force;
    } else if (bed.friction > 0) {
      force.col(j) -= bed.friction * N * SlidingDirection(v.col(j), bed);
    }
  }
}

}  // namespace

void AddExternalForces(const LineModel& m, const Water& water, const LinkGeometry& g,
                       const Points& v, Points& force) {
  if (UsesSea(m, g)) {  // wave_forces.cpp: drag, inertia, weight and buoyancy in waves
    AddWaveExternalForces(m, water, g, v, force);
    if (m.env.seabed.present) AddSeabedForces(m, g, v, force);
    return;
  }
  const bool profile = !m.env.current_profile.empty();
  Vec current = CurrentAt(m, water, 0.0);  // c, or c(y) at the link's midpoint
  // Normal drag on each link, half to each of its stations: D = -f^D |q| q with q the normal
  // part of the relative velocity (eq. (1)'s D n, n the normal in the plane of the motion); and
  // the tangential drag along it, D^t = -f^T |p| p t with p = t . (relative velocity).
  for (int j = 0; j < m.line.links; ++j) {
    const double f = m.line.drag_factor[j], ft = m.line.tangential_drag_factor[j];
    if (f == 0 && ft == 0) continue;
    if (profile) current = CurrentAt(m, water, 0.5 * (g.elevation[j] + g.elevation[j + 1]));
    const Vec t = g.tangent.col(j);
    const Vec rel = 0.5 * (v.col(j) + v.col(j + 1)) - current;  // relative velocity
    if (f != 0) {
      const Vec q = rel - t * t.dot(rel);          // q_{j+1/2} [m/s]
      const Vec D = (-0.5 * f * q.norm()) * q;     // D_{j+1/2} / 2 [N]
      force.col(j) += D;
      force.col(j + 1) += D;
    }
    if (ft != 0) {
      const double p = t.dot(rel);                       // p_{j+1/2} [m/s]
      const Vec Dt = (-0.5 * ft * std::abs(p) * p) * t;  // D^t_{j+1/2} / 2 [N]
      force.col(j) += Dt;
      force.col(j + 1) += Dt;
    }
  }
  for (int j = 0; j <= m.line.links; ++j) {
    force(kVertical, j) -= m.line.net_weight[j];  // W_j + W*_j
  }
  // Prism drag X*, Y*, Z*: quadratic in the relative speed u_j, each axis with its own factor.
  for (int j : m.line.weight_stations) {
    if (profile) current = CurrentAt(m, water, g.elevation[j]);
    const Vec rel = v.col(j) - current;
    const double u = rel.norm();
    force.col(j) -= u * m.line.prism_drag.col(j).cwiseProduct(rel);
    force.col(j) += m.line.prism_force.col(j);
  }
  if (m.env.seabed.present) AddSeabedForces(m, g, v, force);
}

void ComputeStationForces(const LineModel& m, const Water& water, const LinkGeometry& g,
                          const Eigen::VectorXd& tension, const Points& v, Points& force) {
  force.setZero();
  for (int j = 0; j < m.line.links; ++j) {
    const Vec f = tension[j] * g.tangent.col(j);
    force.col(j) += f;
    force.col(j + 1) -= f;
  }
  AddExternalForces(m, water, g, v, force);
}

namespace {

// Whether the inertia takes the wet shares of the added masses: with the sea's forces, when
// the sea's state is there (a geometry made without the model's water has none: all wet).
bool WetInertia(const LineModel& m, const LinkGeometry& g) {
  return UsesSea(m, g) && g.sea.wet.size() == m.stations();
}

// The two below for a line all wet (kWet false: the loops as they were before the wet shares
// came in; tested at every station, those cost P63 at 6000 links a few per cent) or with the
// wet shares.
template <bool kWet>
void AddStationInertiaOf(const LineModel& m, const LinkGeometry& g, int j, double scale, Mat& block) {
  // m_j + m^x_j on the diagonal, plus half the entrained-fluid mass e of each adjoining link
  // across it, e (I - t t^T) / 2: the I, J and -K terms of eq. (1) (I - t t^T = n n^T in the
  // plane); and half its tangential added mass e^t along it, e^t t t^T / 2 (0 unless given).
  // With the sea's forces, the added masses' wet shares: (1 - phi_j) m^x_j is above the
  // surface, and psi_k of each link's. Written out entry by entry (symmetric): this runs for
  // every station in every Newton iteration and explicit step, where Eigen's general
  // expressions cost twice as much (a 3x3 matrix built per station in waves was a sixth of a
  // still-water run's time); and added to the block entry by entry, not returned as a matrix
  // that the caller reads two entries at a time (entries stored one by one and loaded in
  // pairs stall the store forwarding: a sixth of the Newton matrix's inertia part).
  double d0 = m.line.cable_mass[j] + m.line.prism_mass(0, j);
  double d1 = m.line.cable_mass[j] + m.line.prism_mass(1, j);
  double d2 = m.line.cable_mass[j] + m.line.prism_mass(2, j);
  if constexpr (kWet) {
    const double dry = 1.0 - g.sea.wet[j];  // 1 - phi_j
    d0 -= dry * m.line.prism_added_mass(0, j);
    d1 -= dry * m.line.prism_added_mass(1, j);
    d2 -= dry * m.line.prism_added_mass(2, j);
  }
  double m01 = 0, m02 = 0, m12 = 0;
  for (int k = std::max(j - 1, 0); k <= std::min(j, m.line.links - 1); ++k) {
    double e = 0.5 * m.line.virtual_mass[k], et = 0.5 * m.line.tangential_virtual_mass[k];
    if constexpr (kWet) {
      const double psi = LinkWet(g.sea, k);
      e *= psi;
      et *= psi;
    }
    const double tx = g.tangent(0, k), ty = g.tangent(1, k), tz = g.tangent(2, k);
    d0 += e - e * tx * tx;
    d1 += e - e * ty * ty;
    d2 += e - e * tz * tz;
    m01 -= e * tx * ty;
    m02 -= e * tx * tz;
    m12 -= e * ty * tz;
    if (et == 0) continue;
    d0 += et * tx * tx;
    d1 += et * ty * ty;
    d2 += et * tz * tz;
    m01 += et * tx * ty;
    m02 += et * tx * tz;
    m12 += et * ty * tz;
  }
  block(0, 0) += scale * d0;
  block(1, 0) += scale * m01;
  block(2, 0) += scale * m02;
  block(0, 1) += scale * m01;
  block(1, 1) += scale * d1;
  block(2, 1) += scale * m12;
  block(0, 2) += scale * m02;
  block(1, 2) += scale * m12;
  block(2, 2) += scale * d2;
}

template <bool kWet>
Vec StationInertiaTimesOf(const LineModel& m, const LinkGeometry& g, int j, const Vec& a) {
  // (m_j + m^x_j) a on the diagonal; each adjoining link's e (a - t (t . a)) / 2 across it and
  // e^t t (t . a) / 2 along it; with the sea's forces their wet shares (AddStationInertia).
  Vec diagonal = (m.line.cable_mass[j] + m.line.prism_mass.col(j).array()).matrix();
  if constexpr (kWet) diagonal -= (1.0 - g.sea.wet[j]) * m.line.prism_added_mass.col(j);
  Vec f = diagonal.cwiseProduct(a);
  for (int k = std::max(j - 1, 0); k <= std::min(j, m.line.links - 1); ++k) {
    const Vec t = g.tangent.col(k);
    const double ta = t.dot(a);
    double e = 0.5 * m.line.virtual_mass[k], et = 0.5 * m.line.tangential_virtual_mass[k];
    if constexpr (kWet) {
      const double psi = LinkWet(g.sea, k);
      e *= psi;
      et *= psi;
    }
    f += e * a + ((et - e) * ta) * t;
  }
  return f;
}

}  // namespace

void AddStationInertia(const LineModel& m, const LinkGeometry& g, int j, double scale, Mat& block) {
  if (WetInertia(m, g)) AddStationInertiaOf<true>(m, g, j, scale, block);
  else AddStationInertiaOf<false>(m, g, j, scale, block);
}

Vec StationInertiaTimes(const LineModel& m, const LinkGeometry& g, int j, const Vec& a) {
  return WetInertia(m, g) ? StationInertiaTimesOf<true>(m, g, j, a)
                          : StationInertiaTimesOf<false>(m, g, j, a);
}

Mat StationInertia(const LineModel& m, const LinkGeometry& g, int j) {
  Mat M = Mat::Zero();
  AddStationInertia(m, g, j, 1.0, M);
  return M;
}

void ComputeAccelerations(const LineModel& m, const Inputs& in, const Water& water, double t,
                          const Points& x, const Points& v, ForceWorkspace& ws, Points& a) {
  ComputeGeometry(m, water, t, x, ws.geometry);
  ComputeTensions(m, ws.geometry, v, ws.tension);
  ComputeStationForces(m, water, ws.geometry, ws.tension, v, ws.force);
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    const Mat M = StationInertia(m, ws.geometry, j);
    a.col(j) = M.inverse() * ws.force.col(j);  // closed-form inverse of a fixed-size matrix
  }
  if (m.ends.start.prescribed()) a.col(0) = EndAcceleration(m, in, 0, t);
  if (m.ends.end.prescribed()) a.col(m.line.links) = EndAcceleration(m, in, m.line.links, t);
}

double KineticEnergy(const LineModel& m, const LinkGeometry& g, const Points& v) {
  double e = 0;
  for (int j = 0; j <= m.line.links; ++j) {
    const Vec vj = v.col(j);
    e += 0.5 * vj.dot(StationInertia(m, g, j) * vj);
  }
  return e;
}

double ElasticEnergy(const LineModel& m, const LinkGeometry& g) {
  double e = 0;
  for (int j = 0; j < m.line.links; ++j) {
    const double stretch = g.length[j] - m.line.rest_length[j];
    if (stretch > 0) e += 0.5 * m.line.axial_stiffness[j] / m.line.rest_length[j] * stretch * stretch;
  }
  return e;
}

double PotentialEnergy(const LineModel& m, const Points& x) {
  double e = 0;
  for (int j = 0; j <= m.line.links; ++j) e += m.line.net_weight[j] * x(kVertical, j);
  if (m.env.seabed.present) e += SeabedEnergy(m, x);
  if (m.has_waves()) e += SurfaceBuoyancyEnergy(m, x);
  return e;
}

double SeabedEnergy(const LineModel& m, const Points& x) {
  if (!m.env.seabed.present) return 0.0;
  double e = 0;
  for (int j = 0; j <= m.line.links; ++j) {
    const double p = m.env.seabed.y - x(kVertical, j);
    if (p > 0) e += 0.5 * m.line.seabed_stiffness[j] * p * p;
  }
  return e;
}

}  // namespace cablefilm
