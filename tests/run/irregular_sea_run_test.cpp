// A line in an irregular sea run with its kinematics carried by Taylor's first order from their
// last exact evaluation (the default reach, 0.01: wave_forces.cpp) against the same run with
// every evaluation exact (reach 0): the tensions must agree to within what the carried
// kinematics' error allows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

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
// Measured 2.6e-8 of the peak; bound 1e-4 (a step falling elsewhere would move them by the
// scheme's local error, up to ~1e-3: the bound says it does not).
TEST(IrregularSea, CarriedKinematicsAgreeWithExactOnes) {
  const SceneDef scene = ParseScene(kScene, "scenes/storm.toml");
  auto tensions = [&](double reach) {
    Model model = BuildModel(scene);
    for (LineModel& line : model.lines) line.env.wave.sea_reach = reach;
    CheckModelLimits(scene, model);
    const MemoryRun r = RunInMemory(scene, model, nullptr);
    EXPECT_TRUE(r.run.summary.completed) << r.run.summary.failure;
    return r.lines[0].tension;
  };
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

}  // namespace
}  // namespace cablefilm
