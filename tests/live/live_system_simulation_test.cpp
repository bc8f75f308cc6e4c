// A system's live view (cablefilm live on a scene of [[line]], [[point]] and [[body]] tables)
// against truths of its own: the system's run (RunSystemInMemory, rows of `cablefilm run`),
// the scene's prescribed motions of the fairleads plus the offset asked, the current's
// direction asked; and the controls a system refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <cstdio>
#include <string>

#include "live/control.h"
#include "live/live_physics.h"
#include "live/live_system_simulation.h"
#include "run/memory_system_run.h"
#include "scene/build_model.h"
#include "scene/scene_loader.h"

namespace cablefilm {
namespace {

SceneDef Scene(const char* name) {
  return LoadScene(std::string(CABLEFILM_SOURCE_DIR) + "/scenes/" + name);
}

// The spread mooring for `seconds` (its rows every 0.5 s).
SceneDef Spread(double seconds) {
  SceneDef scene = Scene("spread_mooring.toml");
  scene.simulation.duration = seconds;
  return scene;
}

int PointIndex(const Model& sys, const std::string& name) {
  for (int p = 0; p < static_cast<int>(sys.points.size()); ++p)
    if (sys.points[p].name == name) return p;
  ADD_FAILURE() << "no point " << name;
  return 0;
}

// Where point p is in the live state [m]: its first line end's station.
Vec PointNow(const LiveSystemSimulation& sim, int p) {
  const LineEnd& e = sim.run().sys.points[p].ends.front();
  return sim.data().lines[e.line].state.x.col(e.station);
}

TEST(LiveSystemSimulation, WithNoControlRepeatsTheRunRowByRow) {
  // Stepped row by row (0.5 s), the live system takes the run's steps (StepSystemSpan from
  // the same initial LineData, the same inputs: a zero offset adds exactly zero): equal to round-off.
  const SceneDef scene = Spread(6.0);
  const MemorySystemRun run = RunSystemInMemory(scene, BuildSystem(scene), nullptr);
  ASSERT_TRUE(run.run.summary.completed) << run.run.summary.failure;
  LiveSystemSimulation sim(scene);
  ASSERT_EQ(sim.line_count(), static_cast<int>(run.lines.size()));
  const long rows = run.rows.rows;
  ASSERT_EQ(rows, 13);
  double worst_x = 0, worst_t = 0;
  for (long r = 1; r < rows; ++r) {
    sim.Advance(0.5);
    ASSERT_NEAR(sim.t(), 0.5 * r, 1e-12);
    for (int i = 0; i < sim.line_count(); ++i) {
      const MemoryRows& rr = run.lines[i].rows;
      const LineData& d = sim.data().lines[i];
      const long n = d.state.x.size(), s = d.tension().size();
      for (long k = 0; k < n; ++k)
        worst_x = std::max(worst_x, std::abs(d.state.x.data()[k] - rr.x[r * n + k]));
      for (long k = 0; k < s; ++k)
        worst_t = std::max(worst_t, std::abs(d.tension()[k] - rr.tension[r * s + k]));
    }
  }
  // Round-off only: 1e-9 m of stations 500 m out, 1e-6 N of tensions of ~1e5 N.
  EXPECT_LT(worst_x, 1e-9);
  EXPECT_LT(worst_t, 1e-6);
}

TEST(LiveSystemSimulation, FramesAgreeWithTheRunWithinTheStepErrorControl) {
  // At the live view's pace (1/30 s frames), the adaptive step lands elsewhere than the run's:
  // the two differ by the error control's tolerance (1e-6 of the longest line, 0.55 mm, per
  // step) accumulated over the steps. 5 mm and 1 % of the line's largest tension bound it
  // with room (measured: well under both).
  const SceneDef scene = Spread(4.0);
  const MemorySystemRun run = RunSystemInMemory(scene, BuildSystem(scene), nullptr);
  LiveSystemSimulation sim(scene);
  for (int k = 0; k < 120; ++k) sim.Advance(1.0 / 30);
  ASSERT_NEAR(sim.t(), 4.0, 1e-9);
  const long r = 8;
  for (int i = 0; i < sim.line_count(); ++i) {
    const MemoryRows& rr = run.lines[i].rows;
    const LineData& d = sim.data().lines[i];
    const long n = d.state.x.size(), s = d.tension().size();
    double worst_x = 0, worst_t = 0;
    for (long k = 0; k < n; ++k)
      worst_x = std::max(worst_x, std::abs(d.state.x.data()[k] - rr.x[r * n + k]));
    for (long k = 0; k < s; ++k)
      worst_t = std::max(worst_t, std::abs(d.tension()[k] - rr.tension[r * s + k]));
    std::printf("line %d: |dx| %.3g m, |dT| %.3g N of %.4g N\n", i, worst_x, worst_t,
                d.tension().maxCoeff());
    EXPECT_LT(worst_x, 5e-3);
    EXPECT_LT(worst_t, 0.01 * d.tension().maxCoeff());
  }
}

TEST(LiveSystemSimulation, AnOffsetMovesTheFairleadsByItAfterItsRamp) {
  const SceneDef scene = Spread(60.0);
  const Model scene_sys = BuildSystem(scene);  // the scene's own motions: the truth
  LiveSystemSimulation sim(scene), still(scene);
  ASSERT_TRUE(sim.has_vessel());
  EXPECT_EQ(sim.carried_points().size(), 3u);  // the three fairleads, not the clump, no anchor
  for (int k = 0; k < 30; ++k) {  // 1 s, then the offset
    sim.Advance(1.0 / 30);
    still.Advance(1.0 / 30);
  }
  ASSERT_TRUE(sim.SetOffsetX(-6.0));  // towards anchors 2 and 3: leg 1 tightens
  ASSERT_TRUE(sim.SetOffsetZ(2.0));
  // The ramps: max(5 s, 15/8 x 6 m / 2 m/s = 5.6 s) and 5 s.
  const double ramp_end = 1.0 + 1.875 * 6.0 / 2.0;
  Vec mid = Vec::Zero();
  while (sim.t() < ramp_end + 1.0 - 1e-9) {
    sim.Advance(1.0 / 30);
    still.Advance(1.0 / 30);
    if (std::abs(sim.t() - (1.0 + 0.5 * 1.875 * 6.0 / 2.0)) < 1.0 / 60) mid = sim.offset_now();
  }
  // Half way through its ramp the smootherstep is at half the change.
  EXPECT_NEAR(mid.x(), -3.0, 0.15);
  const Vec offset = sim.offset_now();
  EXPECT_DOUBLE_EQ(offset.x(), -6.0);
  EXPECT_DOUBLE_EQ(offset.z(), 2.0);
  for (const char* name : {"fairlead1", "fairlead2", "fairlead3"}) {
    const int p = PointIndex(sim.run().sys, name);
    const Vec want = scene_sys.points[p].motion.Position(sim.t()) + Vec(-6.0, 0.0, 2.0);
    EXPECT_LT((PointNow(sim, p) - want).norm(), 1e-9) << name;
    EXPECT_LT((PointNow(still, p) - (want - Vec(-6.0, 0.0, 2.0))).norm(), 1e-9) << name;
  }
  for (const char* name : {"anchor1", "anchor2", "anchor3"}) {
    const int p = PointIndex(sim.run().sys, name);
    EXPECT_LT((PointNow(sim, p) - scene_sys.points[p].motion.rest()).norm(), 1e-12) << name;
  }
  // Away from anchor 1 (at +x): its leg pulls harder than without the offset, legs 2 and 3
  // (towards -x) less; over one period of the ship's motion (12 s), after the clump has
  // followed (the fairlead tensions' means: the orbit's part averages out).
  double with[4] = {}, without[4] = {};
  const int frames = 12 * 30;
  for (int k = 0; k < 10 * 30 + frames; ++k) {
    sim.Advance(1.0 / 30);
    still.Advance(1.0 / 30);
    if (k < 10 * 30) continue;
    for (int i = 1; i < 4; ++i) {
      const Eigen::VectorXd& a = sim.data().lines[i].tension();
      const Eigen::VectorXd& b = still.data().lines[i].tension();
      with[i] += a[a.size() - 1] / frames;
      without[i] += b[b.size() - 1] / frames;
    }
  }
  std::printf("fairlead tensions with/without the offset: %.0f/%.0f, %.0f/%.0f, %.0f/%.0f N\n",
              with[1], without[1], with[2], without[2], with[3], without[3]);
  EXPECT_GT(with[1], without[1]);  // leg1_upper
  EXPECT_LT(with[2], without[2]);  // leg2
  EXPECT_LT(with[3], without[3]);  // leg3
  // The time series' row has as many fields as its header has columns.
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  const std::string header = sim.timeseries_header();
  sim.WriteTimeseriesRow(f);
  std::rewind(f);
  char row[8192] = {};
  ASSERT_NE(std::fgets(row, sizeof row, f), nullptr);
  std::fclose(f);
  const auto fields = [](const std::string& s) { return std::count(s.begin(), s.end(), ',') + 1; };
  EXPECT_EQ(fields(header), fields(row));
  EXPECT_EQ(fields(header), 7 + 2 * 4 + 6 * 7);  // 4 lines, 7 points
  EXPECT_EQ(header.rfind("t,current,current_heading,offset_x,offset_z,force_x,force_z,"
                         "tension_max_leg1_lower,", 0),
            0u);
}

TEST(LiveSystemSimulation, TheCurrentHeadingControlTurnsTheCurrent) {
  LiveSystemSimulation sim(Spread(60.0));
  EXPECT_NEAR(sim.current_heading_now(), 30.0, 1e-9);  // the scene's current_heading
  ASSERT_TRUE(sim.SetCurrentHeading(120.0));
  ASSERT_TRUE(sim.SetCurrent(1.0));
  for (int k = 0; k < 6 * 30; ++k) sim.Advance(1.0 / 30);  // past the 5 s ramp
  EXPECT_NEAR(sim.current_heading_now(), 120.0, 1e-9);
  EXPECT_NEAR(sim.current_now(), 1.0, 1e-12);
  const double a = 120.0 * M_PI / 180.0;
  for (const LineData& d : sim.data().lines) {  // every line's water flows that way
    EXPECT_NEAR(d.water.current_direction.x(), std::cos(a), 1e-12);
    EXPECT_NEAR(d.water.current_direction.z(), std::sin(a), 1e-12);
    EXPECT_NEAR(d.water.current, 1.0, 1e-12);
  }
  Snapshot snap;
  sim.TakeSnapshot(&snap);  // the picture's arrow: the top of the profile, 1 + 0.5 m/s
  EXPECT_NEAR(snap.current.x(), 1.5 * std::cos(a), 1e-9);
  EXPECT_NEAR(snap.current.z(), 1.5 * std::sin(a), 1e-9);
  ASSERT_EQ(snap.lines.size(), 4u);
  // A restart: the scene's sea and state again.
  sim.Restart();
  EXPECT_EQ(sim.t(), 0.0);
  EXPECT_NEAR(sim.current_heading_now(), 30.0, 1e-9);
}

TEST(LiveSystemSimulation, RefusesWhatASystemDoesNotHave) {
  LiveSystemSimulation spread(Spread(60.0));
  EXPECT_FALSE(spread.SetAmplitudeScale(2.0));
  EXPECT_FALSE(spread.SetPeriod(10.0));
  EXPECT_FALSE(spread.SetWaveHeight(1.0));  // no [waves]
  EXPECT_FALSE(spread.SetOffsetX(std::nan("")));
  // A free body: no vessel to offset.
  const std::unique_ptr<LivePhysics> platform = MakeLivePhysics(Scene("floating_platform.toml"));
  EXPECT_TRUE(platform->is_system());
  EXPECT_FALSE(platform->has_vessel());
  EXPECT_FALSE(platform->SetOffsetX(1.0));
  EXPECT_FALSE(spread.has_free_body());
  EXPECT_FALSE(spread.SetForceX(1e5));
}

// `cablefilm live` passes its Ctrl-C flag to the statics, which a system's (a relaxation, or a
// fuzzed file's long line) can make last seconds: raised, the simulation is not built. A
// line's and a system's alike; with the flag down, both are.
TEST(LivePhysics, RaisedStopFlagStopsTheStatics) {
  CancelFlag stop{0};
  for (const char* name : {"floating_platform.toml", "polachek1963.toml"}) {
    EXPECT_NE(MakeLivePhysics(Scene(name), &stop), nullptr) << name;
    stop = 2;  // SIGINT
    try {
      MakeLivePhysics(Scene(name), &stop);
      ADD_FAILURE() << name << ": built with the flag raised";
    } catch (const CancelledError& e) {
      EXPECT_NE(std::string(e.what()).find("equilibrium"), std::string::npos) << e.what();
    }
    stop = 0;
  }
}

TEST(LiveSystemSimulation, AForcePushesAFreeBodyAlongIt) {
  // The floating platform (a free body on three legs, released 5 m and 3 degrees from its
  // equilibrium): with no control it repeats its run (the scene's force plus exactly zero);
  // an extra force along +x moves it along +x against its legs, and along nothing else much.
  SceneDef scene = Scene("floating_platform.toml");
  scene.simulation.duration = 2.0;
  const MemorySystemRun run = RunSystemInMemory(scene, BuildSystem(scene), nullptr);
  LiveSystemSimulation sim(scene), still(scene);
  ASSERT_TRUE(sim.has_free_body());
  for (long r = 1; r < run.rows.rows; ++r) {
    sim.Advance(0.1);
    still.Advance(0.1);
    for (int k = 0; k < 6; ++k)
      ASSERT_NEAR(sim.data().bodies[0].q[k], run.rows.body_pose[r * 6 + k], 1e-12) << r;
  }
  // The force: up to the sum of the lines' largest tensions at the start.
  EXPECT_GT(sim.force_max(), 1e5);
  ASSERT_TRUE(sim.SetForceX(1e5));
  for (int k = 0; k < 20 * 30; ++k) {
    sim.Advance(1.0 / 30);
    still.Advance(1.0 / 30);
  }
  EXPECT_EQ(sim.force_now().x(), 1e5);
  EXPECT_EQ(sim.run().sys.bodies[0].force.x(), 2e5 + 1e5);  // the scene's 2e5 N wind and it
  const Vec6 dq = sim.data().bodies[0].q - still.data().bodies[0].q;
  std::printf("the platform moved %.3f m along x, %.3f m along z\n", dq[0], dq[2]);
  EXPECT_GT(dq[0], 0.1);
  EXPECT_LT(std::abs(dq[2]), 0.1 * dq[0]);
  sim.Restart();
  EXPECT_EQ(sim.force_now().x(), 0.0);
  EXPECT_EQ(sim.run().sys.bodies[0].force.x(), 2e5);
}

TEST(LiveSystemControl, OffsetsAreASystemsAndAmplitudeIsNot) {
  ControlLimits system;
  system.system = true;
  system.has_driven_end = false;
  system.has_vessel = true;
  system.offset_max = 25;
  const ControlRequest r = ParseControl(R"({"offset_x": -6, "offset_z": 2.5})", system);
  EXPECT_EQ(*r.offset_x, -6.0);
  EXPECT_EQ(*r.offset_z, 2.5);
  auto refusal = [](const std::string& body, const ControlLimits& l) {
    try {
      ParseControl(body, l);
    } catch (const ControlError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(refusal(R"({"offset_x": 26})", system),
            "offset_x: expected a number in [-25, 25] m (the vessel's offset from the scene's "
            "position), got 26");
  EXPECT_EQ(refusal(R"({"offset_z": "far"})", system).rfind("offset_z: expected a number", 0), 0u);
  EXPECT_EQ(refusal(R"({"amplitude_scale": 1})", system).rfind("amplitude_scale: not a control of a system", 0), 0u);
  EXPECT_EQ(refusal(R"({"period": 10})", system).rfind("period: not a control of a system", 0), 0u);
  ControlLimits line;
  EXPECT_EQ(refusal(R"({"offset_x": 1})", line).rfind("offset_x: a system's control", 0), 0u);
  ControlLimits free_body = system;
  free_body.has_vessel = false;
  EXPECT_EQ(refusal(R"({"offset_x": 1})", free_body).rfind("offset_x: the system has no vessel", 0), 0u);
  EXPECT_NE(refusal(R"({"ofset_x": 1})", system).find("camera, offset_x, offset_z, force_x, force_z"),
            std::string::npos);
  EXPECT_EQ(refusal(R"({"force_x": 1})", system).rfind("force_x: the system has no free body", 0), 0u);
  ControlLimits platform = free_body;
  platform.has_free_body = true;
  platform.force_max = 3e5;
  EXPECT_EQ(*ParseControl(R"({"force_z": -2e5})", platform).force_z, -2e5);
  EXPECT_EQ(refusal(R"({"force_x": 4e5})", platform),
            "force_x: expected a number in [-300000, 300000] N (an extra steady force on the free "
            "bodies), got 400000");
  EXPECT_EQ(refusal(R"({"force_z": 1})", line).rfind("force_z: a system's control", 0), 0u);
}

}  // namespace
}  // namespace cablefilm
