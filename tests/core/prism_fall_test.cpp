// A prism falling in still fluid against the closed form of m v' = W - f v|v|:
//   v(t) = -v_t tanh(a0 t / v_t),  y(t) = y0 - (v_t^2 / a0) ln cosh(a0 t / v_t),
// with v_t = sqrt(W / f) the terminal speed, a0 = W / m the initial acceleration, m the mass
// with the virtual mass (m* + rho V^y), W = (m* - rho V*) g, f = rho C^y S^y / 2.
//
// Set-up: two stations; station 0 fixed at the origin, station 1 free, 1 m below it, carrying
// the prism. The one link is 1000 m long unstretched, so it stays slack (T = 0) through the
// whole fall: station 1 is then a free prism. The link is a hair (mu = 1e-9 kg/m, sigma =
// 1e-9 m^2, d = 1e-9 m); its half mass and half net weight are included in m and W below,
// and it falls along its own axis, so its normal drag and normal added mass do not act.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/explicit_step.h"
#include "test_support.h"
#include "core/forces.h"

namespace cablefilm {
namespace {

constexpr double kRho = 1000.0, kG = 9.80665;
constexpr double kMass = 10.0, kVolume = 0.002, kAddedY = 0.005, kCy = 1.0, kSy = 0.05;
constexpr double kLink = 1000.0, kHair = 1e-9;

LineModel PrismModel() {
  SectionSpec s{kLink, 1, kHair, kHair, kHair, 1e9, 1.2, 1.0};
  PrismSpec p;
  p.station = 1;
  p.mass = kMass;
  p.volume = kVolume;
  p.added_volume = Vec(0.004, kAddedY, 0.004);
  p.drag_coefficient = Vec(1.0, kCy, 1.0);
  p.drag_area = Vec(0.08, kSy, 0.08);
  EnvironmentSpec env;
  env.gravity = kG;
  env.fluid_density = kRho;
  return MakeLineModel({s}, {p}, env, EndMotion::Fixed(InPlane(0, 0)), EndMotion::Free(InPlane(0, -1)),
                         LinkLaw::kElastic);
}

struct Closed {
  double m = (kMass + kRho * kAddedY) + 0.5 * kHair * kLink;
  double W = (kMass - kRho * kVolume) * kG + 0.5 * (kHair - kRho * kHair) * kLink * kG;
  double f = 0.5 * kRho * kCy * kSy;
  double vt = std::sqrt(W / f);
  double a0 = W / m;
  double v(double t) const { return -vt * std::tanh(a0 * t / vt); }
  double y(double t) const { return -1.0 - vt * vt / a0 * std::log(std::cosh(a0 * t / vt)); }
};

// Max velocity and position error over a 4 s fall (about 12 time constants v_t / a0).
void Fall(double dt, double* v_err, double* y_err, double* v_end) {
  const LineModel m = PrismModel();
  const Closed c;
  State s;
  s.x = Points(kDim, 2);
  s.x << 0, 0, 0, -1, 0, 0;  // rows x, y, z
  s.v = Points::Zero(kDim, 2);
  testing::Stepper integ(Scheme::kExplicit);
  integ.Initialize(m, s);
  *v_err = *y_err = 0;
  const long steps = std::lround(4.0 / dt);
  for (long k = 1; k <= steps; ++k) {
    integ.Step(m, s, dt);
    ASSERT_EQ(integ.tensions()[0], 0.0) << "the link must stay slack";
    *v_err = std::max(*v_err, std::abs(s.v(1, 1) - c.v(s.t)) / c.vt);
    *y_err = std::max(*y_err, std::abs(s.x(1, 1) - c.y(s.t)));
    ASSERT_EQ(s.x(0, 1), 0.0);  // nothing pushes it sideways
  }
  *v_end = s.v(1, 1);
}

TEST(PrismFall, InitialAccelerationIncludesVirtualMass) {
  const LineModel m = PrismModel();
  const Closed c;
  ForceWorkspace ws(m.line.links);
  Points x(kDim, 2), v = Points::Zero(kDim, 2), a(kDim, 2);
  x << 0, 0, 0, -1, 0, 0;  // rows x, y, z
  ComputeAccelerations(m, SceneInputs(m), SceneWater(m), 0.0, x, v, ws, a);
  std::printf("[ prism ] a(0) = %.12f m/s^2, W/(m* + rho V^y + cable) = %.12f m/s^2 "
              "(without virtual mass it would be %.6f)\n",
              a(1, 1), -c.a0, -c.W / (kMass + 0.5 * kHair * kLink));
  // Rounding only: the same few products and one division.
  EXPECT_NEAR(a(1, 1), -c.a0, 1e-12 * c.a0);
  EXPECT_EQ(a(0, 1), 0.0);
}

TEST(PrismFall, ReachesTerminalVelocityAlongTheClosedForm) {
  const Closed c;
  double ve1, ye1, vend1, ve2, ye2, vend2;
  Fall(2e-3, &ve1, &ye1, &vend1);
  Fall(1e-3, &ve2, &ye2, &vend2);
  std::printf("[ prism ] v_t = %.9f m/s; dt = 2 ms: max |v - exact| %.3e v_t, max |y - exact| "
              "%.3e m; dt = 1 ms: %.3e v_t, %.3e m; ratios %.3f, %.3f; v(4 s) = %.9f m/s\n",
              c.vt, ve1, ye1, ve2, ye2, ve1 / ve2, ye1 / ye2, vend2);
  // The scheme is second order with drag (predicted velocity in the drag term): with a time
  // constant v_t/a0 = 0.34 s, (dt/tau)^2 ~ 1e-5 at 1 ms. Allow 1e-4 of v_t and 1e-4 m.
  EXPECT_LT(ve2, 1e-4);
  EXPECT_LT(ye2, 1e-4);
  // Halving dt divides the error by about 4.
  EXPECT_GT(ve1 / ve2, 3.0);
  EXPECT_LT(ve1 / ve2, 5.0);
  EXPECT_GT(ye1 / ye2, 3.0);
  EXPECT_LT(ye1 / ye2, 5.0);
  // After ~12 time constants the speed is terminal (tanh(12) = 1 - 8e-11) up to the scheme.
  EXPECT_NEAR(vend2, -c.vt, 1e-4 * c.vt);
}

}  // namespace
}  // namespace cablefilm
