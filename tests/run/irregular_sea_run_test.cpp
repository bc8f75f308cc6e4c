// A line in an irregular sea run with its kinematics carried by Taylor's first order from their
// last exact evaluation (the default reach, 0.01: wave_forces.cpp) against the same run with
// every evaluation exact (reach 0): the tensions must agree to within what the carried
// kinematics' error allows.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/sea_components.h"
#include "run/memory_run.h"
#include "scene/build_model.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"
#include "../scene/sea_chain_scene.h"

namespace cablefilm {
namespace {

// The chain with its fairlead heaving and surging with a JONSWAP sea (Hs 4 m, Tp 10 s), 30 s.
const std::string kScene = SeaChainScene(
    "spectrum = \"jonswap\"\nhs = 4.0\ntp = 10.0\nseed = 2\ncomponents = 100",
    "x_rao = [0.3, 90.0]\ny_rao = [0.4, 0.0]", 30.0, "interval = 0.5");

// The carried kinematics err by at most about (reach)^2 / 2 = 5e-5 of the shortest component's
// part (far less for the energetic ones, whose k and omega are several times smaller), and the
// forces and so the tensions move by as little while the adaptive steps fall where they did.
// Measured 3.4e-8 of the peak; bound 1e-4 (a step falling elsewhere would move them by the
// scheme's local error, up to ~1e-3: the bound says it does not).
// The run's tensions [N], row by row and link by link, with the sea's reach and cutoff given.
std::vector<double> Tensions(const SceneDef& scene, double reach, double cutoff) {
  Model model = BuildModel(scene);
  for (LineModel& line : model.lines) {
    line.env.wave.sea_reach = reach;
    line.env.wave.sea_cutoff = cutoff;
  }
  CheckModelLimits(scene, model);
  const MemoryRun r = RunInMemory(scene, model, nullptr);
  EXPECT_TRUE(r.run.summary.completed) << r.run.summary.failure;
  return r.lines[0].tension;
}

// The largest tension of `reference` and the largest difference of `other` from it [N].
std::pair<double, double> PeakAndWorst(const std::vector<double>& other,
                                       const std::vector<double>& reference) {
  EXPECT_EQ(other.size(), reference.size());
  double peak = 0, worst = 0;
  for (std::size_t i = 0; i < reference.size() && i < other.size(); ++i) {
    peak = std::max(peak, std::abs(reference[i]));
    worst = std::max(worst, std::abs(other[i] - reference[i]));
  }
  return {peak, worst};
}

TEST(IrregularSea, CarriedKinematicsAgreeWithExactOnes) {
  const SceneDef scene = ParseScene(kScene, "scenes/storm.toml");
  const auto [peak, worst] = PeakAndWorst(Tensions(scene, 0.01, 1e-8), Tensions(scene, 0.0, 1e-8));
  std::printf("[ chain in a JONSWAP sea, 30 s ] peak %.1f kN; carried kinematics within %.2e of "
              "it\n", peak / 1e3, worst / peak);
  EXPECT_GT(peak, 1e5);
  EXPECT_LT(worst, 1e-4 * peak);
}

// The components too deep to matter left out of each station's sums (Wave::sea_cutoff, 1e-8 of
// a component's surface part, waves.h) against every component everywhere, both carried at the
// default reach: the chain's tensions move by what 1e-8 of the water's motion moves them, and
// by the carrying's error at its deep stations, carried longer without their short components
// (3.4e-8 above). Measured 3.3e-8 of the peak; bound 1e-6, far under the scheme's own error.
TEST(IrregularSea, ComponentsLeftOutAtDepthChangeNoTension) {
  const SceneDef scene = ParseScene(kScene, "scenes/storm.toml");
  const auto [peak, worst] = PeakAndWorst(Tensions(scene, 0.01, 1e-8), Tensions(scene, 0.01, 0.0));
  std::printf("[ chain in a JONSWAP sea, 30 s ] peak %.1f kN; components left out at depth move "
              "the tensions by %.2e of it\n", peak / 1e3, worst / peak);
  EXPECT_GT(peak, 1e5);
  EXPECT_LT(worst, 1e-6 * peak);
}

// A body driven through RAO tables in a sea, as a run moves it: each row's pose is the sum over
// the components of R(t) r(omega_i) a_i cos(theta_i(x0, t) + p(omega_i)) for its heave and its
// pitch (R the sea's ramp), computed here from the components and the tables by hand (1e-9 m,
// 1e-9 rad: the run's poses are the motion's own doubles). So its motion spectrum is |RAO|^2 S, the component variances
// r^2 a^2 / 2 (its variance over three hours within the sampling error of such a record is
// SeaScene.EndFollowsTheSeaThroughItsRaos's, on the same motion). A chain hangs from it.
TEST(IrregularSea, ABodyFollowsTheSeaThroughItsRaosInARun) {
  const std::string dir = ::testing::TempDir() + "/cablefilm_body_rao_" +
                          std::to_string(::getpid());
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/ship.csv")
      << "heading,omega,x,x_phase,y,y_phase,z,z_phase,rx,rx_phase,ry,ry_phase,rz,rz_phase\n"
         "0,0.4,0,0,1.0,0,0,0,0,0,2.0,90,0,0\n0,0.8,0,0,0.6,-30,0,0,0,0,1.0,60,0,0\n"
         "0,1.2,0,0,0.0,-60,0,0,0,0,0.0,30,0,0\n";
  const std::string text = R"(title = "ship in a sea"
[environment]
fluid_density = 1025.0
[seabed]
y = -100.0
[waves]
spectrum = "jonswap"
hs = 4.0
tp = 10.0
seed = 3
components = 80
ramp_rate = 1e6
[[material]]
name = "chain"
diameter = 0.137
area = 0.01465
mass_per_length = 115.0
youngs_modulus = 3.365e10
[[body]]
name = "ship"
motion = "wave"
position = [0.0, 0.0, 0.0]
rao_file = "ship.csv"
[[point]]
name = "anchor"
position = [-500.0, -100.0, 0.0]
[[point]]
name = "fairlead"
body = "ship"
position = [-20.0, -10.0, 0.0]
[[line]]
name = "chain"
start = "anchor"
end = "fairlead"
[[line.section]]
material = "chain"
length = 550.0
segments = 20
[simulation]
duration = 20.0
[output]
interval = 0.5
film = false
)";
  const SceneDef scene = ParseScene(text, dir + "/ship.toml");
  const SeaComponents& c = *scene.waves.components_made;
  // The tables by hand (linear between rows; beyond them held): amplitude, phase [deg].
  auto table = [](double w, const double (&r)[3], const double (&p)[3]) {
    const double rows[3] = {0.4, 0.8, 1.2};
    if (w <= rows[0]) return std::pair<double, double>{r[0], p[0]};
    if (w >= rows[2]) return std::pair<double, double>{r[2], p[2]};
    const int k = w <= rows[1] ? 0 : 1;
    const double f = (w - rows[k]) / (rows[k + 1] - rows[k]);
    return std::pair<double, double>{r[k] + f * (r[k + 1] - r[k]), p[k] + f * (p[k + 1] - p[k])};
  };
  const double heave_r[3] = {1.0, 0.6, 0.0}, heave_p[3] = {0.0, -30.0, -60.0};
  const double pitch_r[3] = {2.0, 1.0, 0.0}, pitch_p[3] = {90.0, 60.0, 30.0};  // [deg/m], [deg]
  const MemoryRun r = RunInMemory(scene, BuildModel(scene), nullptr);
  ASSERT_TRUE(r.run.summary.completed) << r.run.summary.failure;
  const MemoryPointRows& rows = r.points;
  ASSERT_EQ(rows.rows, 41);
  double worst_heave = 0, worst_pitch = 0, largest = 0;
  for (long row = 0; row < rows.rows; ++row) {
    const double t = 0.5 * row;
    double heave = 0, pitch = 0;
    for (int i = 0; i < c.size(); ++i) {
      const double theta = -c.omega[i] * t + c.phase[i];  // at x0 = 0
      const auto [hr, hp] = table(c.omega[i], heave_r, heave_p);
      const auto [pr, pp] = table(c.omega[i], pitch_r, pitch_p);
      heave += hr * c.amplitude[i] * std::cos(theta + hp * M_PI / 180);
      pitch += pr * c.amplitude[i] * std::cos(theta + pp * M_PI / 180) * M_PI / 180;  // [rad]
    }
    // Eq. (3)'s ramp, R = 1 - (1 + nu t) e^{-nu t} at nu = 1e6 1/s: 0 at t = 0, then 1.
    const double ramp = 1 - (1 + 1e6 * t) * std::exp(-1e6 * t);
    heave *= ramp;
    pitch *= ramp;
    const double* pose = rows.body_pose.data() + row * 6;  // the one body's
    worst_heave = std::max(worst_heave, std::abs(pose[1] - heave));
    worst_pitch = std::max(worst_pitch, std::abs(pose[4] - pitch));
    largest = std::max(largest, std::abs(heave));
  }
  std::printf("[ ship in a JONSWAP sea ] heave up to %.2f m; the run's poses off the sums by "
              "%.2e m in heave, %.2e rad in pitch\n", largest, worst_heave, worst_pitch);
  EXPECT_GT(largest, 0.5);  // Hs 4 m: it moves
  EXPECT_LT(worst_heave, 1e-9);
  EXPECT_LT(worst_pitch, 1e-9);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cablefilm
