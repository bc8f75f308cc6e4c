// What the live picture accumulates: a rolling window that stays bounded over hours, a colour
// range that grows with what is seen or stays locked, a box that always holds the cable.
#include <gtest/gtest.h>

#include <cmath>

#include "view/live_history.h"
#include "core/vec.h"

namespace cablefilm {
namespace {

// A 10-link straight line from (0, 0) to (10, 0) with tension `T` in every link.
LiveScenery Scenery(double window) {
  LiveScenery s;
  s.title = "test";
  for (int j = 0; j <= 10; ++j) s.arc_length.push_back(j);
  s.moving_ends = {10};
  s.fixed_ends = {0};
  s.equilibrium.x = s.arc_length;
  s.equilibrium.y.assign(11, 0.0);
  s.equilibrium.tension.assign(10, 1000.0);
  s.window = window;
  return s;
}

Points StraightLine(double end_y) {
  Points x(kDim, 11);
  for (int j = 0; j <= 10; ++j) x.col(j) << j, end_y * j / 10.0;
  return x;
}

TEST(LiveHistory, WindowRollsAndMemoryStaysBounded) {
  LiveHistory h(Scenery(60));
  // Two simulated hours at 30 frames/s.
  for (long k = 0; k <= 2 * 3600 * 30; ++k) {
    const double t = k / 30.0;
    h.Add(t, StraightLine(std::sin(t)), Eigen::VectorXd::Constant(10, 1000 + 100 * std::sin(t)));
    if (k % 3000 == 0) h.AddMarker(t, "change");
  }
  const LiveFrameInput in = h.MakeInput("live");
  EXPECT_NEAR(in.window_end, 7200, 1e-6);
  EXPECT_NEAR(in.window_start, 7140, 1e-6);
  EXPECT_LE(in.times.size(), 60u * 30 + 1);  // one window of frames, not two hours of them
  EXPECT_GE(in.times.size(), 60u * 30);
  for (double t : in.times) EXPECT_GE(t, in.window_start);
  for (const LiveMarker& m : in.markers) EXPECT_GE(m.t, in.window_start);
  EXPECT_EQ(in.markers.size(), 1u);  // one every 100 s: one inside the last 60 s
  ASSERT_EQ(in.end_paths.size(), 1u);
  EXPECT_LE(in.end_paths[0].size(), LiveHistory::kMaxPathPoints);
  EXPECT_NEAR(h.peak(), 1100, 0.01);
}

TEST(LiveHistory, RangeGrowsToNiceNumbersUnlessLocked) {
  LiveHistory h(Scenery(60));
  // The range ends 5 % above the largest tension seen, widened outwards to a multiple of a
  // nice tick step (at most doubling it), so the colour bar's ticks stay put as it grows.
  auto nice = [](double v) { return std::fmod(v, 100.0) == 0; };
  EXPECT_EQ(h.range_min(), 0);
  EXPECT_GE(h.range_max(), 1050);  // the equilibrium's 1000 N
  EXPECT_LE(h.range_max(), 2100);
  EXPECT_TRUE(nice(h.range_max())) << h.range_max();
  h.Add(0.1, StraightLine(0), Eigen::VectorXd::Constant(10, 4700));
  const double grown = h.range_max();
  EXPECT_GE(grown, 1.05 * 4700);
  EXPECT_LE(grown, 2 * 1.05 * 4700);
  EXPECT_TRUE(nice(grown)) << grown;
  h.Add(0.15, StraightLine(0), Eigen::VectorXd::Constant(10, 3000));
  EXPECT_EQ(h.range_max(), grown);  // it never shrinks while unlocked
  h.LockRange(true);
  h.Add(0.2, StraightLine(0), Eigen::VectorXd::Constant(10, 9000));
  EXPECT_EQ(h.range_max(), grown);  // locked: the colours keep their meaning
  h.LockRange(false);                      // unlocked: catches up with what was seen
  EXPECT_GE(h.range_max(), 1.05 * 9000);
  h.SetRange(100, 2000);
  EXPECT_TRUE(h.range_locked());
  const LiveFrameInput in = h.MakeInput("paused");
  EXPECT_EQ(in.tension_min, 100);
  EXPECT_EQ(in.tension_max, 2000);
  EXPECT_TRUE(in.range_locked);
}

// Issue 22 item 13: one snap used to leave the colour range stretched for good (it only
// grows). A reset starts it again from the tensions now and unlocks it, so it grows anew.
TEST(LiveHistory, ResetRangeFollowsTheTensionsNowAfterASnap) {
  LiveHistory h(Scenery(60));
  h.Add(0.1, StraightLine(0), Eigen::VectorXd::Constant(10, 1000));
  h.Add(0.2, StraightLine(0), Eigen::VectorXd::Constant(10, 50000));  // the snap
  h.Add(0.3, StraightLine(0), Eigen::VectorXd::Constant(10, 1200));
  h.LockRange(true);
  EXPECT_GE(h.range_max(), 1.05 * 50000);
  h.ResetRange();
  EXPECT_FALSE(h.range_locked());
  EXPECT_EQ(h.range_min(), 0);
  EXPECT_GE(h.range_max(), 1.05 * 1200);  // the tensions now, with the usual headroom
  EXPECT_LE(h.range_max(), 2 * 1.05 * 1200);
  EXPECT_LE(h.peak(), 50000);  // the peak is a record of the run: kept
  EXPECT_GE(h.peak(), 50000);
  h.Add(0.4, StraightLine(0), Eigen::VectorXd::Constant(10, 3000));
  EXPECT_GE(h.range_max(), 1.05 * 3000);  // unlocked: it grows again
}

TEST(LiveHistory, BoxAlwaysHoldsTheCableAndShrinksSlowly) {
  LiveHistory h(Scenery(60));
  for (int k = 0; k < 100; ++k) {
    const double end_y = k < 50 ? 8.0 : 1.0;  // a big swing, then a small one
    h.Add(k / 30.0, StraightLine(end_y), Eigen::VectorXd::Constant(10, 1000));
    const LiveFrameInput in = h.MakeInput("live");
    for (std::size_t j = 0; j < in.snapshot.x.size(); ++j) {
      EXPECT_GE(in.snapshot.y[j], in.y_min);
      EXPECT_LE(in.snapshot.y[j], in.y_max);
      EXPECT_GE(in.snapshot.x[j], in.x_min);
      EXPECT_LE(in.snapshot.x[j], in.x_max);
    }
    if (k == 51) {
      EXPECT_GT(in.y_max, 7.0);  // one frame later the box has not snapped in
    }
  }
}

// A seabed is passed on to the frame, and the box reaches below it (a strip of ground) even when
// the line lies on it.
TEST(LiveHistory, SeabedInViewWithGroundBelowIt) {
  LiveScenery scenery = Scenery(60);
  scenery.seabed = true;
  scenery.seabed_y = 0;  // the line lies on it
  LiveHistory h(scenery);
  h.Add(0.1, StraightLine(8.0), Eigen::VectorXd::Constant(10, 1000));
  const LiveFrameInput in = h.MakeInput("live");
  EXPECT_TRUE(in.seabed);
  EXPECT_EQ(in.seabed_y, 0.0);
  EXPECT_LT(in.y_min, 0.0);
  EXPECT_FALSE(LiveHistory(Scenery(60)).MakeInput("live").seabed);
}

// Waves: each frame carries the water surface across the box at its time, and the box reaches
// up to the crests.
TEST(LiveHistory, WaterSurfaceAcrossTheBoxUpToTheCrests) {
  LiveScenery scenery = Scenery(60);
  WaveSpec w;
  w.present = true;
  w.height = 2;
  w.period = 4;
  w.depth = 30;
  w.surface_y = 20;  // above the line
  scenery.waves = true;
  scenery.wave = MakeWave(w, 9.80665);
  LiveHistory h(scenery);
  h.Add(1.3, StraightLine(8.0), Eigen::VectorXd::Constant(10, 1000));
  const LiveFrameInput in = h.MakeInput("live");
  EXPECT_TRUE(in.surface);
  ASSERT_GE(in.snapshot.surface_x.size(), 64u);
  // A box's width beyond the box on either side (the plot's x range may be wider than the box).
  EXPECT_DOUBLE_EQ(in.snapshot.surface_x.front(), 2 * in.x_min - in.x_max);
  EXPECT_DOUBLE_EQ(in.snapshot.surface_x.back(), 2 * in.x_max - in.x_min);
  for (std::size_t i = 0; i < in.snapshot.surface_x.size(); i += 7)
    EXPECT_DOUBLE_EQ(in.snapshot.surface_y[i], SurfaceAt(scenery.wave, in.snapshot.surface_x[i], 1.3));
  EXPECT_GE(in.y_max, 21.0);
  EXPECT_FALSE(LiveHistory(Scenery(60)).MakeInput("live").surface);
}

TEST(LiveHistory, ResetForgetsTheRunButNotALockedRange) {
  LiveHistory h(Scenery(60));
  h.Add(1.0, StraightLine(3), Eigen::VectorXd::Constant(10, 3000));
  h.AddMarker(1.0, "current 1 m/s");
  h.SetRange(0, 9000);
  h.Reset();
  const LiveFrameInput in = h.MakeInput("live");
  EXPECT_TRUE(in.times.empty());
  EXPECT_TRUE(in.markers.empty());
  EXPECT_EQ(h.peak(), 0);
  EXPECT_EQ(in.tension_max, 9000);
  EXPECT_EQ(in.snapshot.y[10], 0.0);  // the equilibrium until a frame comes
}

}  // namespace
}  // namespace cablefilm
