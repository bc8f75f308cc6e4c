#include "core/wave_forces.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace cablefilm {
namespace {

Eigen::Map<const Eigen::Matrix2d> Gradient(const Eigen::Matrix4Xd& g, int j) {
  return Eigen::Map<const Eigen::Matrix2d>(g.col(j).data());
}

void CheckSea(const CableModel& m, const SeaState& sea) {
  if (sea.wet.size() != m.stations())
    throw Error("internal: the forces in waves were asked for without the sea's state "
                "(ComputeGeometry with the model and the time)");
}

// Adds the block B to the (row j, column i) block of the free stations' system.
void AddBlock(const CableModel& m, int j, int i, const Eigen::Matrix2d& B, BlockTridiagonal& s) {
  const int j0 = m.first_free(), j1 = m.last_free();
  if (j < j0 || j > j1 || i < j0 || i > j1) return;
  if (i == j) s.diag[j - j0] += B;
  else if (i == j + 1) s.upper[j - j0] += B;
  else s.lower[j - j0] += B;
}

double LinkWet(const SeaState& sea, int k) { return 0.5 * (sea.wet[k] + sea.wet[k + 1]); }

}  // namespace

double WetFraction(double u) {
  if (u <= 0) return 0.0;
  if (u >= 1) return 1.0;
  return u * u * (3.0 - 2.0 * u);
}

double WetFractionSlope(double u) {
  if (u <= 0 || u >= 1) return 0.0;
  return 6.0 * u * (1.0 - u);
}

double SurfaceBuoyancyEnergy(const CableModel& m, const Eigen::Matrix2Xd& x) {
  if (!m.has_waves()) return 0.0;
  // G(u) = int_0^u phi: 0 below the band, u^3 - u^4 / 2 across it, u - 1/2 beyond.
  auto G = [](double u) {
    if (u <= 0) return 0.0;
    if (u >= 1) return u - 0.5;
    return u * u * u * (1.0 - 0.5 * u);
  };
  double e = 0;
  for (int j = 0; j < m.stations(); ++j) {
    const double band = m.wet_band[j];
    if (m.station_buoyancy[j] == 0 || !(band > 0)) continue;
    const double u = (m.wave.spec.surface_y - x(1, j)) / band + 0.5;
    // Under water (u >= 1) y + l G(u) = y_surface: the same at every depth.
    e += m.station_buoyancy[j] * (x(1, j) + band * G(u));
  }
  return e;
}

void ComputeSea(const CableModel& m, double t, const Eigen::Matrix2Xd& x, SeaState& sea) {
  const int n = m.stations();
  if (sea.wet.size() != n) {
    sea.velocity.resize(2, n);
    sea.acceleration.resize(2, n);
    sea.velocity_gradient.resize(4, n);
    sea.acceleration_gradient.resize(4, n);
    sea.wet.resize(n);
    sea.wet_gradient.resize(2, n);
  }
  sea.t = t;
  const WaveRamp ramp = RampAt(m.wave.spec, t);
  for (int j = 0; j < n; ++j) {
    const WaterKinematics w = KinematicsAt(m.wave, x(0, j), x(1, j), t, ramp);
    sea.velocity.col(j) = w.velocity;
    sea.acceleration.col(j) = w.acceleration;
    Eigen::Map<Eigen::Matrix2d>(sea.velocity_gradient.col(j).data()) = w.velocity_gradient;
    Eigen::Map<Eigen::Matrix2d>(sea.acceleration_gradient.col(j).data()) = w.acceleration_gradient;
    // Depth below the instantaneous surface over the station's band: u = 1/2 at the surface.
    const double band = m.wet_band[j];
    const double depth = m.wave.spec.surface_y + w.eta - x(1, j);
    const double u = depth / band + 0.5;
    sea.wet[j] = WetFraction(u);
    sea.wet_gradient.col(j) =
        (WetFractionSlope(u) / band) * Eigen::Vector2d(w.eta_gradient.x(), -1.0);
  }
}

void AddWaveExternalForces(const CableModel& m, const LinkGeometry& g, const Eigen::Matrix2Xd& v,
                           Eigen::Matrix2Xd& force) {
  const SeaState& sea = g.sea;
  CheckSea(m, sea);
  const bool profile = !m.current_profile.empty();
  Eigen::Vector2d current(m.current, 0.0);
  for (int k = 0; k < m.links; ++k) {
    const double psi = LinkWet(sea, k);
    if (psi == 0) continue;  // in the air: no drag, no fluid inertia
    const Eigen::Vector2d n(-g.tangent(1, k), g.tangent(0, k));
    double F = 0;  // along n, on each of the two stations [N]
    if (m.drag_factor[k] != 0) {
      if (profile) current.x() = m.CurrentAt(0.5 * (g.elevation[k] + g.elevation[k + 1]));
      const Eigen::Vector2d rel = 0.5 * (v.col(k) + v.col(k + 1) - sea.velocity.col(k) -
                                         sea.velocity.col(k + 1)) -
                                  current;
      const double q = rel.dot(n);  // q_{k+1/2} [m/s]
      F += -0.5 * psi * m.drag_factor[k] * q * std::abs(q);
    }
    const Eigen::Vector2d A = 0.5 * (sea.acceleration.col(k) + sea.acceleration.col(k + 1));
    F += 0.5 * psi * m.link_fluid_mass[k] * A.dot(n);
    force.col(k) += F * n;
    force.col(k + 1) += F * n;
  }
  for (int j = 0; j <= m.links; ++j)
    force(1, j) -= m.net_weight[j] + (1.0 - sea.wet[j]) * m.station_buoyancy[j];
  for (int j : m.weight_stations) {
    const double phi = sea.wet[j];
    if (phi == 0) continue;
    if (profile) current.x() = m.CurrentAt(g.elevation[j]);
    const Eigen::Vector2d rel = v.col(j) - current - sea.velocity.col(j);
    const double u = rel.norm();
    force.col(j) += phi * (m.prism_fluid_mass.col(j).cwiseProduct(sea.acceleration.col(j)) -
                           u * m.prism_drag.col(j).cwiseProduct(rel));
  }
}

Eigen::Matrix2d WaveStationInertia(const CableModel& m, const LinkGeometry& g, int j) {
  const bool sea = g.sea.wet.size() == m.stations();
  const double phi = sea ? g.sea.wet[j] : 1.0;
  Eigen::Matrix2d M =
      Eigen::Vector2d(m.cable_mass[j] + m.prism_mass(0, j) - (1.0 - phi) * m.prism_added_mass(0, j),
                      m.cable_mass[j] + m.prism_mass(1, j) - (1.0 - phi) * m.prism_added_mass(1, j))
          .asDiagonal();
  for (int k = j - 1; k <= j; ++k) {
    if (k < 0 || k >= m.links) continue;
    const double psi = sea ? LinkWet(g.sea, k) : 1.0;
    const Eigen::Vector2d n(-g.tangent(1, k), g.tangent(0, k));
    M.noalias() += (0.5 * psi * m.virtual_mass[k]) * n * n.transpose();
  }
  return M;
}

void AddWaveForceJacobian(const CableModel& m, const LinkGeometry& g, const Eigen::Matrix2Xd& v,
                          double kv, BlockTridiagonal& system) {
  const SeaState& sea = g.sea;
  CheckSea(m, sea);
  const bool profile = !m.current_profile.empty();
  Eigen::Vector2d current(m.current, 0.0);
  for (int k = 0; k < m.links; ++k) {
    const double L = g.length[k];
    const double psi = LinkWet(sea, k);
    const Eigen::Vector2d dpsi_a = 0.5 * sea.wet_gradient.col(k);
    const Eigen::Vector2d dpsi_c = 0.5 * sea.wet_gradient.col(k + 1);
    if (!(L > 0) || (psi == 0 && dpsi_a.isZero() && dpsi_c.isZero())) continue;
    const Eigen::Vector2d t = g.tangent.col(k);
    const Eigen::Vector2d n(-t.y(), t.x());
    const Eigen::Matrix2d dn = NormalDerivative(t, L);
    // The same force F n on both stations; its derivatives with respect to d = x_{k+1} - x_k
    // (orientation), to x_k and x_{k+1} (the water, the current, the wet fraction), and to
    // either station's velocity.
    Eigen::Matrix2d Hd = Eigen::Matrix2d::Zero(), Ja = Eigen::Matrix2d::Zero(),
                    Jc = Eigen::Matrix2d::Zero(), Jv = Eigen::Matrix2d::Zero();
    double F_dry = 0;  // F / psi: the force along n of the link all wet
    if (m.drag_factor[k] != 0) {
      const double ymid = 0.5 * (g.elevation[k] + g.elevation[k + 1]);
      if (profile) current.x() = m.CurrentAt(ymid);
      const Eigen::Vector2d w = 0.5 * (v.col(k) + v.col(k + 1) - sea.velocity.col(k) -
                                       sea.velocity.col(k + 1)) -
                                current;
      const double q = w.dot(n), f = m.drag_factor[k];
      F_dry += -0.5 * f * q * std::abs(q);
      Hd += -0.5 * psi * f * (2.0 * std::abs(q) * n * (w.transpose() * dn) + q * std::abs(q) * dn);
      Jv = -0.5 * psi * f * std::abs(q) * n * n.transpose();  // d(F n)/dv of either station
      // w = mean v - c(y_mid) e_x - (U_k + U_{k+1}) / 2: d(F n)/dx_i = 2 Jv dw/dx_i.
      Ja -= Jv * Gradient(sea.velocity_gradient, k);
      Jc -= Jv * Gradient(sea.velocity_gradient, k + 1);
      const double slope = profile ? m.CurrentSlope(ymid) : 0.0;
      if (slope != 0) {
        Ja.col(1) -= slope * Jv.col(0);
        Jc.col(1) -= slope * Jv.col(0);
      }
    }
    if (m.link_fluid_mass[k] != 0) {
      const double M = 0.5 * m.link_fluid_mass[k];
      const Eigen::Vector2d A = 0.5 * (sea.acceleration.col(k) + sea.acceleration.col(k + 1));
      F_dry += M * A.dot(n);
      Hd += psi * M * (n * (A.transpose() * dn) + A.dot(n) * dn);
      const Eigen::Matrix2d nn = (0.5 * psi * M) * n * n.transpose();
      Ja += nn * Gradient(sea.acceleration_gradient, k);
      Jc += nn * Gradient(sea.acceleration_gradient, k + 1);
    }
    // Through the wet fraction psi = (phi_k + phi_{k+1}) / 2.
    Ja += (F_dry * n) * dpsi_a.transpose();
    Jc += (F_dry * n) * dpsi_c.transpose();
    Ja -= Hd;
    Jc += Hd;
    // Stored negated, with dv/dx = kv.
    for (int row : {k, k + 1}) {
      AddBlock(m, row, k, -(Ja + kv * Jv), system);
      AddBlock(m, row, k + 1, -(Jc + kv * Jv), system);
    }
  }
  // Buoyancy lost above the surface: F_y = -(1 - phi_j) B_j, dF_y/dx_j = B_j grad phi_j.
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    if (m.station_buoyancy[j] == 0) continue;
    Eigen::Matrix2d B = Eigen::Matrix2d::Zero();
    B.row(1) = -m.station_buoyancy[j] * sea.wet_gradient.col(j).transpose();
    AddBlock(m, j, j, B, system);
  }
  for (int j : m.weight_stations) {
    if (m.prescribed(j)) continue;
    const double phi = sea.wet[j];
    const Eigen::Vector2d dphi = sea.wet_gradient.col(j);
    if (phi == 0 && dphi.isZero()) continue;
    if (profile) current.x() = m.CurrentAt(g.elevation[j]);
    const Eigen::Vector2d rel = v.col(j) - current - sea.velocity.col(j);
    const double u = rel.norm();
    const Eigen::Vector2d f = m.prism_drag.col(j), P = m.prism_fluid_mass.col(j);
    const Eigen::Vector2d F_wet = P.cwiseProduct(sea.acceleration.col(j)) - u * f.cwiseProduct(rel);
    Eigen::Matrix2d dfdv = Eigen::Matrix2d::Zero();
    if (u > 0) dfdv = -(f.asDiagonal() * (u * Eigen::Matrix2d::Identity() + rel * rel.transpose() / u));
    // rel depends on x_j through -U(x_j) and -c(y_j) e_x.
    Eigen::Matrix2d drel_dx = -Gradient(sea.velocity_gradient, j);
    const double slope = profile ? m.CurrentSlope(g.elevation[j]) : 0.0;
    drel_dx(0, 1) -= slope;
    const Eigen::Matrix2d Jx = phi * (dfdv * drel_dx +
                                      P.asDiagonal() * Gradient(sea.acceleration_gradient, j)) +
                               F_wet * dphi.transpose();
    AddBlock(m, j, j, -(Jx + kv * phi * dfdv), system);
  }
}

void AddWaveInertiaJacobian(const CableModel& m, const LinkGeometry& g, const Eigen::Matrix2Xd& a,
                            BlockTridiagonal& system) {
  const SeaState& sea = g.sea;
  CheckSea(m, sea);
  // Prisms: (1 - phi) rho V less inertia: d/dx_j of phi rho V (.) a_j = (rho V (.) a_j) grad^T.
  for (int j : m.weight_stations) {
    if (m.prescribed(j)) continue;
    const Eigen::Vector2d Pa = m.prism_added_mass.col(j).cwiseProduct(a.col(j));
    AddBlock(m, j, j, Pa * sea.wet_gradient.col(j).transpose(), system);
  }
  // Links: (psi e / 2) n n^T a_j on stations j = k, k+1, psi = (phi_k + phi_{k+1}) / 2.
  for (int k = 0; k < m.links; ++k) {
    if (m.virtual_mass[k] == 0) continue;
    const Eigen::Vector2d n(-g.tangent(1, k), g.tangent(0, k));
    const double e = 0.5 * m.virtual_mass[k];
    for (int j : {k, k + 1}) {
      const Eigen::Vector2d f = (e * n.dot(a.col(j))) * n;
      AddBlock(m, j, k, f * (0.5 * sea.wet_gradient.col(k)).transpose(), system);
      AddBlock(m, j, k + 1, f * (0.5 * sea.wet_gradient.col(k + 1)).transpose(), system);
    }
  }
}

}  // namespace cablefilm
