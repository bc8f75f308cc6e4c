// The current over time (environment.current_file): a steady table is the steady current to the
// bit; the statics take the table's current at t = 0; and a current that turns from +x to +z
// leaves a hanging line streaming along +z as the static equilibrium in that current would
// (rotational symmetry about the vertical through its top).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <cstdio>
#include <fstream>
#include <string>

#include "core/error.h"
#include "run/memory_run.h"
#include "scene/build_model.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"

namespace cablefilm {
namespace {

// 60 m of wire rope hanging from a fixed top with a free lower end, in `current` (the body of
// the [environment] table's current keys), for `duration` s.
std::string Scene(const std::string& current, double duration) {
  return R"(title = "streaming wire"
[environment]
fluid_density = 1025.0
)" + current + R"(
[[material]]
name = "wire"
diameter = 0.05
area = 1.5e-3
mass_per_length = 10.0
youngs_modulus = 1.0e11
drag_coefficient = 1.2
[cable]
[[cable.section]]
material = "wire"
length = 60.0
segments = 20
[ends.start]
position = [0.0, 0.0, 0.0]
[ends.end]
position = [0.0, -60.0, 0.0]
motion = "free"
[initial]
state = "equilibrium"
[simulation]
duration = )" + std::to_string(duration) + R"(
[output]
interval = 0.5
film = false
)";
}

// A folder of the test's own (ctest runs the tests at once, each in its own process).
std::filesystem::path Folder() {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("cablefilm_current_history_" +
                    std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

MemoryRun RunScene(const std::string& text, const std::string& file) {
  const SceneDef scene = ParseScene(text, file);
  Model model = BuildModel(scene);
  CheckModelLimits(scene, model);
  MemoryRun r = RunInMemory(scene, std::move(model), nullptr);
  EXPECT_TRUE(r.run.summary.completed) << r.run.summary.failure;
  return r;
}

// A table that holds 0.8 m/s along 30 degrees is that steady current: the same arithmetic
// (1 m/s times 0.8, or 0.8 times 1), the same direction, so the same bits; and rows t,scale,
// heading of 1 and 30 degrees on `current = 0.8` the same.
TEST(CurrentHistory, ASteadyTableIsTheSteadyCurrent) {
  const auto dir = Folder();
  std::ofstream(dir / "speed.csv") << "t,speed,heading\n0,0.8,30\n100,0.8,30\n";
  std::ofstream(dir / "scale.csv") << "t,scale,heading\n0,1,30\n100,1,30\n";
  const std::string file = (dir / "wire.toml").string();
  const MemoryRun steady = RunScene(Scene("current = 0.8\ncurrent_heading = 30.0", 10.0), file);
  const MemoryRun speed = RunScene(Scene("current_file = \"speed.csv\"", 10.0), file);
  const MemoryRun scale =
      RunScene(Scene("current = 0.8\ncurrent_file = \"scale.csv\"", 10.0), file);
  EXPECT_EQ(steady.lines[0].x, speed.lines[0].x);
  EXPECT_EQ(steady.lines[0].tension, speed.lines[0].tension);
  EXPECT_EQ(steady.lines[0].x, scale.lines[0].x);
  // And it streams: the free end 10 m or more downstream (not a still line passing by accident).
  const auto& x = steady.lines[0].x;
  const std::size_t last = x.size() - 3;
  EXPECT_GT(std::hypot(x[last], x[last + 2]), 10.0);
}

// The current turns from +x (0 degrees) to +z (90 degrees) between t = 5 and 25 s at 0.6 m/s,
// then holds. The wire's equilibrium in a current along +z is its equilibrium along +x turned
// by 90 degrees about the vertical through its top: the free end at (0, y0, x0) where it
// started at (x0, y0, 0). The swing the turn starts dies out slowly (the line's sideways
// mode, damped by the drag's linearisation about the current: 8e-3 m left at t = 120 s), so the
// run lasts 480 s; the steady state the implicit scheme holds is the equilibrium itself.
// Measured 9e-12 m at 480 s (the swing decays by 1e-9 in those 360 s); bound 1e-8 m, room for
// rounding and a step sequence another build takes, far below the 8 m it turned.
TEST(CurrentHistory, ATurningCurrentLeavesTheTurnedEquilibrium) {
  const auto dir = Folder();
  std::ofstream(dir / "turn.csv") << "t,speed,heading\n0,0.6,0\n5,0.6,0\n25,0.6,90\n";
  const std::string file = (dir / "wire.toml").string();
  const MemoryRun r = RunScene(Scene("current_file = \"turn.csv\"", 480.0), file);
  const auto& x = r.lines[0].x;
  const std::size_t stations = 21, row = 3 * stations;
  const std::size_t first = row - 3, last = x.size() - 3;  // the free end's, first and last rows
  const double x0 = x[first], y0 = x[first + 1];
  ASSERT_GT(x0, 5.0);                       // streaming along +x at the start
  // The statics took the table's current at t = 0: the steady current's equilibrium, the same
  // solve to the bit.
  const MemoryRun steady = RunScene(Scene("current = 0.6", 1.0), file);
  EXPECT_EQ(x0, steady.lines[0].x[first]);
  EXPECT_EQ(y0, steady.lines[0].x[first + 1]);
  EXPECT_NEAR(x[first + 2], 0.0, 1e-9);     // in the plane
  const double miss = std::sqrt(x[last] * x[last] + (x[last + 1] - y0) * (x[last + 1] - y0) +
                                (x[last + 2] - x0) * (x[last + 2] - x0));
  std::printf("[ turning current ] end from (%.4f, %.4f, 0) m to %.2e m from (0, %.4f, %.4f)\n",
              x0, y0, miss, y0, x0);
  EXPECT_LT(miss, 1e-8);
}

// Bad tables: named by file and key, with what was expected.
TEST(CurrentHistory, BadTablesAreNamed) {
  const auto dir = Folder();
  std::ofstream(dir / "back.csv") << "t,speed,heading\n0,0.5,0\n10,0.5,0\n5,0.5,0\n";
  std::ofstream(dir / "speed.csv") << "t,speed,heading\n0,0.5,0\n";
  std::ofstream(dir / "odd.csv") << "t,speed\n0,0.5\n";
  std::ofstream(dir / "scale.csv") << "t,scale,heading\n0,1,0\n";
  const std::string file = (dir / "wire.toml").string();
  struct Bad {
    std::string keys, key, says;
  } bad[] = {
      {"current_file = \"back.csv\"", "environment.current_file", "t increasing"},
      {"current_file = \"odd.csv\"", "environment.current_file", "t,speed,heading"},
      {"current_file = \"none.csv\"", "environment.current_file", "none.csv"},
      {"current = 0.3\ncurrent_file = \"speed.csv\"", "environment.current", "no current"},
      {"current = [0.3, 0.1]\ncurrent_file = \"scale.csv\"", "environment.current", "[u, w]"},
      {"current_heading = 20.0\ncurrent_file = \"speed.csv\"", "environment.current_heading",
       "heading column"},
  };
  for (const Bad& b : bad) {
    std::string message;
    try {
      ParseScene(Scene(b.keys, 10.0), file);
    } catch (const Error& e) {
      message = e.what();
    }
    EXPECT_NE(message.find("wire.toml"), std::string::npos) << message;
    EXPECT_NE(message.find(b.key), std::string::npos) << message;
    EXPECT_NE(message.find(b.says), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace cablefilm
