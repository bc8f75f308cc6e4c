// The water's force on an inclined straight line held still in a regular Airy wave, against
// Morison's equation written out here: at every station, the part across the line (normal drag,
// Froude-Krylov and normal added mass) and the part along it (tangential drag, Froude-Krylov
// and tangential added mass, MoorDyn's rho V (1 + CaAx) on the water's acceleration along the
// line), from the Airy velocity and acceleration computed here with cosh and sinh at each
// station's position and a wave number found by bisection. The Froude-Krylov part along the
// line is on by default and a material can leave it out (the force along the line is then the
// added mass's alone); the three kinematics give the plain Airy formulas deep under the waves
// (Wheeler's at its stretched elevation).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/forces.h"
#include "core/inputs.h"
#include "core/line_model.h"
#include "core/waves.h"

namespace cablefilm {
namespace {

constexpr double kG = 9.80665;     // [m/s^2]
constexpr double kRho = 1025.0;    // [kg/m^3]
constexpr double kPi = 3.14159265358979323846;

// The wave: H = 3 m, T = 9 s in h = 60 m (L = 125 m, k h = 3.0), travelling 30 deg off +x
// towards +z (so that the line, inclined in 3D, meets it obliquely), phase 0.7 rad, no ramp.
constexpr double kH = 3.0, kT = 9.0, kDepth = 60.0, kHeading = kPi / 6, kPhase = 0.7;

// The line: 40 m in 40 links from (4, -44, -3) m along (0.8, 0.45, 0.3) (its top 26 m under the
// still water level: every station wholly wet), a 0.12 m rope of section pi d^2 / 4, with
// tangential coefficients of their own (C^T = 0.4, k^t = 0.5) so that every term along the line
// is there and none equals a term across it.
constexpr int kLinks = 40;
constexpr double kLength = 40.0, kDiameter = 0.12;
constexpr double kCd = 1.2, kCa = 1.0, kCdAx = 0.4, kCaAx = 0.5;
const double kArea = kPi * kDiameter * kDiameter / 4;  // sigma [m^2]

// k [1/m] of omega^2 = g k tanh(k h) by bisection on x tanh x = omega^2 h / g alone.
double BisectWaveNumber(double omega, double h) {
  const double y = omega * omega * h / kG;
  double lo = 0, hi = std::max(1.0, y) + 1.0;
  for (int i = 0; i < 400; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid * std::tanh(mid) < y ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi) / h;
}

// The Airy water velocity U [m/s] and acceleration A [m/s^2] at a point, R = 1:
//   u = a omega cosh(k (z_e + h)) / sinh(k h) cos(theta) along e,
//   w = a omega sinh(k (z_e + h)) / sinh(k h) sin(theta) up, A = dU/dt,
// theta = k e . x - omega t + phase, z_e the elevation the kinematics use: the point's own
// (linear, extrapolated: every station is below the still water level) or Wheeler's stretched
// z_s = h (z - eta) / (h + eta), eta = a cos(theta).
struct HandAiry {
  double a, omega, k, h;
  Vec e;  // the heading's horizontal unit vector
  void At(const Vec& p, double t, WaveKinematics kinematics, Vec* U, Vec* A) const {
    const double theta = k * (e.x() * p.x() + e.z() * p.z()) - omega * t + kPhase;
    const double eta = a * std::cos(theta), z = p.y();
    const double ze = kinematics == WaveKinematics::kWheeler ? h * (z - eta) / (h + eta) : z;
    const double C = std::cosh(k * (ze + h)) / std::sinh(k * h);
    const double S = std::sinh(k * (ze + h)) / std::sinh(k * h);
    const Vec up(0, 1, 0);
    *U = a * omega * (C * std::cos(theta) * e + S * std::sin(theta) * up);
    *A = a * omega * omega * (C * std::sin(theta) * e - S * std::cos(theta) * up);
  }
};

LineModel HeldLine(WaveKinematics kinematics, bool axial_froude_krylov, const Vec& x0,
                   const Vec& x1) {
  SectionSpec s;
  s.length = kLength;
  s.segments = kLinks;
  s.diameter = kDiameter;
  s.area = kArea;
  s.mass_per_length = 40.0;     // [kg/m]
  s.youngs_modulus = 2e11;      // [Pa]
  s.drag_coefficient = kCd;
  s.added_mass_coefficient = kCa;
  s.tangential_drag_coefficient = kCdAx;
  s.tangential_added_mass_coefficient = kCaAx;
  s.axial_froude_krylov = axial_froude_krylov;
  EnvironmentSpec env;
  env.fluid_density = kRho;
  env.waves.present = true;
  env.waves.height = kH;
  env.waves.period = kT;
  env.waves.depth = kDepth;
  env.waves.phase = kPhase;
  env.waves.heading = kHeading;
  env.waves.ramp_rate = 0;  // R = 1
  env.waves.kinematics = kinematics;
  return MakeLineModel({s}, {}, env, EndMotion::Fixed(x0), EndMotion::Fixed(x1),
                       LinkLaw::kElastic);
}

// The water's force on each station [N] (weight and buoyancy taken out), the line at rest at x.
Points FluidForces(const LineModel& m, const Points& x, double t) {
  ForceWorkspace ws(m.line.links);
  const Water water = SceneWater(m);
  ComputeGeometry(m, water, t, x, ws.geometry);
  for (int j = 0; j <= m.line.links; ++j)
    EXPECT_EQ(ws.geometry.sea.wet[j], 1.0) << "station " << j << " not wholly wet";
  Points f = Points::Zero(kDim, m.stations());
  AddExternalForces(m, water, ws.geometry, Points::Zero(kDim, m.stations()), f);
  f.row(kVertical) += m.line.net_weight.transpose();  // AddExternalForces' -W_j, under water
  return f;
}

struct HeldGeometry {
  Vec x0, t;  // the held end and the unit tangent
  Points x;   // the stations, at their rest spacing
};

HeldGeometry Inclined() {
  HeldGeometry line;
  line.x0 = Vec(4.0, -44.0, -3.0);
  line.t = Vec(0.8, 0.45, 0.3).normalized();
  line.x.resize(kDim, kLinks + 1);
  for (int j = 0; j <= kLinks; ++j) line.x.col(j) = line.x0 + (kLength * j / kLinks) * line.t;
  return line;
}

// Morison's force per unit length [N/m] on a still line of tangent t in water of velocity U and
// acceleration A: normal drag rho/2 C^D d |P U| P U, tangential drag rho/2 C^T pi d |t.U| (t.U) t,
// across rho sigma (1 + k) P A, along rho sigma (fk + k^t) (t.A) t (fk = 1 with the Froude-Krylov
// part along the line, 0 without), P = I - t t^T.
Vec Morison(const Vec& t, const Vec& U, const Vec& A, double fk) {
  const Vec Un = U - t * t.dot(U), An = A - t * t.dot(A);
  const double Ut = t.dot(U), At = t.dot(A);
  return 0.5 * kRho * kCd * kDiameter * Un.norm() * Un +
         0.5 * kRho * kCdAx * kPi * kDiameter * std::abs(Ut) * Ut * t +
         kRho * kArea * (1 + kCa) * An + kRho * kArea * (fk + kCaAx) * At * t;
}

const char* Name(WaveKinematics k) {
  return k == WaveKinematics::kWheeler ? "wheeler"
         : k == WaveKinematics::kLinear ? "linear"
                                        : "extrapolated";
}

// At every station, across and along the line: (1) the lumped force (each link's Morison force
// on the mean of its two stations' water, l long, half to each station) to round-off; (2) the
// continuous Morison force per unit length at the station's own position times its share of
// line, to the lumping's order.
TEST(WaveMorison, HeldInclinedLineMatchesMorisonAtEveryStation) {
  const HeldGeometry line = Inclined();
  const double omega = 2 * kPi / kT, k = BisectWaveNumber(omega, kDepth);
  const HandAiry airy{0.5 * kH, omega, k, kDepth, Vec(std::cos(kHeading), 0, std::sin(kHeading))};
  const double l = kLength / kLinks, kl = k * l;  // [m], [1]: k l = 0.050
  const Vec& t = line.t;
  for (WaveKinematics kin :
       {WaveKinematics::kWheeler, WaveKinematics::kLinear, WaveKinematics::kExtrapolated}) {
    const LineModel m = HeldLine(kin, true, line.x0, line.x.col(kLinks));
    ASSERT_NEAR(m.env.wave.k, k, 1e-12 * k);
    // At each time: the forces, the lumped closed form and the continuous one at the stations.
    constexpr int kTimes = 3;
    const double times[kTimes] = {0.0, 2.3, 6.1};  // [s]
    Points f[kTimes], lumped[kTimes], continuous[kTimes];
    for (int i = 0; i < kTimes; ++i) {
      f[i] = FluidForces(m, line.x, times[i]);
      Points U(kDim, kLinks + 1), A(kDim, kLinks + 1);
      for (int j = 0; j <= kLinks; ++j) {
        Vec u, a;
        airy.At(line.x.col(j), times[i], kin, &u, &a);
        U.col(j) = u;
        A.col(j) = a;
      }
      lumped[i] = Points::Zero(kDim, kLinks + 1);
      continuous[i].resize(kDim, kLinks + 1);
      for (int link = 0; link < kLinks; ++link) {
        const Vec F = 0.5 * l *
                      Morison(t, 0.5 * (U.col(link) + U.col(link + 1)),
                              0.5 * (A.col(link) + A.col(link + 1)), 1.0);
        lumped[i].col(link) += F;
        lumped[i].col(link + 1) += F;
      }
      for (int j = 0; j <= kLinks; ++j) {
        const double share = (j == 0 || j == kLinks) ? 0.5 * l : l;  // [m]
        continuous[i].col(j) = share * Morison(t, U.col(j), A.col(j), 1.0);
      }
    }
    // Each component on its own scale: the largest over the stations and the times.
    double scale_n = 0, scale_t = 0;
    for (int i = 0; i < kTimes; ++i)
      for (int j = 0; j <= kLinks; ++j) {
        const Vec F = lumped[i].col(j);
        scale_n = std::max(scale_n, (F - t * t.dot(F)).norm());
        scale_t = std::max(scale_t, std::abs(t.dot(F)));
      }
    ASSERT_GT(scale_t, 0.2 * scale_n) << "the part along the line is to be tested, not lost";
    double lumped_n = 0, lumped_t = 0, cont_n = 0, cont_t = 0, ends_n = 0, ends_t = 0;
    for (int i = 0; i < kTimes; ++i)
      for (int j = 0; j <= kLinks; ++j) {
        const Vec d = f[i].col(j) - lumped[i].col(j), c = f[i].col(j) - continuous[i].col(j);
        lumped_n = std::max(lumped_n, (d - t * t.dot(d)).norm() / scale_n);
        lumped_t = std::max(lumped_t, std::abs(t.dot(d)) / scale_t);
        const bool end = j == 0 || j == kLinks;
        double& worst_n = end ? ends_n : cont_n;
        double& worst_t = end ? ends_t : cont_t;
        worst_n = std::max(worst_n, (c - t * t.dot(c)).norm() / scale_n);
        worst_t = std::max(worst_t, std::abs(t.dot(c)) / scale_t);
      }
    std::printf("[ morison ] %s: lumped form %.1e across, %.1e along; continuous form at the "
                "stations %.1e across, %.1e along (ends %.1e, %.1e); k l = %.3f\n",
                Name(kin), lumped_n, lumped_t, cont_n, cont_t, ends_n, ends_t, kl);
    // (1) The same sums in another order, cosh and sinh against the exponentials: round-off,
    // 1e-15 of the scale; 1e-12 leaves room, and a missing or doubled term is O(0.1) or more.
    EXPECT_LT(lumped_n, 1e-12) << Name(kin);
    EXPECT_LT(lumped_t, 1e-12) << Name(kin);
    // (2) A link's mean water departs from that at its midpoint by (l^2 / 8) q'' and the mean of
    // two midpoints' forces from the station's by (l^2 / 8) f'': (k l)^2 / 4 of the scale for
    // the terms linear in the water (|q''| <= k^2 |q| along the line in deep water), twice that,
    // (k l)^2 / 2, for the drag, quadratic in it; (k l)^2 leaves a factor 2 (measured: 1.1e-3 =
    // 0.45 (k l)^2). An end station's share is one link whose mean water is l / 2 away: first
    // order, (l / 2)^2 |f'| over the interior's l |f|, k l / 4 for the linear terms and k l / 2
    // for the drag; bound k l (measured: 2.0e-2 = 0.4 k l).
    EXPECT_LT(cont_n, kl * kl) << Name(kin);
    EXPECT_LT(cont_t, kl * kl) << Name(kin);
    EXPECT_LT(ends_n, kl) << Name(kin);
    EXPECT_LT(ends_t, kl) << Name(kin);
  }
}

// The material without the Froude-Krylov force along the line: the part across unchanged, the
// part along the added mass's alone (rho sigma l k^t on the water's acceleration along the
// line), and the difference at each station rho sigma l (t . mean A) / 2 of each of its links.
TEST(WaveMorison, AxialFroudeKrylovLeftOutLeavesTheAddedMassAlone) {
  const HeldGeometry line = Inclined();
  const double omega = 2 * kPi / kT, k = BisectWaveNumber(omega, kDepth);
  const HandAiry airy{0.5 * kH, omega, k, kDepth, Vec(std::cos(kHeading), 0, std::sin(kHeading))};
  const double l = kLength / kLinks;
  const Vec& t = line.t;
  const LineModel on = HeldLine(WaveKinematics::kWheeler, true, line.x0, line.x.col(kLinks));
  const LineModel off = HeldLine(WaveKinematics::kWheeler, false, line.x0, line.x.col(kLinks));
  double across = 0, along = 0, difference = 0;
  for (double time : {0.0, 2.3, 6.1}) {
    const Points f_on = FluidForces(on, line.x, time), f_off = FluidForces(off, line.x, time);
    Points U(kDim, kLinks + 1), A(kDim, kLinks + 1);
    for (int j = 0; j <= kLinks; ++j) {
      Vec u, a;
      airy.At(line.x.col(j), time, WaveKinematics::kWheeler, &u, &a);
      U.col(j) = u;
      A.col(j) = a;
    }
    Points lumped = Points::Zero(kDim, kLinks + 1), fk = Points::Zero(kDim, kLinks + 1);
    for (int i = 0; i < kLinks; ++i) {
      const Vec Um = 0.5 * (U.col(i) + U.col(i + 1)), Am = 0.5 * (A.col(i) + A.col(i + 1));
      const Vec F = 0.5 * l * Morison(t, Um, Am, 0.0);
      const Vec G = 0.5 * kRho * kArea * l * t.dot(Am) * t;  // [N]: half the link's
      for (int j : {i, i + 1}) {
        lumped.col(j) += F;
        fk.col(j) += G;
      }
    }
    double scale_n = 0, scale_t = 0, scale_fk = 0;
    for (int j = 0; j <= kLinks; ++j) {
      scale_n = std::max(scale_n, (f_on.col(j) - t * t.dot(f_on.col(j))).norm());
      scale_t = std::max(scale_t, std::abs(t.dot(lumped.col(j))));
      scale_fk = std::max(scale_fk, fk.col(j).norm());
    }
    for (int j = 0; j <= kLinks; ++j) {
      const Vec d = f_on.col(j) - f_off.col(j);
      across = std::max(across, (d - t * t.dot(d)).norm() / scale_n);
      along = std::max(along, std::abs(t.dot(f_off.col(j) - lumped.col(j))) / scale_t);
      difference = std::max(difference, (d - fk.col(j)).norm() / scale_fk);
    }
  }
  std::printf("[ morison ] without the axial Froude-Krylov part: across %.1e, along %.1e of "
              "the closed form, the difference %.1e of rho sigma l (t . A)\n",
              across, along, difference);
  // Round-off: the same sums, one term fewer (see the test above).
  EXPECT_LT(across, 1e-12);
  EXPECT_LT(along, 1e-12);
  EXPECT_LT(difference, 1e-12);
}

}  // namespace
}  // namespace cablefilm
