// Where the Airy formulas are evaluated (waves.kinematics): at a point in a crest above the still
// water level each mode gives the values it defines, written out here with cosh and sinh:
// Wheeler's at the stretched elevation, "linear" at the point's own, "extrapolated" the Taylor
// line from the still water level; above the instantaneous surface each holds the surface's
// own; below the still water level "linear" and "extrapolated" are the plain Airy formulas; and
// the gradients the implicit scheme's Jacobian uses match central differences in every mode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "test_support.h"
#include "core/waves.h"

namespace cablefilm {
namespace {

constexpr double kG = 9.80665;  // [m/s^2]

// A steep wave, so that the modes differ by much in a crest: T = 8 s in h = 30 m (L = 95 m,
// k h = 1.98), H = 6 m (H / L = 0.063, Miche's limit 0.14). Along +x, no ramp (R = 1), phase 0.
WaveSpec Steep(WaveKinematics kinematics) {
  WaveSpec w;
  w.present = true;
  w.height = 6.0;
  w.period = 8.0;
  w.depth = 30.0;
  w.ramp_rate = 0;
  w.kinematics = kinematics;
  return w;
}

// Airy at evaluation elevation z_e with profile values C, S (R = 1, along +x):
//   U = a omega (C cos theta, S sin theta), A = a omega^2 (C sin theta, -S cos theta).
struct Expected {
  Vec U, A;
};
Expected AiryWith(double a, double omega, double C, double S, double theta) {
  return {a * omega * Vec(C * std::cos(theta), S * std::sin(theta), 0),
          a * omega * omega * Vec(C * std::sin(theta), -S * std::cos(theta), 0)};
}

// The depth profiles written out: cosh(k (z + h)) / sinh(k h), sinh(k (z + h)) / sinh(k h).
double Ch(double k, double h, double z) { return std::cosh(k * (z + h)) / std::sinh(k * h); }
double Sh(double k, double h, double z) { return std::sinh(k * (z + h)) / std::sinh(k * h); }

// What each mode defines at elevation z (above the still water level) where the surface is at
// eta: z is first held to [-h, eta]; Wheeler evaluates at h (z - eta) / (h + eta), "linear" at
// z, "extrapolated" at z below 0 and C(0) + z k S(0), S(0) + z k C(0) above.
Expected Defined(WaveKinematics kin, double a, double omega, double k, double h, double z,
                 double theta) {
  const double eta = a * std::cos(theta);
  z = std::clamp(z, -h, eta);
  if (kin == WaveKinematics::kWheeler) {
    const double zs = h * (z - eta) / (h + eta);
    return AiryWith(a, omega, Ch(k, h, zs), Sh(k, h, zs), theta);
  }
  if (kin == WaveKinematics::kExtrapolated && z > 0)
    return AiryWith(a, omega, Ch(k, h, 0) + z * k * Sh(k, h, 0), Sh(k, h, 0) + z * k * Ch(k, h, 0),
                    theta);
  return AiryWith(a, omega, Ch(k, h, z), Sh(k, h, z), theta);
}

const WaveKinematics kModes[] = {WaveKinematics::kWheeler, WaveKinematics::kLinear,
                                 WaveKinematics::kExtrapolated};

// Points at phase theta (x = theta / k at t = 0) and elevation z: in a crest half-way up from
// the still water level, 2 m above the crest, above the still water level over a trough (the
// surface below: held at the surface), and below the still water level.
TEST(WaveKinematicsModes, EachModeGivesWhatItDefines) {
  for (WaveKinematics kin : kModes) {
    const Wave wave = MakeWave(Steep(kin), kG);
    const double a = wave.amplitude, w = wave.omega, k = wave.k, h = wave.spec.depth;
    const double scale = a * w * Ch(k, h, 0);  // the surface velocity's amplitude [m/s]
    struct At {
      double theta, z;
    };
    const double crest = a * std::cos(0.4);  // eta at theta = 0.4 [m]
    for (const At& p : {At{0.4, 0.5 * crest}, At{0.0, 0.3 * a}, At{0.4, crest + 2.0},
                        At{2.5, 0.5}, At{2.5, -0.3 * h}, At{1.1, -0.05 * h}, At{5.0, -0.9 * h}}) {
      const WaterKinematics got = KinematicsAt(wave, Vec(p.theta / k, p.z, 0), 0.0);
      const Expected want = Defined(kin, a, w, k, h, p.z, p.theta);
      // The exponential form against cosh and sinh: round-off, 1e-15 of the scale.
      EXPECT_LT((got.velocity - want.U).norm(), 1e-12 * scale)
          << static_cast<int>(kin) << " theta " << p.theta << " z " << p.z;
      EXPECT_LT((got.acceleration - want.A).norm(), 1e-12 * scale * w)
          << static_cast<int>(kin) << " theta " << p.theta << " z " << p.z;
    }
  }
}

// The modes side by side in a crest (theta = 0, z = a / 2 = 1.5 m): linear theory's exponential
// growth above the still water level is above its Taylor line, which is above Wheeler's
// stretched value; below the still water level "linear" and "extrapolated" are the same plain
// formula, exactly.
TEST(WaveKinematicsModes, InACrestAndBelowTheStillWaterLevel) {
  const Wave wheeler = MakeWave(Steep(WaveKinematics::kWheeler), kG);
  const Wave linear = MakeWave(Steep(WaveKinematics::kLinear), kG);
  const Wave extrapolated = MakeWave(Steep(WaveKinematics::kExtrapolated), kG);
  const double a = wheeler.amplitude, w = wheeler.omega, k = wheeler.k, h = wheeler.spec.depth;
  const Vec crest(0.0, 0.5 * a, 0.0);
  const double uw = KinematicsAt(wheeler, crest, 0.0).velocity.x();
  const double ul = KinematicsAt(linear, crest, 0.0).velocity.x();
  const double ue = KinematicsAt(extrapolated, crest, 0.0).velocity.x();
  EXPECT_NEAR(ul, a * w * Ch(k, h, 0.5 * a), 1e-12 * ul);
  EXPECT_NEAR(ue, a * w * (Ch(k, h, 0) + 0.5 * a * k), 1e-12 * ue);  // S(0) = 1
  EXPECT_NEAR(uw, a * w * Ch(k, h, -h * 0.5 * a / (h + a)), 1e-12 * uw);
  EXPECT_GT(ul, ue);
  EXPECT_GT(ue, uw);
  for (double z : {-0.15 * h, -0.3 * h, -h})  // under the trough, eta >= -a = -0.1 h
    for (double theta : {0.3, 1.9, 4.4}) {
      const Vec p(theta / k, z, 0.0);
      const WaterKinematics l = KinematicsAt(linear, p, 0.0), e = KinematicsAt(extrapolated, p, 0.0);
      EXPECT_EQ(l.velocity, e.velocity);
      EXPECT_EQ(l.acceleration, e.acceleration);
      EXPECT_EQ(l.velocity_gradient, e.velocity_gradient);
      const Expected airy = AiryWith(a, w, Ch(k, h, z), Sh(k, h, z), theta);
      EXPECT_LT((l.velocity - airy.U).norm(), 1e-12 * a * w * Ch(k, h, 0));
    }
}

// The gradients against central differences of the kinematics themselves, in every mode, at
// points below the still water level, in a crest above it and above the surface (where the
// value is the surface's own and moves with it), late in the ramp (R' != 0) and off the x axis.
// Step 1e-5 of the wave length: truncation (k dx)^2 ~ 4e-9, round-off 1e-16 / 6e-5 ~ 2e-12;
// every point is at least 0.3 m from the surface, where the kinematics turn to the surface's.
TEST(WaveKinematicsModes, GradientsMatchCentralDifferences) {
  for (WaveKinematics kin : kModes) {
    WaveSpec spec = Steep(kin);
    spec.heading = 0.6;      // [rad]
    spec.ramp_rate = 0.125;  // [1/s]: R(30 s) = 0.89, R' = 0.011 1/s
    spec.phase = 0.3;
    const Wave wave = MakeWave(spec, kG);
    const double t = 30.0, L = wave.length(), d = 1e-5 * L;
    const double su = wave.k * wave.amplitude * wave.omega / std::tanh(wave.k * spec.depth);
    double worst = 0;
    int above_still = 0, above_surface = 0;
    for (int i = 0; i < 40; ++i) {
      const Vec base(0.025 * i * L, 0.0, -0.01 * i * L);
      const double eta = SurfaceAt(wave, base, t);  // [m], the still water level at 0
      for (double y : {-25.0, -4.0, -0.5, 0.5 * eta, eta + 0.5, eta + 1.5}) {
        if (std::abs(y - eta) < 0.3) continue;
        const Vec at(base.x(), y, base.z());
        above_still += y > 0 && y < eta;
        above_surface += y > eta;
        const WaterKinematics w = KinematicsAt(wave, at, t);
        Mat Gu, Ga;
        testing::KinematicsGradientsByDifferences(wave, at, t, d, &Gu, &Ga);
        worst = std::max(worst, (w.velocity_gradient - Gu).cwiseAbs().maxCoeff() / su);
        worst = std::max(worst, (w.acceleration_gradient - Ga).cwiseAbs().maxCoeff() /
                                    (su * wave.omega));
      }
    }
    EXPECT_GE(above_still, 4) << static_cast<int>(kin);
    EXPECT_GE(above_surface, 40) << static_cast<int>(kin);
    EXPECT_LT(worst, 1e-7) << static_cast<int>(kin);
  }
}

// In "linear" and "extrapolated" the acceleration is the velocity's rate at the fixed point
// itself (in a crest too): central differences in time, step 1e-5 T, truncation (omega dt)^2 ~
// 4e-9.
TEST(WaveKinematicsModes, AccelerationIsTheRateAtTheFixedPoint) {
  for (WaveKinematics kin : {WaveKinematics::kLinear, WaveKinematics::kExtrapolated}) {
    const Wave wave = MakeWave(Steep(kin), kG);
    const double T = wave.spec.period, dt = 1e-5 * T;
    const double scale = wave.amplitude * wave.omega * wave.omega / std::tanh(wave.k * 30.0);
    // x = 0.05 L at t near 0: a crest (eta = 2.9 m) over the point at z = 1 m, and 10 m down.
    for (double z : {1.0, -10.0}) {
      const Vec p(0.05 * wave.length(), z, 0.0);
      const double t = 0.1;
      ASSERT_GT(SurfaceAt(wave, p, t), z + 0.5);
      const Vec rate = (KinematicsAt(wave, p, t + dt).velocity -
                        KinematicsAt(wave, p, t - dt).velocity) / (2 * dt);
      EXPECT_LT((KinematicsAt(wave, p, t).acceleration - rate).norm(), 1e-7 * scale)
          << static_cast<int>(kin) << " z " << z;
    }
  }
}

}  // namespace
}  // namespace cablefilm
