// What the live picture accumulates (a following History): a rolling window that stays bounded
// over hours, a colour range that grows with what is seen or stays locked, a box that always
// holds the cable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/vec.h"
#include "view/history.h"
#include "view/snapshot.h"

namespace cablefilm {
namespace {

// A 10-link straight line from (0, 0) to (10, 0), its reference at 1000 N in every link.
SceneView Scene() {
  SceneView s;
  s.title = "test";
  s.lines.resize(1);
  LineView& line = s.lines[0];
  for (int j = 0; j <= 10; ++j) line.arc_length.push_back(j);
  line.marks.moving_ends = {10};
  line.marks.fixed_ends = {0};
  line.reference.x = line.arc_length;
  line.reference.y.assign(11, 0.0);
  line.reference.tension.assign(10, 1000.0);
  return s;
}

Points StraightLine(double end_y) {
  Points x = Points::Zero(kDim, 11);  // z = 0: the comma initializer below sets x and y only
  for (int j = 0; j <= 10; ++j) x.col(j) << j, end_y * j / 10.0;
  return x;
}

// The live session's step: the state now (positions x [m], tensions T [N]) at t [s].
void Add(History& h, double t, const Points& x, const Eigen::VectorXd& T) {
  Snapshot s;
  s.t = t;
  s.lines.resize(1);
  SetLineState(x, T, &s.lines[0]);
  h.Add(s);
}

TEST(LiveHistory, WindowRollsAndMemoryStaysBounded) {
  History h(Scene(), FollowingPolicy{60, {}});
  // Two simulated hours at 30 frames/s.
  Snapshot s;
  s.lines.resize(1);
  for (long k = 0; k <= 2 * 3600 * 30; ++k) {
    const double t = k / 30.0;
    s.t = t;
    SetLineState(StraightLine(std::sin(t)), Eigen::VectorXd::Constant(10, 1000 + 100 * std::sin(t)),
                 &s.lines[0]);
    h.Add(s);
    if (k % 3000 == 0) h.AddMarker(t, "change");
  }
  EXPECT_NEAR(h.time_max(), 7200, 1e-6);
  EXPECT_NEAR(h.time_min(), 7140, 1e-6);
  EXPECT_LE(h.times().size(), 60u * 30 + 1);  // one window of frames, not two hours of them
  EXPECT_GE(h.times().size(), 60u * 30);
  EXPECT_EQ(h.max_tension()[0].size(), h.times().size());
  for (double t : h.times()) EXPECT_GE(t, h.time_min());
  for (const TimeMarker& m : h.markers()) EXPECT_GE(m.t, h.time_min());
  EXPECT_EQ(h.markers().size(), 1u);  // one every 100 s: one inside the last 60 s
  ASSERT_EQ(h.end_paths().size(), 1u);
  ASSERT_EQ(h.end_paths()[0].pieces.size(), 1u);
  EXPECT_LE(h.end_paths()[0].pieces[0].size(), History::kMaxPathPoints);
  EXPECT_NEAR(h.peak(), 1100, 0.01);
}

TEST(LiveHistory, RangeGrowsToNiceNumbersUnlessLocked) {
  History h(Scene(), FollowingPolicy{60, {}});
  // The range ends 5 % above the largest tension seen, widened outwards to a multiple of a
  // nice tick step (at most doubling it), so the colour bar's ticks stay put as it grows.
  auto nice = [](double v) { return std::fmod(v, 100.0) == 0; };
  EXPECT_EQ(h.range_min(), 0);
  EXPECT_GE(h.range_max(), 1050);  // the reference's 1000 N
  EXPECT_LE(h.range_max(), 2100);
  EXPECT_TRUE(nice(h.range_max())) << h.range_max();
  Add(h, 0.1, StraightLine(0), Eigen::VectorXd::Constant(10, 4700));
  const double grown = h.range_max();
  EXPECT_GE(grown, 1.05 * 4700);
  EXPECT_LE(grown, 2 * 1.05 * 4700);
  EXPECT_TRUE(nice(grown)) << grown;
  Add(h, 0.15, StraightLine(0), Eigen::VectorXd::Constant(10, 3000));
  EXPECT_EQ(h.range_max(), grown);  // it never shrinks while unlocked
  h.LockRange(true);
  Add(h, 0.2, StraightLine(0), Eigen::VectorXd::Constant(10, 9000));
  EXPECT_EQ(h.range_max(), grown);  // locked: the colours keep their meaning
  h.LockRange(false);                      // unlocked: catches up with what was seen
  EXPECT_GE(h.range_max(), 1.05 * 9000);
  h.SetRange(100, 2000);
  EXPECT_TRUE(h.range_locked());
  EXPECT_EQ(h.range_min(), 100);
  EXPECT_EQ(h.range_max(), 2000);
}

// Issue 22 item 13: one snap used to leave the colour range stretched for good (it only
// grows). A reset starts it again from the tensions now and unlocks it, so it grows anew.
TEST(LiveHistory, ResetRangeFollowsTheTensionsNowAfterASnap) {
  History h(Scene(), FollowingPolicy{60, {}});
  Add(h, 0.1, StraightLine(0), Eigen::VectorXd::Constant(10, 1000));
  Add(h, 0.2, StraightLine(0), Eigen::VectorXd::Constant(10, 50000));  // the snap
  Add(h, 0.3, StraightLine(0), Eigen::VectorXd::Constant(10, 1200));
  h.LockRange(true);
  EXPECT_GE(h.range_max(), 1.05 * 50000);
  h.ResetRange();
  EXPECT_FALSE(h.range_locked());
  EXPECT_EQ(h.range_min(), 0);
  EXPECT_GE(h.range_max(), 1.05 * 1200);  // the tensions now, with the usual headroom
  EXPECT_LE(h.range_max(), 2 * 1.05 * 1200);
  EXPECT_LE(h.peak(), 50000);  // the peak is a record of the run: kept
  EXPECT_GE(h.peak(), 50000);
  Add(h, 0.4, StraightLine(0), Eigen::VectorXd::Constant(10, 3000));
  EXPECT_GE(h.range_max(), 1.05 * 3000);  // unlocked: it grows again
}

TEST(LiveHistory, BoxAlwaysHoldsTheCableAndShrinksSlowly) {
  History h(Scene(), FollowingPolicy{60, {}});
  for (int k = 0; k < 100; ++k) {
    const double end_y = k < 50 ? 8.0 : 1.0;  // a big swing, then a small one
    Add(h, k / 30.0, StraightLine(end_y), Eigen::VectorXd::Constant(10, 1000));
    const WorldBox box = h.box();
    const LineSnapshot& now = h.now().lines[0];
    for (std::size_t j = 0; j < now.x.size(); ++j) {
      EXPECT_GE(now.y[j], box.y_min);
      EXPECT_LE(now.y[j], box.y_max);
      EXPECT_GE(now.x[j], box.x_min);
      EXPECT_LE(now.x[j], box.x_max);
    }
    if (k == 51) {
      EXPECT_GT(box.y_max, 7.0);  // one frame later the box has not snapped in
    }
  }
}

// The moving end's recent path: points a thousandth of the view apart, the newest where the end
// is now. The line spans 10 m in x, so the view is at least 10 m wide and the spacing at least
// 0.01 m. An orbit of 0.002 m (a pixel's fraction) stays two points however long it runs; one of
// 2 m radius at 30 frames/s (0.042 m a frame, over the spacing) keeps every frame, up to the
// bound, and spans its diameter.
TEST(LiveHistory, RecentPathKeepsWhatTheViewCanShow) {
  const double kPi = std::acos(-1.0);
  auto orbit = [kPi](double radius, double period, long frames) {
    History h(Scene(), FollowingPolicy{60, {}});
    Points x = StraightLine(0);
    for (long k = 0; k < frames; ++k) {
      const double t = k / 30.0, a = 2 * kPi * t / period;  // [s], [rad]
      x(0, 10) = 10 + radius * std::cos(a);  // [m]
      x(1, 10) = radius * std::sin(a);
      Add(h, t, x, Eigen::VectorXd::Constant(10, 1000));
    }
    return std::make_pair(h.end_paths().at(0).pieces.at(0), x.col(10).eval());
  };
  auto distance = [](const Vec3f& a, const Vec3f& b) {
    return std::hypot(double{a.x} - b.x, double{a.y} - b.y, double{a.z} - b.z);
  };
  {
    const auto [path, end] = orbit(0.002, 10, 30 * 3600);  // an hour
    ASSERT_EQ(path.size(), 2u);
    EXPECT_FLOAT_EQ(path.back().x, static_cast<float>(end.x()));
    EXPECT_FLOAT_EQ(path.back().y, static_cast<float>(end.y()));
  }
  {
    const auto [path, end] = orbit(2.0, 10, 30 * 600);
    EXPECT_EQ(path.size(), History::kMaxPathPoints);
    EXPECT_FLOAT_EQ(path.back().x, static_cast<float>(end.x()));
    EXPECT_FLOAT_EQ(path.back().y, static_cast<float>(end.y()));
    double widest = 0;
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      // 2 m x 2 pi / 300 frames a chord of 0.0419 m (float positions: 1e-5 m).
      EXPECT_NEAR(distance(path[i], path[i + 1]), 2.0 * 2 * std::sin(kPi / 300), 1e-4);
      widest = std::max(widest, distance(path[0], path[i + 1]));
    }
    EXPECT_NEAR(widest, 4.0, 0.01);  // 1024 frames: more than a period, the whole orbit
  }
}

// A seabed is in the box, and the box reaches below it (a strip of ground) even when the line
// lies on it.
TEST(LiveHistory, SeabedInViewWithGroundBelowIt) {
  SceneView scene = Scene();
  scene.sea.seabed = true;
  scene.sea.seabed_y = 0;  // the line lies on it
  History h(scene, FollowingPolicy{60, {}});
  Add(h, 0.1, StraightLine(8.0), Eigen::VectorXd::Constant(10, 1000));
  EXPECT_LT(h.box().y_min, 0.0);
  // A seabed below the line: the box reaches down to it, and beyond.
  scene.sea.seabed_y = -2;
  History below(scene, FollowingPolicy{60, {}});
  History none(Scene(), FollowingPolicy{60, {}});
  for (History* each : {&below, &none})
    Add(*each, 0.1, StraightLine(8.0), Eigen::VectorXd::Constant(10, 1000));
  EXPECT_LT(below.box().y_min, -2.0);
  EXPECT_GT(none.box().y_min, -2.0);
}

// Waves: each frame carries the water surface across the box at its time, and the box reaches
// up to the crests.
TEST(LiveHistory, WaterSurfaceAcrossTheBoxUpToTheCrests) {
  SceneView scene = Scene();
  WaveSpec w;
  w.present = true;
  w.height = 2;
  w.period = 4;
  w.depth = 30;
  w.surface_y = 20;  // above the line
  scene.sea.surface = true;
  const Wave wave = MakeWave(w, 9.80665);
  History h(scene, FollowingPolicy{60, wave});
  Add(h, 1.3, StraightLine(8.0), Eigen::VectorXd::Constant(10, 1000));
  const Snapshot& now = h.now();
  const WorldBox box = h.box();
  ASSERT_GE(now.surface_x.size(), 64u);
  // A box's width beyond the box on either side (the plot's x range may be wider than the box).
  EXPECT_DOUBLE_EQ(now.surface_x.front(), 2 * box.x_min - box.x_max);
  EXPECT_DOUBLE_EQ(now.surface_x.back(), 2 * box.x_max - box.x_min);
  for (std::size_t i = 0; i < now.surface_x.size(); i += 7)
    EXPECT_DOUBLE_EQ(now.surface_y[i], SurfaceAt(wave, InPlane(now.surface_x[i], 0.0), 1.3));
  EXPECT_GE(box.y_max, 21.0);
  History calm(Scene(), FollowingPolicy{60, wave});  // no surface in the scene: none drawn
  Add(calm, 1.3, StraightLine(8.0), Eigen::VectorXd::Constant(10, 1000));
  EXPECT_TRUE(calm.now().surface_x.empty());
  EXPECT_LT(calm.box().y_max, 21.0);
}

TEST(LiveHistory, ResetForgetsTheRunButNotALockedRange) {
  History h(Scene(), FollowingPolicy{60, {}});
  Add(h, 1.0, StraightLine(3), Eigen::VectorXd::Constant(10, 3000));
  h.AddMarker(1.0, "current 1 m/s");
  h.SetRange(0, 9000);
  h.Reset();
  EXPECT_TRUE(h.times().empty());
  EXPECT_TRUE(h.markers().empty());
  EXPECT_EQ(h.peak(), 0);
  EXPECT_EQ(h.range_max(), 9000);
  EXPECT_EQ(h.now().lines[0].y[10], 0.0);  // the reference until a frame comes
}

}  // namespace
}  // namespace cablefilm
