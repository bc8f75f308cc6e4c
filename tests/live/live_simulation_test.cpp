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
#include "scene/scene_loader.h"

namespace cablefilm {
namespace {

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
    out.push_back(sim.tensions().maxCoeff());
  }
  return out;
}

TEST(LiveSimulation, RestartReturnsToTheScenesInitialStateAndSea) {
  LiveSimulation sim(P63());
  const State initial = sim.state();
  const Eigen::VectorXd tension = sim.tensions();
  sim.Advance(5.0);
  ASSERT_TRUE(sim.SetCurrent(0.8));
  ASSERT_TRUE(sim.SetAmplitudeScale(2.0));
  ASSERT_TRUE(sim.SetPeriod(7.0));
  sim.Advance(3.0);
  EXPECT_GT((sim.state().x - initial.x).norm(), 0.1);
  sim.Restart();
  EXPECT_EQ(sim.t(), 0.0);
  EXPECT_EQ((sim.state().x - initial.x).norm(), 0.0);
  EXPECT_EQ((sim.state().v - initial.v).norm(), 0.0);
  EXPECT_EQ((sim.tensions() - tension).norm(), 0.0);
  EXPECT_EQ(sim.targets().amplitude_scale, 1.0);
  EXPECT_EQ(sim.targets().period, 10.0);
  EXPECT_EQ(sim.targets().current, 0.0);
  // And it runs as from the start: the same tensions as a fresh simulation 2 s in.
  LiveSimulation fresh(P63());
  sim.Advance(2.0);
  fresh.Advance(2.0);
  EXPECT_LT((sim.tensions() - fresh.tensions()).cwiseAbs().maxCoeff(), 1e-6);
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
  EXPECT_TRUE(sim.state().x.allFinite());
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
  const double x_end = sim.state().x(0, sim.model().line.links), g = sim.model().env.gravity;
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
  EXPECT_TRUE(sim.state().x.allFinite());
  sim.Restart();
  EXPECT_EQ(sim.targets().wave_period, 6.0);
  EXPECT_EQ(sim.wave().spec.period, 6.0);
  EXPECT_EQ(sim.wave().spec.phase, scene.waves.phase);
}

// An end that follows the wave (motion = "wave") follows its period too.
TEST(LiveSimulation, AnEndThatFollowsTheWaveTakesItsPeriod) {
  const SceneDef scene =
      LoadScene(std::string(CABLEFILM_SOURCE_DIR) + "/scenes/grounded_mooring.toml");
  ASSERT_TRUE(scene.end.follows_wave);
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
  scene.end.motion = EndMotionKind::kFixed;
  LiveSimulation sim(scene);
  ASSERT_FALSE(sim.has_driven_end());
  EXPECT_FALSE(sim.SetAmplitudeScale(2.0));  // nothing to scale
  ASSERT_TRUE(sim.SetCurrent(0.5));
  EXPECT_EQ(sim.current_now(), 0.0);  // a ramp, not a step
  sim.Advance(2.5);
  EXPECT_NEAR(sim.current_now(), 0.25, 1e-3);  // half way through the 5 s ramp (sampled mid-step)
  for (int i = 0; i < 600; ++i) sim.Advance(1.0);
  LineModel in_current = sim.model();
  in_current.env.current = 0.5;
  const State expected = SolveLineEquilibrium(in_current);
  // Drag damps the swing geometrically; after 600 s what is left is far below a millimetre.
  EXPECT_LT((sim.state().x - expected.x).cwiseAbs().maxCoeff(), 1e-3);
  // It did move: the current pushes this fairly taut line 0.16 m downstream.
  EXPECT_GT((expected.x - sim.initial_state().x).cwiseAbs().maxCoeff(), 0.1);
}

// The current turned live (issue 19): the short way round, over the current's 5 s ramp, and
// with the fairlead held still a current turned across the line (heading 90 degrees: along +z)
// settles on the static equilibrium in that current as the Newton solver finds it, out of the
// x-y plane.
TEST(LiveSimulation, ACurrentTurnedAcrossSettlesOnTheEquilibriumOutOfThePlane) {
  SceneDef scene = P63();
  scene.end.motion = EndMotionKind::kFixed;
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
  LineModel in_current = sim.model();
  in_current.env.current = 0.5;
  in_current.env.current_direction = Vec(0.0, 0.0, 1.0);
  const State expected = SolveLineEquilibrium(in_current);
  // The heading's direction is (cos 90 deg, 0, sin 90 deg) = (6e-17, 0, 1): the same to 1e-16
  // of the drag. Drag damps the swing geometrically; after 600 s what is left is far below a
  // millimetre.
  EXPECT_LT((sim.state().x - expected.x).cwiseAbs().maxCoeff(), 1e-3);
  // Out of the plane: the line's stations pushed along +z, by more than 0.1 m somewhere.
  const int links = sim.model().line.links;
  EXPECT_EQ(sim.state().x(2, 0), 0.0);
  EXPECT_EQ(sim.state().x(2, links), 0.0);
  EXPECT_GT(expected.x.row(2).maxCoeff(), 0.1);
  for (int j = 1; j < links; ++j) EXPECT_GT(sim.state().x(2, j), 0.0) << "station " << j;
  // Turned to -90 (half a turn: the short way is either way; along -z whichever), the current
  // pushes the line the other way: every inner station's z changes sign, and it settles on the
  // mirror image of the +90 equilibrium (z -> -z, x and y the same), as the solver finds it for
  // a current along -z (to the same 1e-3 m as above).
  const Points at_plus_90 = sim.state().x;
  ASSERT_TRUE(sim.SetCurrentHeading(-90.0));
  EXPECT_NEAR(std::abs(sim.targets().current_heading), 90.0, 1e-12);
  for (int i = 0; i < 600; ++i) sim.Advance(1.0);
  EXPECT_NEAR(std::abs(sim.current_heading_now()), 90.0, 1e-12);
  in_current.env.current_direction = Vec(0.0, 0.0, -1.0);
  const State mirrored = SolveLineEquilibrium(in_current);
  EXPECT_LT((sim.state().x - mirrored.x).cwiseAbs().maxCoeff(), 1e-3);
  for (int j = 1; j < links; ++j) {
    EXPECT_LT(sim.state().x(2, j), 0.0) << "station " << j;
    EXPECT_NEAR(sim.state().x(2, j), -at_plus_90(2, j), 1e-3) << "station " << j;
    EXPECT_NEAR(sim.state().x(1, j), at_plus_90(1, j), 1e-3) << "station " << j;
  }
  EXPECT_LT(sim.state().x.row(2).minCoeff(), -0.1);
  sim.Restart();
  EXPECT_EQ(sim.targets().current_heading, 0.0);
  EXPECT_EQ(sim.current_heading_now(), 0.0);
  EXPECT_EQ(sim.state().x.row(2).cwiseAbs().maxCoeff(), 0.0);
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
  const Vec p = sim.state().x.col(sim.model().line.links);
  auto theta = [&](double t) {  // the model's wave phase at p, t [rad]
    const Wave& w = sim.wave();
    return w.k * w.direction.dot(p) - w.omega * t + w.spec.phase;
  };
  advance(2.0);
  EXPECT_EQ(sim.state().x.row(2).cwiseAbs().maxCoeff(), 0.0);  // in the plane so far
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
  const double z = sim.state().x.row(2).cwiseAbs().maxCoeff();
  std::printf("[ wave heading ] largest |z| 6 s after the waves turned to +z: %.3g m\n", z);
  EXPECT_GT(z, 1e-3);
  EXPECT_TRUE(sim.state().x.allFinite());
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

}  // namespace
}  // namespace cablefilm
