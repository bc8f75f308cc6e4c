// End motions: eq. (3) (trochoid with the ramp that starts from rest) and the table spline.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/end_motion.h"
#include "core/error.h"
#include "core/smooth_schedule.h"
#include "test_support.h"

namespace cablefilm {
namespace {

// Eq. (3) typed in from the paper (x: a, b; y: c, d), with the same form across (z: e, f).
Vec Eq3(double t, const Vec& rest, double a, double b, double c, double d, double e, double f,
        double w, double nu) {
  const double R = 1 - (1 + nu * t) * std::exp(-nu * t);
  return rest + R * Vec(a * std::cos(w * t) + b * std::sin(w * t),
                        c * std::cos(w * t) + d * std::sin(w * t),
                        e * std::cos(w * t) + f * std::sin(w * t));
}

TEST(EndMotion, TrochoidFollowsEquation3) {
  const Vec rest(80.0, 30.48, -4.0);
  const double a = 1.8288, b = 0.3, c = -0.2, d = 1.8288, ez = 0.7, fz = -0.4;
  const double w = 2 * M_PI / 10, nu = 0.5;
  const EndMotion e = EndMotion::Trochoid(rest, Vec(a, c, ez), Vec(b, d, fz), w, nu);
  // Starts from rest: R(0) = 0 and R'(0) = 0.
  EXPECT_EQ(e.Position(0.0), rest);
  EXPECT_EQ(e.Velocity(0.0), Vec::Zero());
  EXPECT_EQ(e.Position(-1.0), rest);  // holds before t = 0
  // Just after 0 it has barely moved: R(t) ~ nu^2 t^2 / 2, R'(t) ~ nu^2 t.
  EXPECT_LT(e.Velocity(1e-6).norm(), 1e-6 * nu * nu * 2.0 * 2.0);
  for (double t : {0.01, 0.3, 1.0, 2.7, 5.0, 13.1, 60.0}) {
    EXPECT_LT((e.Position(t) - Eq3(t, rest, a, b, c, d, ez, fz, w, nu)).norm(), 1e-12) << t;
    // Central differences, step h: truncation h^2/6 |x'''| ~ 1e-8 * few, round-off
    // 1e-16 * 80 / h ~ 1e-11 (velocity) and 1e-16 * 80 / h^2 ~ 1e-8 (acceleration, from the
    // velocity: 1e-16 / h ~ 1e-12). Tolerances 1e-7 hold both with room.
    const double h = 1e-4;
    const Vec v_fd = (Eq3(t + h, rest, a, b, c, d, ez, fz, w, nu) -
                                  Eq3(t - h, rest, a, b, c, d, ez, fz, w, nu)) / (2 * h);
    EXPECT_LT((e.Velocity(t) - v_fd).norm(), 1e-7) << t;
    const Vec a_fd = (e.Velocity(t + h) - e.Velocity(t - h)) / (2 * h);
    EXPECT_LT((e.Acceleration(t) - a_fd).norm(), 1e-7) << t;
  }
  // Late on the ramp is done: a circle of radius 1.83 m about rest (a = d, b = -c would be
  // exact; here only check it stays within the amplitude bound).
  EXPECT_LT((e.Position(60.0) - rest).norm(), std::hypot(a, b) + std::hypot(c, d) + std::hypot(ez, fz));
}

// A table added to eq. (3) (a drift on a wave-frequency motion): position, velocity and
// acceleration the trochoid's plus the linear table's (its slope between rows, no
// acceleration), to round-off; its rows are the motion's kinks; the live view's scale and
// clock act on the trochoid only (the drift is real time).
TEST(EndMotion, AnAddedTableIsTheSumOfBoth) {
  const Vec rest(80.0, 30.48, -4.0);
  const double w = 2 * M_PI / 10, nu = 0.5;
  const EndMotion wave = EndMotion::Trochoid(rest, Vec(1.5, 0.4, 0.2), Vec(0.3, 1.2, -0.1), w, nu);
  const EndMotion drift = EndMotion::Table(
      Vec::Zero(), {0.0, 100.0, 250.0}, {Vec::Zero(), Vec(12.0, 0.0, 3.0), Vec(2.0, 0.0, -4.0)},
      TableInterpolation::kLinear);
  const EndMotion both = wave.WithAdded(drift);
  EXPECT_TRUE(both.has_added());
  for (double t : {0.0, 1.0, 37.5, 100.0, 140.0, 250.0, 300.0}) {
    // By hand: 0.12 m/s along x and 0.03 along z to t = 100 s, then (-10, 0, -7) over 150 s.
    const Vec offset = t <= 100 ? Vec(0.12 * t, 0, 0.03 * t)
                       : t <= 250 ? Vec(12.0 - (t - 100) / 15, 0, 3.0 - 7.0 * (t - 100) / 150)
                                  : Vec(2.0, 0, -4.0);
    const Vec rate = t <= 100 ? Vec(0.12, 0, 0.03) : t <= 250 ? Vec(-1.0 / 15, 0, -7.0 / 150)
                                                               : Vec::Zero();
    EXPECT_LT((both.Position(t) - wave.Position(t) - offset).norm(), 1e-12) << t;
    EXPECT_LT((both.Velocity(t) - wave.Velocity(t) - rate).norm(), 1e-14) << t;
    EXPECT_LT((both.Acceleration(t) - wave.Acceleration(t)).norm(), 1e-14) << t;
  }
  EXPECT_EQ(both.NextKink(50.0), 100.0);  // the table's rows, where a step should land
  EXPECT_EQ(both.NextKink(100.0), 250.0);
  EXPECT_EQ(wave.NextKink(50.0), std::numeric_limits<double>::infinity());
  // Twice the amplitude (the live view's scale): the trochoid's offsets double, the drift not.
  SmoothSchedule scale(2.0), clock(1.0);
  const double t = 140.0;
  const Vec doubled = rest + 2.0 * (wave.Position(t) - rest);
  EXPECT_LT((both.Evaluate(t, 0, scale, clock) - doubled - (both.Position(t) - wave.Position(t)))
                .norm(),
            1e-12);
  EXPECT_THROW(wave.WithAdded(wave), Error);  // only a plain table adds
}

TEST(EndMotion, FixedAndFreeHoldStill) {
  const EndMotion f = EndMotion::Fixed(InPlane(1, 2));
  EXPECT_EQ(f.Position(5.0), InPlane(1, 2));
  EXPECT_EQ(f.Velocity(5.0), Vec::Zero());
  EXPECT_EQ(f.Acceleration(5.0), Vec::Zero());
  EXPECT_TRUE(f.prescribed());
  EXPECT_FALSE(EndMotion::Free(InPlane(0, 0)).prescribed());
}

std::vector<Eigen::Vector3d> Rows() {
  return {{0.0, 0.0, 0.0}, {0.5, 0.3, -0.1}, {1.5, -0.2, 0.4}, {2.0, 0.1, 0.1}, {3.2, 0.6, -0.5}};
}

TEST(EndMotion, TableSplineThroughKnotsC2AndHeld) {
  const Vec rest = InPlane(10.0, -2.0);
  const auto rows = Rows();
  const EndMotion e = testing::PlanarTable(rest, rows);
  for (const auto& r : rows)
    EXPECT_LT((e.Position(r[0]) - rest - InPlane(r[1], r[2])).norm(), 1e-14) << r[0];
  // C2 at the interior knots: value, slope and curvature agree from both sides.
  const double eps = 1e-9;
  for (size_t i = 1; i + 1 < rows.size(); ++i) {
    const double t = rows[i][0];
    EXPECT_LT((e.Position(t + eps) - e.Position(t - eps)).norm(), 1e-8) << t;
    EXPECT_LT((e.Velocity(t + eps) - e.Velocity(t - eps)).norm(), 1e-7) << t;
    EXPECT_LT((e.Acceleration(t + eps) - e.Acceleration(t - eps)).norm(), 1e-6) << t;
  }
  // The derivatives are those of the position (central differences inside a piece).
  for (double t : {0.2, 0.9, 1.7, 2.6}) {
    const double h = 1e-5;
    EXPECT_LT((e.Velocity(t) - (e.Position(t + h) - e.Position(t - h)) / (2 * h)).norm(), 1e-8);
    EXPECT_LT((e.Acceleration(t) - (e.Velocity(t + h) - e.Velocity(t - h)) / (2 * h)).norm(),
              1e-7);
  }
  // Natural spline: no curvature at the ends.
  EXPECT_LT(e.Acceleration(1e-12).norm(), 1e-9);
  EXPECT_LT(e.Acceleration(3.2 - 1e-12).norm(), 1e-9);
  // Holds still outside the table.
  EXPECT_EQ(e.Position(-1.0), rest);
  EXPECT_LT((e.Position(10.0) - rest - InPlane(0.6, -0.5)).norm(), 1e-15);
  EXPECT_EQ(e.Velocity(10.0), Vec::Zero());
  EXPECT_EQ(e.Acceleration(-1.0), Vec::Zero());
}

TEST(EndMotion, TableSplineHandValues) {
  // Knots (0,0), (1,1), (2,0): the natural spline has M1 = -3 (2 (h0 + h1) M1 = 6 (-1 - 1)),
  // so p(0.5) = 0.5 + (0.125 - 0.5)(-3)/6 = 0.6875, p'(0) = 1 - (-3)/6 = 1.5, p''(1) = -3.
  const EndMotion e = testing::PlanarTable(InPlane(0, 0), {{0, 0, 0}, {1, 1, 2}, {2, 0, 0}});
  EXPECT_NEAR(e.Position(0.5).x(), 0.6875, 1e-15);
  EXPECT_NEAR(e.Position(1.5).y(), 2 * 0.6875, 1e-15);
  EXPECT_NEAR(e.Velocity(1e-12).x(), 1.5, 1e-9);
  EXPECT_NEAR(e.Acceleration(1.0).x(), -3.0, 1e-12);
  // A linear table is reproduced exactly.
  const EndMotion lin = testing::PlanarTable(InPlane(0, 0), {{0, 0, 0}, {1, 2, -1}, {3, 6, -3}, {4, 8, -4}});
  EXPECT_NEAR(lin.Position(2.2).x(), 4.4, 1e-14);
  EXPECT_NEAR(lin.Velocity(2.2).y(), -1.0, 1e-14);
  EXPECT_NEAR(lin.Acceleration(0.7).x(), 0.0, 1e-13);
}

TEST(EndMotion, TableMovesAcrossTheLineToo) {
  // A linear table in all three axes is reproduced exactly, z as x and y.
  const EndMotion lin = EndMotion::Table(Vec(1, 2, 3), {0, 1, 3},
                                         {Vec(0, 0, 0), Vec(2, -1, 0.5), Vec(6, -3, 1.5)});
  EXPECT_LT((lin.Position(2.2) - Vec(1 + 4.4, 2 - 2.2, 3 + 1.1)).norm(), 1e-14);
  EXPECT_LT((lin.Velocity(0.4) - Vec(2, -1, 0.5)).norm(), 1e-14);
  EXPECT_LT(lin.Acceleration(1.7).norm(), 1e-13);
}

// A table's motion against its rows, both interpolations: the position at every row is the
// row's offset exactly (A, B of the segment are exactly 0 and 1 there); between rows the linear
// one is the straight line, its velocity the slope arriving at the point (at a row: the
// segment's before it), no acceleration; the last row of either carries the motion's own end
// velocity, not a standstill, and only strictly after it does the end hold still.
TEST(EndMotion, TableMotionAgainstItsRows) {
  const Vec rest(10.0, -2.0, 1.0);
  const std::vector<double> t = {0.0, 0.5, 1.5, 2.0, 3.2};
  const std::vector<Vec> p = {Vec(0, 0, 0), Vec(0.3, -0.1, 0.2), Vec(-0.2, 0.4, 0.0),
                              Vec(0.1, 0.1, -0.3), Vec(0.6, -0.5, 0.1)};
  for (TableInterpolation how : {TableInterpolation::kSpline, TableInterpolation::kLinear}) {
    const EndMotion e = EndMotion::Table(rest, t, p, how);
    EXPECT_EQ(e.interpolation(), how);
    for (size_t i = 0; i < t.size(); ++i) EXPECT_EQ(e.Position(t[i]), Vec(rest + p[i])) << i;
    EXPECT_EQ(e.table_start(), 0.0);
    EXPECT_EQ(e.table_end(), 3.2);
    // Held strictly outside.
    EXPECT_EQ(e.Position(-0.1), Vec(rest + p.front()));
    EXPECT_EQ(e.Position(3.2 + 1e-9), Vec(rest + p.back()));
    EXPECT_EQ(e.Velocity(3.2 + 1e-9), Vec::Zero());
    EXPECT_EQ(e.Acceleration(3.2 + 1e-9), Vec::Zero());
    // The end velocity is the motion's own, the slope of the position arriving at the row
    // (one-sided difference, h = 1e-7: truncation h |p''| / 2 < 1e-6 and round-off
    // 1e-16 x 10 / h ~ 1e-8; for the linear table exact to round-off).
    const double h = 1e-7;
    const Vec v_fd = (e.Position(3.2) - e.Position(3.2 - h)) / h;
    EXPECT_LT((e.Velocity(3.2) - v_fd).norm(), 1e-6);
    EXPECT_GT(e.Velocity(3.2).norm(), 0.1);  // the table ends moving: not a standstill
    EXPECT_NEAR(e.EndSpeed(), e.Velocity(3.2).norm(), 1e-15);
  }
  const EndMotion lin = EndMotion::Table(rest, t, p, TableInterpolation::kLinear);
  for (size_t i = 0; i + 1 < t.size(); ++i) {
    const Vec slope = (p[i + 1] - p[i]) / (t[i + 1] - t[i]);
    for (double f : {0.0, 0.25, 0.5, 0.9, 1.0}) {
      const double ti = t[i] + f * (t[i + 1] - t[i]);
      if (f > 0 || i == 0) {  // at t_i itself the segment arriving at it (below)
        EXPECT_LT((lin.Velocity(ti) - slope).norm(), 1e-14) << ti;
        EXPECT_EQ(lin.Acceleration(ti), Vec::Zero()) << ti;
      }
      // Straight between rows: (1 - f) p_i + f p_i+1 (f = 0.25, 0.5 exact in binary).
      // Round-off of the rest position (10 m): 2e-15 m a component.
      EXPECT_LT((lin.Position(ti) - rest - ((1 - f) * p[i] + f * p[i + 1])).norm(), 1e-14) << ti;
    }
    // A step landing on row i + 1 sees the velocity it arrives with.
    EXPECT_LT((lin.Velocity(t[i + 1]) - slope).norm(), 1e-14);
    // Where the velocity jumps: at the rows, and only for the linear table.
    EXPECT_EQ(lin.NextKink(t[i]), t[i + 1]);
    EXPECT_EQ(lin.NextKink(0.5 * (t[i] + t[i + 1])), t[i + 1]);
  }
  EXPECT_TRUE(std::isinf(lin.NextKink(3.2)));
  EXPECT_TRUE(std::isinf(EndMotion::Table(rest, t, p).NextKink(0.1)));
}

TEST(EndMotion, TableSplineEndVelocityByHand) {
  // Knots (0,0), (1,1), (2,0), M1 = -3 (TableSplineHandValues): on the last piece
  // p'(t) = (p2 - p1)/h + (-(3A^2 - 1) M1 + (3B^2 - 1) M2) h / 6, at t = 2 (A = 0, B = 1):
  // -1 + (-3)/6 = -1.5, the mirror of p'(0) = 1.5. Before the fix the last row read 0.
  const EndMotion e = testing::PlanarTable(InPlane(0, 0), {{0, 0, 0}, {1, 1, 2}, {2, 0, 0}});
  EXPECT_NEAR(e.Velocity(2.0).x(), -1.5, 1e-14);
  EXPECT_NEAR(e.Velocity(2.0).y(), -3.0, 1e-14);
  EXPECT_NEAR(e.Velocity(0.0).x(), 1.5, 1e-14);  // the first row: the first piece's
  EXPECT_NEAR(e.Acceleration(2.0).x(), 0.0, 1e-14);  // natural end
  EXPECT_EQ(e.Velocity(2.0 + 1e-12), Vec::Zero());   // held after
}

TEST(EndMotion, TableRejectsBadRows) {
  EXPECT_THROW(testing::PlanarTable(InPlane(0, 0), {{0, 0, 0}}), Error);
  EXPECT_THROW(testing::PlanarTable(InPlane(0, 0), {{0, 0, 0}, {1, 0, 0}, {1, 1, 1}}), Error);
}

}  // namespace
}  // namespace cablefilm
