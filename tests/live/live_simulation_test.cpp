// The physics of a change made while the cable runs (cablefilm live): against the static
// equilibrium solver (a current ramped in settles on the equilibrium in that current), against
// the same run without the change (a small change makes a small difference: no spike from the
// control itself), and against the scene's initial state (restart).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/line_equilibrium.h"
#include "core/waves.h"
#include "live/live_simulation.h"
#include "core/cancel.h"
#include "scene/build_model.h"
#include "run/memory_run.h"
#include "scene/scene_loader.h"

namespace cablefilm {
namespace {

// The state of a live simulation's one line.
const State& LineState(const LiveSimulation& sim) { return sim.data().lines.front().state; }

SceneDef P63() { return LoadScene(std::string(CABLEFILM_SOURCE_DIR) + "/scenes/polachek1963.toml"); }

// P63 under waves of 1 m and 6 s in 60 m of water (L = 56 m), their surface above the
// fairlead's highest point (32.3 m).
void AddWaves(SceneDef& scene) {
  scene.waves.present = true;
  scene.waves.height = 1.0;
  scene.waves.period = 6.0;
  scene.waves.depth = 60.0;
  scene.waves.surface_y = 40.0;
  scene.waves.ramp_rate = 1.0;
}

// The largest link tension at every 1/30 s of [t0, t1] [N].
std::vector<double> MaxTensions(LiveSimulation& sim, double t1) {
  std::vector<double> out;
  while (sim.t() < t1 - 1e-9) {
    sim.Advance(1.0 / 30);
    out.push_back(sim.line_tensions(0).maxCoeff());
  }
  return out;
}

TEST(LiveSimulation, RestartReturnsToTheScenesInitialStateAndSea) {
  LiveSimulation sim(P63());
  const State initial = LineState(sim);
  const Eigen::VectorXd tension = sim.line_tensions(0);
  sim.Advance(5.0);
  ASSERT_TRUE(sim.SetCurrent(0.8));
  ASSERT_TRUE(sim.SetAmplitudeScale(2.0));
  ASSERT_TRUE(sim.SetPeriod(7.0));
  sim.Advance(3.0);
  EXPECT_GT((LineState(sim).x - initial.x).norm(), 0.1);
  sim.Restart();
  EXPECT_EQ(sim.t(), 0.0);
  EXPECT_EQ((LineState(sim).x - initial.x).norm(), 0.0);
  EXPECT_EQ((LineState(sim).v - initial.v).norm(), 0.0);
  EXPECT_EQ((sim.line_tensions(0) - tension).norm(), 0.0);
  EXPECT_EQ(sim.targets().amplitude_scale, 1.0);
  EXPECT_EQ(sim.targets().period, 10.0);
  EXPECT_EQ(sim.targets().current, 0.0);
  // And it runs as from the start: the same tensions as a fresh simulation 2 s in.
  LiveSimulation fresh(P63());
  sim.Advance(2.0);
  fresh.Advance(2.0);
  EXPECT_LT((sim.line_tensions(0) - fresh.line_tensions(0)).cwiseAbs().maxCoeff(), 1e-6);
}

// The waves' height changed live: it ramps over one wave period from the scene's to the new one
// (the model stepped carries it, as the picture's surface does), restart returns to the scene's,
// and a scene without waves refuses it.
TEST(LiveSimulation, WaveHeightRampsOverOnePeriod) {
  SceneDef scene = P63();
  EXPECT_FALSE(LiveSimulation(scene).SetWaveHeight(1.0));
  AddWaves(scene);
  LiveSimulation sim(scene);
  EXPECT_EQ(sim.scene_sea().wave_height, 1.0);
  auto advance = [&](double seconds) {  // frame by frame, as the live view does
    for (int i = 0; i < std::lround(seconds * 30); ++i) sim.Advance(1.0 / 30);
  };
  advance(2.0);
  ASSERT_TRUE(sim.SetWaveHeight(3.0));
  EXPECT_EQ(sim.targets().wave_height, 3.0);
  advance(3.0);  // half-way: the smootherstep's value h(1/2) = 1/2
  EXPECT_NEAR(sim.wave_height_now(), 2.0, 1e-9);
  // Held over each frame at its middle: 1/60 s before the end of a 6 s ramp at its steepest
  // (slope 1.875 x 2 m / 6 s) is 0.01 m short.
  EXPECT_NEAR(sim.wave().spec.height, 2.0, 0.011);
  advance(3.5);
  EXPECT_EQ(sim.wave().spec.height, 3.0);
  EXPECT_EQ(sim.wave().amplitude, 1.5);
  EXPECT_TRUE(LineState(sim).x.allFinite());
  sim.Restart();
  EXPECT_EQ(sim.targets().wave_height, 1.0);
  EXPECT_EQ(sim.wave().spec.height, 1.0);
}

// The waves' period changed live: it ramps over one wave period, each step with the wave number
// of its period (the dispersion relation) and a phase that keeps the wave's phase continuous at
// the driven end (x = 80 m in P63), so there theta(t) = theta(t0) - integral of omega(t) dt,
// omega = 2 pi / T(t), T along the smootherstep. The model takes each frame's omega at the
// frame's middle and carries the phase from one middle to the next: against the exact integral
// that lags by half a frame's worth of the whole change of omega (2 pi (1/6 - 1/9) rad/s x
// 1/60 s = 5.8e-3 rad); bound 0.01 rad. A wave made higher than its breaking height at a
// shorter period is held at that height (Miche: tanh(k h) / 7 of the length).
TEST(LiveSimulation, WavePeriodRampsWithThePhaseKeptAtTheDrivenEnd) {
  SceneDef scene = P63();
  EXPECT_FALSE(LiveSimulation(scene).SetWavePeriod(8.0));
  AddWaves(scene);
  LiveSimulation sim(scene);
  EXPECT_EQ(sim.scene_sea().wave_period, 6.0);
  auto advance = [&](double seconds) {
    for (int i = 0; i < std::lround(seconds * 30); ++i) sim.Advance(1.0 / 30);
  };
  auto theta = [&](double x, double t) {  // the model's wave phase at x, t [rad]
    const Wave& w = sim.wave();
    return w.k * x - w.omega * t + w.spec.phase;
  };
  const double x_end = LineState(sim).x(0, sim.model().lines.front().line.links), g = sim.model().lines.front().env.gravity;
  advance(2.0);
  const double theta0 = theta(x_end, 2.0);
  ASSERT_TRUE(sim.SetWavePeriod(9.0));
  EXPECT_EQ(sim.targets().wave_period, 9.0);
  advance(6.0);  // the ramp: one period of the wave as it was (6 s)
  // The exact integral of omega over the ramp, T(t) = 6 + 3 h((t - 2) / 6) (Simpson, 6000 panels).
  auto omega = [](double t) {
    const double u = std::clamp((t - 2.0) / 6.0, 0.0, 1.0);
    return 2 * M_PI / (6.0 + 3.0 * u * u * u * (10 - 15 * u + 6 * u * u));
  };
  double integral = 0;
  const int n = 6000;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 + 6.0 * i / n, b = 2.0 + 6.0 * (i + 1) / n;
    integral += (b - a) / 6 * (omega(a) + 4 * omega(0.5 * (a + b)) + omega(b));
  }
  const double drift = std::remainder(theta(x_end, 8.0) - (theta0 - integral), 2 * M_PI);
  std::printf("[ wave period ] phase at the driven end after the ramp: %.2e rad from the exact "
              "integral of omega\n", drift);
  EXPECT_LT(std::abs(drift), 0.01);
  advance(0.1);  // past the ramp's end at every step's middle
  EXPECT_EQ(sim.wave().spec.period, 9.0);
  EXPECT_DOUBLE_EQ(sim.wave().omega, 2 * M_PI / 9.0);
  EXPECT_DOUBLE_EQ(sim.wave().k, WaveNumber(2 * M_PI / 9.0, g, 60.0));
  EXPECT_EQ(sim.wave().spec.height, 1.0);
  // Higher, then shorter: at 4 s the wave breaks above tanh(k h) / 7 L (3.56 m here).
  ASSERT_TRUE(sim.SetWaveHeight(7.0));
  advance(9.5);
  EXPECT_EQ(sim.wave().spec.height, 7.0);
  ASSERT_TRUE(sim.SetWavePeriod(4.0));
  advance(9.5);
  const double k4 = WaveNumber(2 * M_PI / 4.0, g, 60.0);
  EXPECT_NEAR(sim.wave().spec.height, std::tanh(k4 * 60.0) / 7.0 * 2 * M_PI / k4, 1e-12);
  EXPECT_TRUE(LineState(sim).x.allFinite());
  sim.Restart();
  EXPECT_EQ(sim.targets().wave_period, 6.0);
  EXPECT_EQ(sim.wave().spec.period, 6.0);
  EXPECT_EQ(sim.wave().spec.phase, scene.waves.phase);
}

// An end that follows the wave (motion = "wave") follows its period too.
TEST(LiveSimulation, AnEndThatFollowsTheWaveTakesItsPeriod) {
  const SceneDef scene =
      LoadScene(std::string(CABLEFILM_SOURCE_DIR) + "/scenes/grounded_mooring.toml");
  ASSERT_TRUE(scene.points[1].motion.follows_wave);
  LiveSimulation sim(scene);
  EXPECT_EQ(sim.targets().period, scene.waves.period);
  ASSERT_TRUE(sim.SetWavePeriod(12.0));
  EXPECT_EQ(sim.targets().wave_period, 12.0);
  EXPECT_DOUBLE_EQ(sim.targets().period, 12.0);
}

// A 2 % change of the amplitude (or of the period, or a small current) part way through case
// P63. A jump of the fairlead's position or velocity would ring the steel wire's axial modes at
// once (EA/l = 3e7 N/m: a 1 mm jump is 30 kN). The ramps start with zero rate and curvature:
// in the first second (a tenth of the 10 s ramp, h(0.1) < 0.9 %) the motion has changed by
// less than 0.02 % of its amplitude, so the tension by a few newtons at most: bound 10 N.
// Over the next 25 s the difference grows as the response follows: about 2 % of the dynamic
// range (7.7 kN peak over a 6.2 kN static maximum: 1.5 kN, so ~30 N) for the amplitude and
// the current (bound 150 N: 5 x the linear estimate); the period change shifts the phase by
// up to 0.049 of a cycle by t = 45 s, 2 x 1.5 kN x sin(pi 0.049) = 460 N (bound 600 N).
TEST(LiveSimulation, SmallChangesMakeSmallDifferencesNoSpike) {
  LiveSimulation base(P63());
  base.Advance(20.0);
  const std::vector<double> reference = MaxTensions(base, 45.0);
  struct Case {
    const char* what;
    bool (LiveSimulation::*set)(double);
    double value, bound;
  };
  for (const Case& c : {Case{"amplitude", &LiveSimulation::SetAmplitudeScale, 1.02, 150},
                        Case{"period", &LiveSimulation::SetPeriod, 10.2, 600},
                        Case{"current", &LiveSimulation::SetCurrent, 0.05, 150}}) {
    LiveSimulation sim(P63());
    sim.Advance(20.0);
    ASSERT_TRUE((sim.*c.set)(c.value)) << c.what;
    const std::vector<double> changed = MaxTensions(sim, 45.0);
    ASSERT_EQ(changed.size(), reference.size());
    double first_second = 0, worst = 0;
    for (std::size_t i = 0; i < changed.size(); ++i) {
      const double d = std::abs(changed[i] - reference[i]);
      worst = std::max(worst, d);
      if (i < 30) first_second = std::max(first_second, d);
    }
    EXPECT_LT(first_second, 10.0) << c.what;
    EXPECT_LT(worst, c.bound) << c.what;
    EXPECT_GT(worst, 1.0) << c.what << ": the change must change something";
  }
}

// With the fairlead held still, a current ramped in from rest damps out through the drag and
// leaves the cable in the static equilibrium of that current, as the Newton solver finds it.
TEST(LiveSimulation, ACurrentRampedInSettlesOnTheEquilibriumInThatCurrent) {
  SceneDef scene = P63();
  scene.points[1].motion.motion = EndMotionKind::kFixed;
  LiveSimulation sim(scene);
  ASSERT_FALSE(sim.has_driven_end());
  EXPECT_FALSE(sim.SetAmplitudeScale(2.0));  // nothing to scale
  ASSERT_TRUE(sim.SetCurrent(0.5));
  EXPECT_EQ(sim.current_now(), 0.0);  // a ramp, not a step
  sim.Advance(2.5);
  EXPECT_NEAR(sim.current_now(), 0.25, 1e-3);  // half way through the 5 s ramp (sampled mid-step)
  for (int i = 0; i < 600; ++i) sim.Advance(1.0);
  LineModel in_current = sim.model().lines.front();
  in_current.env.current = 0.5;
  const State expected = SolveLineEquilibrium(in_current);
  // Drag damps the swing geometrically; after 600 s what is left is far below a millimetre.
  EXPECT_LT((LineState(sim).x - expected.x).cwiseAbs().maxCoeff(), 1e-3);
  // It did move: the current pushes this fairly taut line 0.16 m downstream.
  EXPECT_GT((expected.x - sim.run().initial.lines.front().state.x).cwiseAbs().maxCoeff(), 0.1);
}

// The current turned live (issue 19): the short way round, over the current's 5 s ramp, and
// with the fairlead held still a current turned across the line (heading 90 degrees: along +z)
// settles on the static equilibrium in that current as the Newton solver finds it, out of the
// x-y plane.
TEST(LiveSimulation, ACurrentTurnedAcrossSettlesOnTheEquilibriumOutOfThePlane) {
  SceneDef scene = P63();
  scene.points[1].motion.motion = EndMotionKind::kFixed;
  LiveSimulation sim(scene);
  EXPECT_EQ(sim.scene_sea().current_heading, 0.0);
  // 350 degrees from 0 is 10 degrees clockwise: the target -10, half-way (h(1/2) = 1/2) -5.
  ASSERT_TRUE(sim.SetCurrentHeading(350.0));
  EXPECT_NEAR(sim.targets().current_heading, -10.0, 1e-12);
  EXPECT_EQ(sim.current_heading_now(), 0.0);  // a ramp, not a step
  sim.Advance(2.5);
  EXPECT_NEAR(sim.current_heading_now(), -5.0, 1e-9);
  // On to 90 (from the target -10: 100 degrees anticlockwise), with a current to turn.
  ASSERT_TRUE(sim.SetCurrentHeading(90.0));
  EXPECT_NEAR(sim.targets().current_heading, 90.0, 1e-12);
  ASSERT_TRUE(sim.SetCurrent(0.5));
  for (int i = 0; i < 600; ++i) sim.Advance(1.0);
  EXPECT_NEAR(sim.current_heading_now(), 90.0, 1e-12);
  LineModel in_current = sim.model().lines.front();
  in_current.env.current = 0.5;
  in_current.env.current_direction = Vec(0.0, 0.0, 1.0);
  const State expected = SolveLineEquilibrium(in_current);
  // The heading's direction is (cos 90 deg, 0, sin 90 deg) = (6e-17, 0, 1): the same to 1e-16
  // of the drag. Drag damps the swing geometrically; after 600 s what is left is far below a
  // millimetre.
  EXPECT_LT((LineState(sim).x - expected.x).cwiseAbs().maxCoeff(), 1e-3);
  // Out of the plane: the line's stations pushed along +z, by more than 0.1 m somewhere.
  const int links = sim.model().lines.front().line.links;
  EXPECT_EQ(LineState(sim).x(2, 0), 0.0);
  EXPECT_EQ(LineState(sim).x(2, links), 0.0);
  EXPECT_GT(expected.x.row(2).maxCoeff(), 0.1);
  for (int j = 1; j < links; ++j) EXPECT_GT(LineState(sim).x(2, j), 0.0) << "station " << j;
  // Turned to -90 (half a turn: the short way is either way; along -z whichever), the current
  // pushes the line the other way: every inner station's z changes sign, and it settles on the
  // mirror image of the +90 equilibrium (z -> -z, x and y the same), as the solver finds it for
  // a current along -z (to the same 1e-3 m as above).
  const Points at_plus_90 = LineState(sim).x;
  ASSERT_TRUE(sim.SetCurrentHeading(-90.0));
  EXPECT_NEAR(std::abs(sim.targets().current_heading), 90.0, 1e-12);
  for (int i = 0; i < 600; ++i) sim.Advance(1.0);
  EXPECT_NEAR(std::abs(sim.current_heading_now()), 90.0, 1e-12);
  in_current.env.current_direction = Vec(0.0, 0.0, -1.0);
  const State mirrored = SolveLineEquilibrium(in_current);
  EXPECT_LT((LineState(sim).x - mirrored.x).cwiseAbs().maxCoeff(), 1e-3);
  for (int j = 1; j < links; ++j) {
    EXPECT_LT(LineState(sim).x(2, j), 0.0) << "station " << j;
    EXPECT_NEAR(LineState(sim).x(2, j), -at_plus_90(2, j), 1e-3) << "station " << j;
    EXPECT_NEAR(LineState(sim).x(1, j), at_plus_90(1, j), 1e-3) << "station " << j;
  }
  EXPECT_LT(LineState(sim).x.row(2).minCoeff(), -0.1);
  sim.Restart();
  EXPECT_EQ(sim.targets().current_heading, 0.0);
  EXPECT_EQ(sim.current_heading_now(), 0.0);
  EXPECT_EQ(LineState(sim).x.row(2).cwiseAbs().maxCoeff(), 0.0);
}

// The waves turned live: over one wave period, the short way round, the phase kept at the
// driven end's rest point (80, 30.48, 0) while the crests swing round it: there theta(t) =
// theta(t0) - omega (t - t0) at the constant period, to round-off (bound 1e-9 rad). Turned to
// travel along +z, their particle velocities push the line out of the x-y plane.
TEST(LiveSimulation, WaveHeadingTurnsWithThePhaseKeptAtTheDrivenEnd) {
  SceneDef scene = P63();
  EXPECT_FALSE(LiveSimulation(scene).SetWaveHeading(90.0));
  AddWaves(scene);
  LiveSimulation sim(scene);
  EXPECT_EQ(sim.scene_sea().wave_heading, 0.0);
  auto advance = [&](double seconds) {  // frame by frame, as the live view does
    for (int i = 0; i < std::lround(seconds * 30); ++i) sim.Advance(1.0 / 30);
  };
  const Vec p = LineState(sim).x.col(sim.model().lines.front().line.links);
  auto theta = [&](double t) {  // the model's wave phase at p, t [rad]
    const Wave& w = sim.wave();
    return w.k * w.direction.dot(p) - w.omega * t + w.spec.phase;
  };
  advance(2.0);
  EXPECT_EQ(LineState(sim).x.row(2).cwiseAbs().maxCoeff(), 0.0);  // in the plane so far
  const double theta0 = theta(2.0), omega = sim.wave().omega;
  ASSERT_TRUE(sim.SetWaveHeading(90.0));
  EXPECT_NEAR(sim.targets().wave_heading, 90.0, 1e-12);
  // Half-way through the 6 s ramp, h(1/2) = 1/2: each frame holds the heading of its middle,
  // 1/60 s before the ramp's steepest point (slope 1.875 x (pi/2) / 6 s): 0.008 rad short.
  advance(3.0);
  EXPECT_NEAR(sim.wave().spec.heading, M_PI / 4, 0.01);
  EXPECT_LT(std::abs(std::remainder(theta(5.0) - (theta0 - 3.0 * omega), 2 * M_PI)), 1e-9);
  advance(3.1);  // past the ramp's end at every frame's middle
  EXPECT_DOUBLE_EQ(sim.wave().spec.heading, M_PI / 2);
  EXPECT_NEAR(sim.wave().direction.x(), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(sim.wave().direction.z(), 1.0);
  EXPECT_EQ(sim.wave().omega, omega);  // the period as it was
  EXPECT_LT(std::abs(std::remainder(theta(sim.t()) - (theta0 - (sim.t() - 2.0) * omega),
                                    2 * M_PI)),
            1e-9);
  advance(6.0);
  const double z = LineState(sim).x.row(2).cwiseAbs().maxCoeff();
  std::printf("[ wave heading ] largest |z| 6 s after the waves turned to +z: %.3g m\n", z);
  EXPECT_GT(z, 1e-3);
  EXPECT_TRUE(LineState(sim).x.allFinite());
  // -270 is 90: no turn. -45 from 90 is 135 clockwise (not 225 anticlockwise).
  ASSERT_TRUE(sim.SetWaveHeading(-270.0));
  EXPECT_NEAR(sim.targets().wave_heading, 90.0, 1e-12);
  ASSERT_TRUE(sim.SetWaveHeading(-45.0));
  EXPECT_NEAR(sim.targets().wave_heading, -45.0, 1e-12);
  sim.Restart();
  EXPECT_EQ(sim.targets().wave_heading, 0.0);
  EXPECT_EQ(sim.wave().spec.heading, 0.0);
  EXPECT_EQ(sim.wave().spec.phase, scene.waves.phase);
}

// Scenes of several lines, points and bodies.

SceneDef Scene(const char* name) {
  return LoadScene(std::string(CABLEFILM_SOURCE_DIR) + "/scenes/" + name);
}

// The spread mooring for `seconds` (its rows every 0.5 s).
SceneDef Spread(double seconds) {
  SceneDef scene = Scene("spread_mooring.toml");
  scene.simulation.duration = seconds;
  return scene;
}

int PointIndex(const Model& model, const std::string& name) {
  for (int p = 0; p < static_cast<int>(model.points.size()); ++p)
    if (model.points[p].name == name) return p;
  ADD_FAILURE() << "no point " << name;
  return 0;
}

// Where point p is in the live state [m]: its first line end's station.
Vec PointNow(const LiveSimulation& sim, int p) {
  const LineEnd& e = sim.run().model.points[p].ends.front();
  return sim.data().lines[e.line].state.x.col(e.station);
}

TEST(LiveSimulation, WithNoControlRepeatsTheRunRowByRow) {
  // Stepped row by row (0.5 s), the live view takes the run's steps (StepSpan from
  // the same initial LineData, the same inputs: a zero offset adds exactly zero): equal to round-off.
  const SceneDef scene = Spread(6.0);
  const MemoryRun run = RunInMemory(scene, BuildModel(scene), nullptr);
  ASSERT_TRUE(run.run.summary.completed) << run.run.summary.failure;
  LiveSimulation sim(scene);
  ASSERT_EQ(sim.line_count(), static_cast<int>(run.lines.size()));
  const long rows = run.points.rows;
  ASSERT_EQ(rows, 13);
  double worst_x = 0, worst_t = 0;
  for (long r = 1; r < rows; ++r) {
    sim.Advance(0.5);
    ASSERT_NEAR(sim.t(), 0.5 * r, 1e-12);
    for (int i = 0; i < sim.line_count(); ++i) {
      const MemoryRows& rr = run.lines[i];
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

TEST(LiveSimulation, FramesAgreeWithTheRunWithinTheStepErrorControl) {
  // At the live view's pace (1/30 s frames), the adaptive step lands elsewhere than the run's:
  // the two differ by the error control's tolerance (1e-6 of the longest line, 0.55 mm, per
  // step) accumulated over the steps. 5 mm and 1 % of the line's largest tension bound it
  // with room (measured: well under both).
  const SceneDef scene = Spread(4.0);
  const MemoryRun run = RunInMemory(scene, BuildModel(scene), nullptr);
  LiveSimulation sim(scene);
  for (int k = 0; k < 120; ++k) sim.Advance(1.0 / 30);
  ASSERT_NEAR(sim.t(), 4.0, 1e-9);
  const long r = 8;
  for (int i = 0; i < sim.line_count(); ++i) {
    const MemoryRows& rr = run.lines[i];
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

TEST(LiveSimulation, AnOffsetMovesTheFairleadsByItAfterItsRamp) {
  const SceneDef scene = Spread(60.0);
  const Model scene_sys = BuildModel(scene);  // the scene's own motions: the truth
  LiveSimulation sim(scene), still(scene);
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
    const int p = PointIndex(sim.run().model, name);
    const Vec want = scene_sys.points[p].motion.Position(sim.t()) + Vec(-6.0, 0.0, 2.0);
    EXPECT_LT((PointNow(sim, p) - want).norm(), 1e-9) << name;
    EXPECT_LT((PointNow(still, p) - (want - Vec(-6.0, 0.0, 2.0))).norm(), 1e-9) << name;
  }
  for (const char* name : {"anchor1", "anchor2", "anchor3"}) {
    const int p = PointIndex(sim.run().model, name);
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

TEST(LiveSimulation, TheCurrentHeadingControlTurnsTheCurrent) {
  LiveSimulation sim(Spread(60.0));
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

TEST(LiveSimulation, OffersTheControlsOfWhatTheSceneHas) {
  // The spread mooring: its fairleads move in eq. (3)'s orbit (a driven end: amplitude and
  // period) and are a vessel's (offsets); no waves, no free body.
  LiveSimulation spread(Spread(60.0));
  EXPECT_TRUE(spread.has_driven_end());
  EXPECT_TRUE(spread.has_vessel());
  EXPECT_DOUBLE_EQ(spread.scene_sea().period, 12.0);
  EXPECT_TRUE(spread.SetAmplitudeScale(2.0));
  EXPECT_TRUE(spread.SetPeriod(10.0));
  EXPECT_FALSE(spread.SetWaveHeight(1.0));  // no [waves]
  EXPECT_FALSE(spread.SetOffsetX(std::nan("")));
  EXPECT_FALSE(spread.has_free_body());
  EXPECT_FALSE(spread.SetForceX(1e5));
  // A free body on three legs: no vessel to offset, nothing driven.
  LiveSimulation platform(Scene("floating_platform.toml"));
  EXPECT_GT(platform.line_count(), 1);
  EXPECT_FALSE(platform.has_vessel());
  EXPECT_FALSE(platform.SetOffsetX(1.0));
  EXPECT_FALSE(platform.has_driven_end());
  EXPECT_FALSE(platform.SetAmplitudeScale(2.0));
  EXPECT_TRUE(platform.has_free_body());
  // A line alone whose end moves (P63's ship): its end is a vessel too.
  LiveSimulation p63(Scene("polachek1963.toml"));
  EXPECT_TRUE(p63.has_driven_end());
  EXPECT_TRUE(p63.has_vessel());
  EXPECT_FALSE(p63.has_free_body());
}

// The driven ends' amplitude scales every driven point's orbit: the spread mooring's fairleads
// move by the scale times their scene's offsets from rest, once the ramp (one period) is over.
TEST(LiveSimulation, TheAmplitudeScalesEveryDrivenPoint) {
  const SceneDef scene = Spread(60.0);
  const Model scene_model = BuildModel(scene);  // the scene's own motions: the truth
  LiveSimulation sim(scene);
  ASSERT_TRUE(sim.SetAmplitudeScale(0.5));
  while (sim.t() < 12.0 + 5.0 - 1e-9) sim.Advance(1.0 / 30);
  for (const char* name : {"fairlead1", "fairlead2", "fairlead3"}) {
    const int p = PointIndex(sim.run().model, name);
    const EndMotion& m = scene_model.points[p].motion;
    const Vec want = m.rest() + 0.5 * (m.Position(sim.t()) - m.rest());
    EXPECT_LT((PointNow(sim, p) - want).norm(), 1e-9) << name;
  }
}

// `cablefilm live` passes its Ctrl-C flag to the statics, which can last seconds (a relaxation,
// or a fuzzed file's long line): raised, the simulation is not built; with it down, it is.
TEST(LiveSimulation, RaisedStopFlagStopsTheStatics) {
  CancelFlag stop{0};
  for (const char* name : {"floating_platform.toml", "polachek1963.toml"}) {
    EXPECT_NO_THROW(LiveSimulation(Scene(name), &stop)) << name;
    stop = 2;  // SIGINT
    try {
      LiveSimulation(Scene(name), &stop);
      ADD_FAILURE() << name << ": built with the flag raised";
    } catch (const CancelledError& e) {
      EXPECT_NE(std::string(e.what()).find("equilibrium"), std::string::npos) << e.what();
    }
    stop = 0;
  }
}

TEST(LiveSimulation, AForcePushesAFreeBodyAlongIt) {
  // The floating platform (a free body on three legs, released 5 m and 3 degrees from its
  // equilibrium): with no control it repeats its run (the scene's force plus exactly zero);
  // an extra force along +x moves it along +x against its legs, and along nothing else much.
  SceneDef scene = Scene("floating_platform.toml");
  scene.simulation.duration = 2.0;
  const MemoryRun run = RunInMemory(scene, BuildModel(scene), nullptr);
  LiveSimulation sim(scene), still(scene);
  ASSERT_TRUE(sim.has_free_body());
  for (long r = 1; r < run.points.rows; ++r) {
    sim.Advance(0.1);
    still.Advance(0.1);
    for (int k = 0; k < 6; ++k)
      ASSERT_NEAR(sim.data().bodies[0].q[k], run.points.body_pose[r * 6 + k], 1e-12) << r;
  }
  // The force: up to the sum of the lines' largest tensions at the start.
  EXPECT_GT(sim.force_max(), 1e5);
  ASSERT_TRUE(sim.SetForceX(1e5));
  for (int k = 0; k < 20 * 30; ++k) {
    sim.Advance(1.0 / 30);
    still.Advance(1.0 / 30);
  }
  EXPECT_EQ(sim.force_now().x(), 1e5);
  EXPECT_EQ(sim.run().model.bodies[0].force.x(), 2e5 + 1e5);  // the scene's 2e5 N wind and it
  const Vec6 dq = sim.data().bodies[0].q - still.data().bodies[0].q;
  std::printf("the platform moved %.3f m along x, %.3f m along z\n", dq[0], dq[2]);
  EXPECT_GT(dq[0], 0.1);
  EXPECT_LT(std::abs(dq[2]), 0.1 * dq[0]);
  sim.Restart();
  EXPECT_EQ(sim.force_now().x(), 0.0);
  EXPECT_EQ(sim.run().model.bodies[0].force.x(), 2e5);
}

}  // namespace
}  // namespace cablefilm
