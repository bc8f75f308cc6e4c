// A line in an irregular sea run with its kinematics carried by Taylor's first order from their
// last exact evaluation (the default reach, 0.01: wave_forces.cpp) against the same run with
// every evaluation exact (reach 0): the tensions must agree to within what the carried
// kinematics' error allows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
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

TEST(IrregularSea, CarriedKinematicsAgreeWithExactOnes) {
  const SceneDef scene = ParseScene(kScene, "scenes/storm.toml");
  auto tensions = [&](double reach) { return Tensions(scene, reach, 1e-8); };
  const auto carried = tensions(0.01), exact = tensions(0.0);
  ASSERT_EQ(carried.size(), exact.size());
  double peak = 0, worst = 0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    peak = std::max(peak, std::abs(exact[i]));
    worst = std::max(worst, std::abs(carried[i] - exact[i]));
  }
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
  const std::vector<double> cut = Tensions(scene, 0.01, 1e-8), all = Tensions(scene, 0.01, 0.0);
  ASSERT_EQ(cut.size(), all.size());
  double peak = 0, worst = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    peak = std::max(peak, std::abs(all[i]));
    worst = std::max(worst, std::abs(cut[i] - all[i]));
  }
  std::printf("[ chain in a JONSWAP sea, 30 s ] peak %.1f kN; components left out at depth move "
              "the tensions by %.2e of it\n", peak / 1e3, worst / peak);
  EXPECT_GT(peak, 1e5);
  EXPECT_LT(worst, 1e-6 * peak);
}

}  // namespace
}  // namespace cablefilm
