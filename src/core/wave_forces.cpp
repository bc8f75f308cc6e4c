#include "core/wave_forces.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/sea_components.h"

namespace cablefilm {
namespace {

Eigen::Map<const Mat> Gradient(const Gradients& g, int j) {
  return Eigen::Map<const Mat>(g.col(j).data());
}

void CheckSea(const LineModel& m, const SeaState& sea) {
  if (sea.wet.size() != m.stations())
    throw Error("internal: the forces in waves were asked for without the sea's state "
                "(ComputeGeometry with the model and the time)");
}

// Adds the block B to the (row j, column i) block of the free stations' system.
void AddBlock(const LineModel& m, int j, int i, const Mat& B, BlockTridiagonal& s) {
  const int j0 = m.first_free(), j1 = m.last_free();
  if (j < j0 || j > j1 || i < j0 || i > j1) return;
  if (i == j) s.diag[j - j0] += B;
  else if (i == j + 1) s.upper[j - j0] += B;
  else s.lower[j - j0] += B;
}

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

double SurfaceBuoyancyEnergy(const LineModel& m, const Points& x) {
  if (!m.has_waves()) return 0.0;
  // G(u) = int_0^u phi: 0 below the band, u^3 - u^4 / 2 across it, u - 1/2 beyond.
  auto G = [](double u) {
    if (u <= 0) return 0.0;
    if (u >= 1) return u - 0.5;
    return u * u * u * (1.0 - 0.5 * u);
  };
  double e = 0;
  for (int j = 0; j < m.stations(); ++j) {
    const double band = m.line.wet_band[j];
    if (m.line.station_buoyancy[j] == 0 || !(band > 0)) continue;
    const double u = (m.env.wave.spec.surface_y - x(kVertical, j)) / band + 0.5;
    // Under water (u >= 1) y + l G(u) = y_surface: the same at every depth.
    e += m.line.station_buoyancy[j] * (x(kVertical, j) + band * G(u));
  }
  return e;
}

namespace {

// Station j's wet fraction and its gradient from the surface's elevation eta [m] above the
// still water level there and its gradient `ddepth` (d eta / d position; y set here).
void SetWetFraction(const LineModel& m, const Wave& wave, const Points& x, int j, double eta,
                    Vec ddepth, SeaState& sea) {
  // Depth below the instantaneous surface over the station's band: u = 1/2 at the surface.
  const double band = m.line.wet_band[j];
  const double depth = wave.spec.surface_y + eta - x(kVertical, j);
  const double u = depth / band + 0.5;
  sea.wet[j] = WetFraction(u);
  ddepth[kVertical] = -1.0;
  sea.wet_gradient.col(j) = (WetFractionSlope(u) / band) * ddepth;
}

// An irregular sea: its sum over every component costs N trigonometric and exponential
// evaluations a station, so each station's kinematics are evaluated exactly at a base (t_0,
// x_0) of its own and carried from it by Taylor's first order while its time and position stay
// within the sea's reach (Wave::sea_reach) over the highest frequency and wave number summed
// there: U + A dt + G_u dx, A + J dt + G_a dx, eta + eta' dt + grad eta . dx, the gradients the
// base's. Within a step's Newton iterations (one time, positions moving by corrections) and an
// explicit window's steps (each a fraction of a millisecond) a base serves many evaluations,
// and a deep station, whose short components the depth has taken out (Wave::sea_cutoff), is
// carried longer than one near the surface.
void ComputeIrregularSea(const LineModel& m, const Wave& wave, double t, const Points& x,
                         SeaState& sea) {
  const int n = m.stations();
  const double reach = wave.sea_reach;
  const bool valid = sea.base_valid && sea.base_scale == wave.sea_scale && sea.base_x.cols() == n;
  // Each station's base, made anew where the station is out of its reach.
  if (sea.base_x.cols() != n) {
    sea.base_x.resize(kDim, n);
    sea.base_velocity.resize(kDim, n);
    sea.base_acceleration.resize(kDim, n);
    sea.base_jerk.resize(kDim, n);
    sea.base_eta_gradient.resize(kDim, n);
    sea.base_velocity_gradient.resize(kDim * kDim, n);
    sea.base_acceleration_gradient.resize(kDim * kDim, n);
    sea.base_eta.resize(n);
    sea.base_eta_rate.resize(n);
    sea.base_t.resize(n);
    sea.base_reach_t.resize(n);
    sea.base_reach_x.resize(n);
  }
  WaveRamp ramp;
  bool ramped = false;  // the ramp at t, found for the first station evaluated
  for (int j = 0; j < n; ++j) {
    if (valid && std::abs(t - sea.base_t[j]) <= sea.base_reach_t[j] &&
        (x.col(j) - sea.base_x.col(j)).norm() <= sea.base_reach_x[j])
      continue;  // carried
    if (!ramped) {
      ramp = RampAt(wave.spec, t);
      ramped = true;
    }
    const WaterKinematics w = KinematicsAt(wave, x.col(j), t, ramp);
    sea.base_velocity.col(j) = w.velocity;
    sea.base_acceleration.col(j) = w.acceleration;
    sea.base_jerk.col(j) = w.jerk;
    Eigen::Map<Mat>(sea.base_velocity_gradient.col(j).data()) = w.velocity_gradient;
    Eigen::Map<Mat>(sea.base_acceleration_gradient.col(j).data()) = w.acceleration_gradient;
    sea.base_eta[j] = w.eta;
    sea.base_eta_rate[j] = w.eta_rate;
    sea.base_eta_gradient.col(j) = w.eta_gradient;
    sea.base_x.col(j) = x.col(j);
    sea.base_t[j] = t;
    // Without a component summed (none: too deep for all), the whole sea's highest.
    sea.base_reach_t[j] = reach / (w.omega_max > 0 ? w.omega_max : wave.sea->max_omega);
    sea.base_reach_x[j] = reach / (w.k_max > 0 ? w.k_max : wave.sea->max_k);
    ++sea.exact_evaluations;
  }
  sea.base_scale = wave.sea_scale;
  sea.base_valid = true;
  sea.velocity_gradient = sea.base_velocity_gradient;
  sea.acceleration_gradient = sea.base_acceleration_gradient;
  for (int j = 0; j < n; ++j) {
    const double dt = t - sea.base_t[j];          // [s]
    const Vec dx = x.col(j) - sea.base_x.col(j);  // [m]
    const Eigen::Map<const Mat> Gu(sea.base_velocity_gradient.col(j).data());
    const Eigen::Map<const Mat> Ga(sea.base_acceleration_gradient.col(j).data());
    sea.velocity.col(j) = sea.base_velocity.col(j) + sea.base_acceleration.col(j) * dt + Gu * dx;
    sea.acceleration.col(j) = sea.base_acceleration.col(j) + sea.base_jerk.col(j) * dt + Ga * dx;
    const Vec grad = sea.base_eta_gradient.col(j);
    const double eta = sea.base_eta[j] + sea.base_eta_rate[j] * dt + grad.dot(dx);
    SetWetFraction(m, wave, x, j, eta, grad, sea);
  }
}

}  // namespace

void ComputeSea(const LineModel& m, const Water& water, double t, const Points& x, SeaState& sea) {
  const int n = m.stations();
  if (sea.wet.size() != n) {
    sea.velocity.resize(kDim, n);
    sea.acceleration.resize(kDim, n);
    sea.velocity_gradient.resize(kDim * kDim, n);
    sea.acceleration_gradient.resize(kDim * kDim, n);
    sea.wet.resize(n);
    sea.wet_gradient.resize(kDim, n);
    sea.still = sea.still_under = false;  // nothing in them yet
  }
  sea.t = t;
  const Wave& wave = water.wave;
  const bool still = wave.amplitude == 0;
  if (still) {
    // The water at rest: KinematicsAt's zeros, set once rather than computed (with its
    // trigonometry) at every station.
    if (!sea.still) {
      sea.velocity.setZero();
      sea.acceleration.setZero();
      sea.velocity_gradient.setZero();
      sea.acceleration_gradient.setZero();
      sea.still = true;
    }
    bool under = true;  // is every station's band under the surface?
    for (int j = 0; j < n && under; ++j)
      under = wave.spec.surface_y - x(kVertical, j) >= 0.5 * m.line.wet_band[j];
    if (under) {
      if (!sea.still_under) {  // the wet fractions as the loop below would find them
        sea.wet.setOnes();
        sea.wet_gradient.setZero();
        sea.still_under = true;
      }
      return;
    }
  }
  sea.still = still;
  sea.still_under = false;
  if (!still && wave.irregular()) {
    ComputeIrregularSea(m, wave, t, x, sea);
    return;
  }
  const WaveRamp ramp = RampAt(wave.spec, t);
  for (int j = 0; j < n; ++j) {
    double eta = 0;
    Vec ddepth = Vec::Zero();  // d depth / d position
    if (!still) {
      const WaterKinematics w = KinematicsAt(wave, x.col(j), t, ramp);
      sea.velocity.col(j) = w.velocity;
      sea.acceleration.col(j) = w.acceleration;
      Eigen::Map<Mat>(sea.velocity_gradient.col(j).data()) = w.velocity_gradient;
      Eigen::Map<Mat>(sea.acceleration_gradient.col(j).data()) = w.acceleration_gradient;
      eta = w.eta;
      ddepth = w.eta_gradient;
    }
    SetWetFraction(m, wave, x, j, eta, ddepth, sea);
  }
}

void AddWaveExternalForces(const LineModel& m, const Water& water, const LinkGeometry& g,
                           const Points& v, Points& force) {
  const SeaState& sea = g.sea;
  CheckSea(m, sea);
  const bool profile = !m.env.current_profile.empty();
  Vec current = CurrentAt(m, water, 0.0);
  for (int k = 0; k < m.line.links; ++k) {
    const double psi = LinkWet(sea, k);
    if (psi == 0) continue;  // in the air: no drag, no fluid inertia
    const Vec t = g.tangent.col(k);
    Vec F = Vec::Zero();  // on each of the link's two stations [N]
    const double f = m.line.drag_factor[k], ft = m.line.tangential_drag_factor[k];
    if (f != 0 || ft != 0) {
      if (profile) current = CurrentAt(m, water, 0.5 * (g.elevation[k] + g.elevation[k + 1]));
      const Vec rel = 0.5 * (v.col(k) + v.col(k + 1) - sea.velocity.col(k) -
                             sea.velocity.col(k + 1)) -
                      current;
      if (f != 0) {
        const Vec q = rel - t * t.dot(rel);  // q_{k+1/2} [m/s]
        F += (-0.5 * psi * f * q.norm()) * q;
      }
      if (ft != 0) {  // along the link: -f^T |p| p t, p = t . rel [m/s]
        const double p = t.dot(rel);
        F += (-0.5 * psi * ft * std::abs(p) * p) * t;
      }
    }
    if (!sea.still) {  // the water's acceleration A (none in still water)
      const Vec A = 0.5 * (sea.acceleration.col(k) + sea.acceleration.col(k + 1));
      F += (0.5 * psi * m.line.link_fluid_mass[k]) * (A - t * t.dot(A));
      // Along the link Froude-Krylov rho sigma l plus the tangential added mass e^t on the
      // water's acceleration along it (MoorDyn's 1 + CaAx; e^t alone without the axial
      // Froude-Krylov part: see model.md, Waves).
      if (m.line.link_axial_fluid_mass[k] != 0)
        F += (0.5 * psi * m.line.link_axial_fluid_mass[k] * t.dot(A)) * t;
    }
    force.col(k) += F;
    force.col(k + 1) += F;
  }
  for (int j = 0; j <= m.line.links; ++j)
    force(kVertical, j) -= m.line.net_weight[j] + (1.0 - sea.wet[j]) * m.line.station_buoyancy[j];
  for (int j : m.line.weight_stations) {
    force.col(j) += m.line.prism_force.col(j);
    const double phi = sea.wet[j];
    if (phi == 0) continue;
    if (profile) current = CurrentAt(m, water, g.elevation[j]);
    const Vec rel = v.col(j) - current - sea.velocity.col(j);
    const double u = rel.norm();
    force.col(j) += phi * (m.line.prism_fluid_mass.col(j).cwiseProduct(sea.acceleration.col(j)) -
                           u * m.line.prism_drag.col(j).cwiseProduct(rel));
  }
}

void AddWaveForceJacobian(const LineModel& m, const Water& water, const LinkGeometry& g,
                          const Points& v, double kv, BlockTridiagonal& system) {
  const SeaState& sea = g.sea;
  CheckSea(m, sea);
  const bool profile = !m.env.current_profile.empty();
  Vec current = CurrentAt(m, water, 0.0);
  for (int k = 0; k < m.line.links; ++k) {
    const double L = g.length[k];
    const double psi = LinkWet(sea, k);
    const Vec dpsi_a = 0.5 * sea.wet_gradient.col(k);
    const Vec dpsi_c = 0.5 * sea.wet_gradient.col(k + 1);
    if (!(L > 0) || (psi == 0 && dpsi_a.isZero() && dpsi_c.isZero())) continue;
    const Vec t = g.tangent.col(k);
    const Mat P = Mat::Identity() - t * t.transpose();
    // The same force F on both stations; its derivatives with respect to d = x_{k+1} - x_k
    // (orientation), to x_k and x_{k+1} (the water, the current, the wet fraction), and to
    // either station's velocity.
    Mat Hd = Mat::Zero(), Ja = Mat::Zero(), Jc = Mat::Zero(), Jv = Mat::Zero();
    Vec F_dry = Vec::Zero();  // F / psi: the force of the link all wet
    const double f = m.line.drag_factor[k], ft = m.line.tangential_drag_factor[k];
    if (f != 0 || ft != 0) {
      const double ymid = 0.5 * (g.elevation[k] + g.elevation[k + 1]);
      if (profile) current = CurrentAt(m, water, ymid);
      const Vec w = 0.5 * (v.col(k) + v.col(k + 1) - sea.velocity.col(k) -
                           sea.velocity.col(k + 1)) -
                    current;
      const Vec q = w - t * t.dot(w);
      if (f != 0) {
        const Mat G = NormalDragDerivative(q);  // d(|q| q) / dq
        F_dry += (-0.5 * f * q.norm()) * q;
        Hd += (-0.5 * psi * f) * G * NormalPartDerivative(t, L, w, q);
        Jv = (-0.25 * psi * f) * G * P;  // dF/dv of either station (dq/dv = P / 2)
      }
      if (ft != 0) {
        // -(f^T / 2) |p| p t, p = t . w: d/dd = -(f^T / 2) |p| (2 t q^T + p P) / L, d/dv of
        // either station -(f^T / 2) |p| t t^T (dp/dv = t^T / 2).
        const double p = t.dot(w), c = -0.5 * ft * std::abs(p);  // [m/s], [kg/s]
        F_dry += (c * p) * t;
        Hd += (psi / L) * ((2.0 * c) * t * q.transpose() + (c * p) * P);
        Jv += (psi * c) * (Mat::Identity() - P);
      }
      // w = mean v - c(y_mid) - (U_k + U_{k+1}) / 2: dF/dx_i = 2 Jv dw/dx_i (0 in still
      // water).
      if (!sea.still) {
        Ja -= Jv * Gradient(sea.velocity_gradient, k);
        Jc -= Jv * Gradient(sea.velocity_gradient, k + 1);
      }
      const Vec slope = profile ? CurrentSlope(m, water, ymid) : Vec::Zero();
      if (!slope.isZero()) {
        Ja.col(kVertical) -= Jv * slope;
        Jc.col(kVertical) -= Jv * slope;
      }
    }
    // The water's acceleration A: none in still water.
    if (m.line.link_fluid_mass[k] != 0 && !sea.still) {
      const double M = 0.5 * m.line.link_fluid_mass[k];
      const Vec A = 0.5 * (sea.acceleration.col(k) + sea.acceleration.col(k + 1));
      const Vec An = A - t * t.dot(A);
      F_dry += M * An;
      Hd += (psi * M) * NormalPartDerivative(t, L, A, An);
      const Mat across = (0.5 * psi * M) * P;  // dF/dA_i: A is the mean of the two stations'
      Ja += across * Gradient(sea.acceleration_gradient, k);
      Jc += across * Gradient(sea.acceleration_gradient, k + 1);
    }
    if (m.line.link_axial_fluid_mass[k] != 0 && !sea.still) {
      // (M^t / 2) (t . A) t, M^t = rho sigma l (1 + k^t) (or e^t alone): through t, d/dd =
      // (M^t / 2)((t . A) P + t (P A)^T) / L, the negative of the part across's; through A,
      // (M^t / 2) t t^T on each station's half.
      const double Mt = 0.5 * m.line.link_axial_fluid_mass[k];  // [kg]
      const Vec A = 0.5 * (sea.acceleration.col(k) + sea.acceleration.col(k + 1));
      const Vec An = A - t * t.dot(A);
      F_dry += (Mt * t.dot(A)) * t;
      Hd -= (psi * Mt) * NormalPartDerivative(t, L, A, An);
      const Mat along = (0.5 * psi * Mt) * (Mat::Identity() - P);
      Ja += along * Gradient(sea.acceleration_gradient, k);
      Jc += along * Gradient(sea.acceleration_gradient, k + 1);
    }
    // Through the wet fraction psi = (phi_k + phi_{k+1}) / 2.
    Ja += F_dry * dpsi_a.transpose();
    Jc += F_dry * dpsi_c.transpose();
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
    if (m.line.station_buoyancy[j] == 0) continue;
    Mat B = Mat::Zero();
    B.row(kVertical) = -m.line.station_buoyancy[j] * sea.wet_gradient.col(j).transpose();
    AddBlock(m, j, j, B, system);
  }
  for (int j : m.line.weight_stations) {
    if (m.prescribed(j)) continue;
    const double phi = sea.wet[j];
    const Vec dphi = sea.wet_gradient.col(j);
    if (phi == 0 && dphi.isZero()) continue;
    if (profile) current = CurrentAt(m, water, g.elevation[j]);
    const Vec rel = v.col(j) - current - sea.velocity.col(j);
    const double u = rel.norm();
    const Vec f = m.line.prism_drag.col(j), P = m.line.prism_fluid_mass.col(j);
    const Vec F_wet = P.cwiseProduct(sea.acceleration.col(j)) - u * f.cwiseProduct(rel);
    Mat dfdv = Mat::Zero();
    if (u > 0) dfdv = -(f.asDiagonal() * (u * Mat::Identity() + rel * rel.transpose() / u));
    // rel depends on x_j through -U(x_j) and -c(y_j) e_x.
    Mat drel_dx = -Gradient(sea.velocity_gradient, j);
    if (profile) drel_dx.col(kVertical) -= CurrentSlope(m, water, g.elevation[j]);
    const Mat Jx = phi * (dfdv * drel_dx +
                                      P.asDiagonal() * Gradient(sea.acceleration_gradient, j)) +
                               F_wet * dphi.transpose();
    AddBlock(m, j, j, -(Jx + kv * phi * dfdv), system);
  }
}

void AddWaveInertiaJacobian(const LineModel& m, const LinkGeometry& g, const Points& a,
                            BlockTridiagonal& system) {
  const SeaState& sea = g.sea;
  CheckSea(m, sea);
  // Prisms: (1 - phi) rho V less inertia: d/dx_j of phi rho V (.) a_j = (rho V (.) a_j) grad^T.
  for (int j : m.line.weight_stations) {
    if (m.prescribed(j)) continue;
    const Vec Pa = m.line.prism_added_mass.col(j).cwiseProduct(a.col(j));
    AddBlock(m, j, j, Pa * sea.wet_gradient.col(j).transpose(), system);
  }
  // Links: (psi e / 2) (I - t t^T) a_j on stations j = k, k+1, psi = (phi_k + phi_{k+1}) / 2.
  // And the tangential (psi e^t / 2) t t^T a_j.
  for (int k = 0; k < m.line.links; ++k) {
    const double et = 0.5 * m.line.tangential_virtual_mass[k];
    if (m.line.virtual_mass[k] == 0 && et == 0) continue;
    const Vec t = g.tangent.col(k);
    const double e = 0.5 * m.line.virtual_mass[k];
    for (int j : {k, k + 1}) {
      Vec f = e * (a.col(j) - t * t.dot(a.col(j)));
      if (et != 0) f += (et * t.dot(a.col(j))) * t;
      AddBlock(m, j, k, f * (0.5 * sea.wet_gradient.col(k)).transpose(), system);
      AddBlock(m, j, k + 1, f * (0.5 * sea.wet_gradient.col(k + 1)).transpose(), system);
    }
  }
}

}  // namespace cablefilm
