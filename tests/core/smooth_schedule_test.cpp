// SmoothSchedule and the modulated end motion (the live view's changes of amplitude and
// period) against independent truths: finite differences of the schedule's own value (its
// derivatives and integral must be those of one smooth function), the unmodulated formula of
// eq. (3), and the exact scaled or re-timed orbit once a ramp is complete.
#include <gtest/gtest.h>

#include <cmath>

#include "core/end_motion.h"
#include "core/smooth_schedule.h"
#include "test_support.h"

namespace cablefilm {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Central differences with step h: error O(h^2 f'''), about 1e-7 relative for h = 1e-4 on
// these quintic ramps of 1-10 s; the tolerances below allow 10x that.
TEST(SmoothSchedule, DerivativesAndIntegralAreThoseOfOneFunction) {
  SmoothSchedule s(1.0);
  ASSERT_TRUE(s.Change(2.0, 3.0, 4.0));   // 1 -> 3 over [2, 6]
  ASSERT_TRUE(s.Change(4.0, 0.5, 2.0));   // then -> 0.5 over [4, 6], overlapping
  const double h = 1e-4;
  double quadrature = 0;  // trapezoidal integral of the value, step 1e-4: error ~1e-9
  double previous = s.ValueAt(0);
  for (int i = 1; i <= 80000; ++i) {
    const double t = i * 1e-4;
    const double v = s.ValueAt(t);
    quadrature += 0.5 * (previous + v) * 1e-4;
    previous = v;
    if (i % 997 == 0) {
      const SmoothSchedule::Value a = s.At(t);
      EXPECT_NEAR(a.rate, (s.ValueAt(t + h) - s.ValueAt(t - h)) / (2 * h), 1e-6) << t;
      EXPECT_NEAR(a.rate2, (s.At(t + h).rate - s.At(t - h).rate) / (2 * h), 1e-5) << t;
      EXPECT_NEAR(a.integral, quadrature, 1e-7) << t;
    }
  }
  EXPECT_DOUBLE_EQ(s.ValueAt(1.9), 1.0);
  EXPECT_DOUBLE_EQ(s.ValueAt(6.0), 0.5);  // the last target, once both ramps are done
  EXPECT_DOUBLE_EQ(s.target(), 0.5);
}

TEST(SmoothSchedule, RampsStartAndEndWithZeroRateAndCurvature) {
  SmoothSchedule s(0.0);
  ASSERT_TRUE(s.Change(1.0, 2.0, 3.0));
  for (double t : {1.0, 4.0}) {
    EXPECT_NEAR(s.At(t).rate, 0, 1e-15);
    EXPECT_NEAR(s.At(t).rate2, 0, 1e-15);
  }
  EXPECT_NEAR(s.ValueAt(2.5), 1.0, 1e-15);  // the quintic's midpoint is half way
}

TEST(SmoothSchedule, RetireKeepsEveryValueExactly) {
  SmoothSchedule s(2.0);
  ASSERT_TRUE(s.Change(0.5, 5.0, 1.0));
  ASSERT_TRUE(s.Change(3.0, 1.0, 2.0));
  const SmoothSchedule::Value before = s.At(10.0);
  s.Retire(10.0);
  EXPECT_TRUE(s.constant());
  const SmoothSchedule::Value after = s.At(10.0);
  EXPECT_NEAR(after.value, before.value, 1e-14);
  EXPECT_NEAR(after.integral, before.integral, 1e-12);
  // The integral by hand: 2 over [0, 0.5], the ramp to 5 averages 3.5 over [0.5, 1.5], 5 until
  // 3, the ramp to 1 averages 3 over [3, 5], then 1 until 10.
  EXPECT_NEAR(after.integral, 2 * 0.5 + 3.5 * 1 + 5 * 1.5 + 3 * 2 + 1 * 5, 1e-12);
}

TEST(SmoothSchedule, RefusesMoreRampsThanItHolds) {
  SmoothSchedule s(0.0);
  for (int i = 0; i < SmoothSchedule::kMaxRamps; ++i) ASSERT_TRUE(s.Change(i * 0.01, i, 100));
  EXPECT_FALSE(s.Change(1.0, 7.0, 1.0));
  EXPECT_DOUBLE_EQ(s.target(), SmoothSchedule::kMaxRamps - 1);  // the refused one left no trace
  EXPECT_FALSE(s.Change(200.0, 1.0, 0.0));  // a zero duration is refused too
}

// An end motion as the inputs change it (core/inputs.h): its amplitude scaled, its clock's rate.
struct Modulated {
  EndMotion motion;
  SmoothSchedule scale, rate;
  Vec Position(double t) const { return motion.Evaluate(t, 0, scale, rate); }
  Vec Velocity(double t) const { return motion.Evaluate(t, 1, scale, rate); }
  Vec Acceleration(double t) const { return motion.Evaluate(t, 2, scale, rate); }
};

EndMotion P63Fairlead() {  // case P63's circular orbit: radius 1.8288 m, period 10 s, nu 0.5
  return EndMotion::Trochoid(InPlane(80.0, 30.48), InPlane(1.8288, 0.0), InPlane(0.0, 1.8288), 2 * kPi / 10, 0.5);
}

TEST(ModulatedEndMotion, IdentityModulationIsTheScenesMotion) {
  const EndMotion plain = P63Fairlead();
  const Modulated modulated{plain, SmoothSchedule(1.0), SmoothSchedule(1.0)};
  for (double t : {0.0, 0.3, 2.0, 7.7, 31.0, 1234.5}) {
    EXPECT_LT((modulated.Position(t) - plain.Position(t)).norm(), 1e-12) << t;
    EXPECT_LT((modulated.Velocity(t) - plain.Velocity(t)).norm(), 1e-12) << t;
    EXPECT_LT((modulated.Acceleration(t) - plain.Acceleration(t)).norm(), 1e-12) << t;
  }
}

// Through a change of amplitude and one of period, overlapping, the velocity and acceleration
// are the derivatives of the position (so nothing jumps), and afterwards the motion is the
// scene's orbit scaled, on a clock of the new period.
TEST(ModulatedEndMotion, ChangesAreSmoothAndEndOnTheNewOrbit) {
  const EndMotion plain = P63Fairlead();
  SmoothSchedule scale(1.0), rate(1.0);
  ASSERT_TRUE(scale.Change(20.0, 2.0, 10.0));
  ASSERT_TRUE(rate.Change(25.0, 10.0 / 6.0, 10.0));  // period 10 s -> 6 s
  const Modulated m{plain, scale, rate};
  const double h = 1e-5;
  for (double t = 15.0; t < 40.0; t += 0.37) {
    const Vec v_fd = (m.Position(t + h) - m.Position(t - h)) / (2 * h);
    const Vec a_fd = (m.Velocity(t + h) - m.Velocity(t - h)) / (2 * h);
    // Central differences of an orbit of ~2-4 m at ~1 rad/s: truncation ~1e-10 and
    // round-off ~1e-16 * 80 m / 1e-5 s ~ 1e-9; 1e-7 is far below any jump a ramp could cause.
    EXPECT_LT((m.Velocity(t) - v_fd).norm(), 1e-7) << t;
    EXPECT_LT((m.Acceleration(t) - a_fd).norm(), 1e-7) << t;
  }
  // Before the first change: the scene's motion.
  EXPECT_LT((m.Position(19.0) - plain.Position(19.0)).norm(), 1e-12);
  // After both: radius 2 x 1.8288 m about the rest point (the ramp R(t) is 1 to 1e-9 by
  // t = 50 s), period 6 s.
  const Vec rest = InPlane(80.0, 30.48);
  for (double t : {50.0, 51.3, 77.7}) {
    EXPECT_NEAR((m.Position(t) - rest).norm(), 2 * 1.8288, 1e-8) << t;
    EXPECT_LT((m.Position(t + 6.0) - m.Position(t)).norm(), 1e-8) << t;
    EXPECT_NEAR(m.Velocity(t).norm(), 2 * 1.8288 * 2 * kPi / 6.0, 1e-8) << t;
  }
}

TEST(ModulatedEndMotion, TableMotionIsScaledAndRetimed) {
  const std::vector<Eigen::Vector3d> rows{{0, 0, 0}, {1, 1, 0}, {2, 1, 1}, {3, 0, 1}, {4, 0, 0}};
  const EndMotion plain = testing::PlanarTable(InPlane(5, 5), rows);
  SmoothSchedule scale(3.0), rate(0.5);  // constant: three times the offsets, half as fast
  const Modulated m{plain, scale, rate};
  for (double t : {0.5, 1.7, 3.3, 6.1}) {
    const Vec expect = InPlane(5, 5) + 3.0 * (plain.Position(0.5 * t) -
                                                                   InPlane(5, 5));
    EXPECT_LT((m.Position(t) - expect).norm(), 1e-12) << t;
    EXPECT_LT((m.Velocity(t) - 1.5 * plain.Velocity(0.5 * t)).norm(), 1e-12) << t;
    EXPECT_LT((m.Acceleration(t) - 0.75 * plain.Acceleration(0.5 * t)).norm(), 1e-12) << t;
  }
  EXPECT_DOUBLE_EQ(plain.period(), 4.0);  // a table's "period" is its span
}

}  // namespace
}  // namespace cablefilm
