// A point of a driven body that turns (issue 20): R(theta(t)) and its time derivatives
// (rotation_rates.h) and EndMotion::WithTurn, against a yaw at a constant rate in closed form
// and against central finite differences.
#include <gtest/gtest.h>

#include <cmath>

#include "core/body.h"
#include "core/end_motion.h"
#include "core/rotation_rates.h"

namespace cablefilm {
namespace {

// Angles and their first two derivatives along a smooth path [rad, rad/s, rad/s^2].
struct Path {
  Vec a0, a1, w;  // theta(t) = a0 + a1 sin(w t) (componentwise w)
  Vec At(double t) const { return a0 + a1.cwiseProduct((w * t).array().sin().matrix()); }
  Vec Rate(double t) const {
    return a1.cwiseProduct(w).cwiseProduct((w * t).array().cos().matrix());
  }
  Vec Rate2(double t) const {
    return -a1.cwiseProduct(w).cwiseProduct(w).cwiseProduct((w * t).array().sin().matrix());
  }
};

TEST(RotationInTime, IsBodyRotationAndItsTimeDerivatives) {
  const Path path{Vec(0.3, -0.7, 1.1), Vec(0.5, 0.8, -0.6), Vec(1.3, 0.7, 2.1)};
  const Vec p(4.0, -2.0, 3.0);  // [m]
  for (double t : {0.0, 0.4, 1.7, 3.2}) {
    const RotationRates r = RotationInTime(path.At(t), path.Rate(t), path.Rate2(t));
    // The same rotation as body.h's, to round-off.
    EXPECT_LT((r.R - BodyRotation(path.At(t))).norm(), 1e-15) << t;
    // R' p is BodyPointTurn's chain rule: (dR p/dtheta) theta'.
    EXPECT_LT((r.dR * p - BodyPointTurn(path.At(t), p) * path.Rate(t)).norm(), 1e-13) << t;
    // Central differences of R(theta(t)) p, step h = 1e-4 s: truncation h^2/6 |(Rp)'''| with
    // |(Rp)'''| below |p| (sum of rates)^3 ~ 5.4 x 4^3 ~ 350 m/s^3: 6e-7 m/s and, for the
    // second difference, h^2/12 |(Rp)''''| ~ 1e-9 x 5.4 x 4^4 ~ 1.2e-6 m/s^2; round-off
    // 1e-16 x 5.4 / h ~ 5e-12 and 1e-16 x 5.4 x 4 / h^2 ~ 2e-7. Tolerance 5e-6 holds both.
    const double h = 1e-4;
    auto x = [&](double s) -> Vec { return BodyRotation(path.At(s)) * p; };
    const Vec v_fd = (x(t + h) - x(t - h)) / (2 * h);
    const Vec a_fd = (x(t + h) - 2 * x(t) + x(t - h)) / (h * h);
    EXPECT_LT((r.dR * p - v_fd).norm(), 5e-6) << t;
    EXPECT_LT((r.d2R * p - a_fd).norm(), 5e-6) << t;
  }
}

// A yaw at a constant rate (about y, up): a point at radius rho from the axis goes round a
// circle at speed rho omega, accelerating rho omega^2 towards the axis; its height stays.
TEST(TurningMotion, ConstantYawIsACircle) {
  const double omega = 0.2;  // [rad/s]
  const double span = 10.0;  // [s]: a linear table of two rows is a constant rate
  const Vec r0(5.0, -1.0, 2.0), local(3.0, 0.5, 4.0);  // [m]; rho = |(3, 4)| = 5 m
  const double rho = 5.0;
  const EndMotion reference = EndMotion::Table(r0, {0.0, span}, {Vec::Zero(), Vec::Zero()},
                                               TableInterpolation::kLinear);
  const EndMotion angles = EndMotion::Table(Vec::Zero(), {0.0, span},
                                            {Vec::Zero(), Vec(0.0, omega * span, 0.0)},
                                            TableInterpolation::kLinear);
  const EndMotion point = reference.WithRest(r0 + local).WithTurn(angles, local);
  EXPECT_TRUE(point.turns());
  EXPECT_TRUE(point.moves());
  for (double t : {0.5, 2.0, 5.0, 9.5}) {
    const Vec x = point.Position(t), v = point.Velocity(t), a = point.Acceleration(t);
    const double phi = omega * t;
    // About +y: (x, z) -> (x cos + z sin, -x sin + z cos).
    const Vec expected = r0 + Vec(3.0 * std::cos(phi) + 4.0 * std::sin(phi), 0.5,
                                  -3.0 * std::sin(phi) + 4.0 * std::cos(phi));
    // Tolerances: a few round-offs of 10 m (1e-15 relative): 1e-13.
    EXPECT_LT((x - expected).norm(), 1e-13) << t;
    EXPECT_NEAR(v.norm(), rho * omega, 1e-13) << t;
    EXPECT_NEAR(a.norm(), rho * omega * omega, 1e-13) << t;
    const Vec towards_axis = Vec(r0.x() - x.x(), 0.0, r0.z() - x.z()) / rho;
    EXPECT_LT((a - rho * omega * omega * towards_axis).norm(), 1e-13) << t;
    EXPECT_NEAR(v.dot(x - r0), 0.0, 1e-13) << t;  // tangent to the circle
  }
}

// A table that moves and turns about all three axes, splined: position, velocity and
// acceleration against central differences of Position().
TEST(TurningMotion, SplinedTableAgainstFiniteDifferences) {
  const std::vector<double> times{0.0, 2.0, 3.5, 6.0, 8.0};
  const std::vector<Vec> offsets{Vec::Zero(), Vec(1.0, 0.2, -0.5), Vec(0.4, -0.3, 0.2),
                                 Vec(-0.8, 0.1, 0.6), Vec(0.0, 0.0, 0.0)};
  const double deg = M_PI / 180.0;
  const std::vector<Vec> turns{Vec::Zero(), Vec(5.0, -10.0, 3.0) * deg, Vec(-4.0, 20.0, -6.0) * deg,
                               Vec(2.0, 5.0, 8.0) * deg, Vec(0.0, 0.0, 0.0)};
  const Vec rest_angles = Vec(2.0, 30.0, -1.0) * deg;
  const Vec r0(10.0, -5.0, 3.0), local(20.0, -8.0, 15.0);  // [m]
  const Vec rest = r0 + BodyRotation(rest_angles) * local;
  const EndMotion point = EndMotion::Table(r0, times, offsets)
                              .WithRest(rest)
                              .WithTurn(EndMotion::Table(rest_angles, times, turns), local);
  // At rest (t = 0, the first row: no offset, no turn) the point is at its rest position.
  EXPECT_LT((point.Position(0.0) - rest).norm(), 1e-13);
  for (double t : {0.7, 2.5, 4.1, 5.2, 7.3}) {
    const Vec theta = rest_angles + EndMotion::Table(Vec::Zero(), times, turns).Position(t);
    const Vec expected =
        r0 + EndMotion::Table(Vec::Zero(), times, offsets).Position(t) + BodyRotation(theta) * local;
    EXPECT_LT((point.Position(t) - expected).norm(), 1e-12) << t;
    // Step h = 1e-4 s inside a spline segment (no row within h of t): truncation h^2/6 x
    // |x'''| (a few m/s^3 here, from |local| ~ 26 m and rates ~ 0.2 rad/s) ~ 1e-8, round-off
    // 1e-16 x 30 / h ~ 3e-11 (velocity) and 1e-16 x 30 / h^2 ~ 3e-7 (acceleration).
    // Tolerances 1e-7 and 2e-6.
    const double h = 1e-4;
    const Vec v_fd = (point.Position(t + h) - point.Position(t - h)) / (2 * h);
    const Vec a_fd =
        (point.Position(t + h) - 2 * point.Position(t) + point.Position(t - h)) / (h * h);
    EXPECT_LT((point.Velocity(t) - v_fd).norm(), 1e-7) << t;
    EXPECT_LT((point.Acceleration(t) - a_fd).norm(), 2e-6) << t;
  }
}

// The live view's scale and clock act on the angles as on the offsets; at 1 both, the scene's.
TEST(TurningMotion, SceneScheduleIsThePlainMotion) {
  const Vec local(3.0, 1.0, -2.0), r0(1.0, 2.0, 3.0);
  const EndMotion angles =
      EndMotion::Trochoid(Vec(0.1, 0.2, 0.3), Vec(0.05, 0.1, 0.0), Vec(0.0, 0.02, 0.08), 0.6, 0.5);
  const EndMotion point =
      EndMotion::Trochoid(r0, Vec(1.0, 0.5, 0.0), Vec(0.0, 0.3, 0.2), 0.6, 0.5)
          .WithRest(r0 + BodyRotation(Vec(0.1, 0.2, 0.3)) * local)
          .WithTurn(angles, local);
  const SmoothSchedule one(1.0);
  for (double t : {0.0, 1.0, 4.5})
    for (int order = 0; order < 3; ++order) {
      const Vec plain = order == 0 ? point.Position(t)
                        : order == 1 ? point.Velocity(t)
                                     : point.Acceleration(t);
      EXPECT_EQ(point.Evaluate(t, order, one, one), plain) << t << " " << order;
    }
  // Carried by the live view's vessel (inputs.h adds its offset): still the same turn.
  const EndMotion carried = point.Carried();
  EXPECT_TRUE(carried.carried() && carried.turns());
  EXPECT_EQ(carried.Acceleration(4.5), point.Acceleration(4.5));
  // At t = 0 the trochoid's ramp is 0: the point is at its rest position, still.
  EXPECT_LT((point.Position(0.0) - point.rest()).norm(), 1e-15);
  EXPECT_EQ(point.Velocity(0.0), Vec::Zero());
}

// A linear table's kinks: the angles' rows count too.
TEST(TurningMotion, NextKinkIncludesTheAngles) {
  const EndMotion angles = EndMotion::Table(Vec::Zero(), {0.0, 1.5, 4.0},
                                            {Vec::Zero(), Vec(0.0, 0.1, 0.0), Vec::Zero()},
                                            TableInterpolation::kLinear);
  const EndMotion point = EndMotion::Trochoid(Vec::Zero(), Vec(1, 0, 0), Vec::Zero(), 1.0, 1.0)
                              .WithTurn(angles, Vec(1.0, 0.0, 0.0));
  EXPECT_EQ(point.NextKink(0.2), 1.5);
  EXPECT_EQ(point.NextKink(2.0), 4.0);
  EXPECT_TRUE(std::isinf(point.NextKink(5.0)));
}

}  // namespace
}  // namespace cablefilm
