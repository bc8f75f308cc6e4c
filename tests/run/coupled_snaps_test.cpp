// A coupled island's explicit windows through snaps, against the same line alone: the shipped
// snapping line (50 links of stiff wire, slack and snapping taut from about 6.5 s) split at its
// middle into two lines of 25 links joined at a free point of no mass. The point is then the
// line's station 25 with the same lumped mass, so the split line is the line: before its snaps
// the coupled implicit step must give the line's tensions; through them it must hand each snap
// to explicit steps as the line's own step does, and its snap loads must be of the explicit
// scheme's kind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "run/memory_run.h"
#include "scene/build_model.h"
#include "scene/scene_loader.h"
#include "scene/scene_parser.h"

namespace cablefilm {
namespace {

const std::string kLine = std::string(CABLEFILM_SOURCE_DIR) + "/scenes/snapping_line.toml";

// snapping_line.toml split at its middle; `extra` goes into [simulation].
std::string SplitLine(const std::string& extra) {
  return R"(title = "Snapping line, split at its middle"
[environment]
gravity = 9.80665
fluid_density = 1025.0
[[material]]
name = "stiff"
diameter = 0.0113
area = 1e-4
mass_per_length = 0.05
youngs_modulus = 2e11
[[point]]
name = "anchor"
position = [0.0, 0.0]
[[point]]
name = "middle"
position = [20.0, 10.0]
motion = "free"
[[point]]
name = "ship"
position = [40.0, 20.0]
motion = "trochoid"
x_amplitudes = [1.0, 0.0]
y_amplitudes = [0.0, 1.0]
period = 5.0
ramp_rate = 0.5
[[line]]
name = "a"
start = "anchor"
end = "middle"
[[line.section]]
material = "stiff"
length = 25.0
segments = 25
[[line]]
name = "b"
start = "middle"
end = "ship"
[[line.section]]
material = "stiff"
length = 25.0
segments = 25
[simulation]
duration = 10.0
time_step = "auto"
)" + extra + R"(
[output]
interval = 0.05
film = false
)";
}

MemoryRun Simulate(const SceneDef& scene) {
  MemoryRun r = RunInMemory(scene, BuildModel(scene), nullptr);
  EXPECT_TRUE(r.run.summary.completed) << r.run.summary.failure;
  return r;
}

SceneDef LineScene(double duration, IntegratorChoice integrator) {
  SceneDef s = LoadScene(kLine);
  s.simulation.duration = duration;
  s.simulation.integrator = integrator;
  return s;
}

// Row r's tension of link j [N].
double Tension(const MemoryRows& rows, long r, int j, int links) {
  return rows.tension[static_cast<std::size_t>(r * links + j)];
}

// Before its first snap (6 s) the split line's tensions at the anchor and at the ship are the
// line's. The line's own default differs from the explicit scheme's there by 0.55 N (of a 65 N
// peak: its step error); the split must add far less than that, a tenth of it at most
// (measured 9e-4 N: round-off and Newton's tolerance, the same steps taken).
TEST(CoupledSnaps, BeforeItsSnapsTheSplitLineIsTheLine) {
  // The split's tolerance is its longest line's share, 25 m x 1e-6 by default: given the
  // line's (50 m x 1e-6) so that both take the same steps.
  SceneDef split = ParseScene(SplitLine("tolerance = 5e-5"), "split.toml");
  split.simulation.duration = 6.0;
  const MemoryRun s = Simulate(split), l = Simulate(LineScene(6.0, IntegratorChoice::kImplicit));
  const MemoryRun e = Simulate(LineScene(6.0, IntegratorChoice::kExplicit));
  ASSERT_EQ(s.lines.size(), 2u);
  ASSERT_EQ(l.lines.front().rows, s.lines[0].rows);
  double split_gap = 0, scheme_gap = 0;
  for (long r = 0; r < l.lines.front().rows; ++r) {
    const double anchor = Tension(l.lines[0], r, 0, 50), ship = Tension(l.lines[0], r, 49, 50);
    split_gap = std::max({split_gap, std::abs(Tension(s.lines[0], r, 0, 25) - anchor),
                          std::abs(Tension(s.lines[1], r, 24, 25) - ship)});
    scheme_gap = std::max({scheme_gap, std::abs(Tension(e.lines[0], r, 0, 50) - anchor),
                           std::abs(Tension(e.lines[0], r, 49, 50) - ship)});
  }
  std::printf("[ split ] to 6 s: split line against the line %.3g N, the line against the "
              "explicit scheme %.3g N (peak %.4g N); steps %ld and %ld\n",
              split_gap, scheme_gap, l.run.summary.peak, s.run.summary.stats.steps,
              l.run.summary.stats.steps);
  EXPECT_EQ(s.run.summary.stats.snap_windows, 0);
  EXPECT_LT(split_gap, 0.1 * scheme_gap);
}

// The RMS of the rows' largest tension from 7 s on, where it snaps [N].
double SnapRms(const MemoryRun& run) {
  double squares = 0;
  int rows = 0;
  for (long r = 0; r < run.lines.front().rows; ++r) {
    if (run.lines.front().time[static_cast<std::size_t>(r)] < 7.0) continue;
    double largest = 0;
    for (const MemoryRows& line : run.lines) {
      const long links = static_cast<long>(line.tension.size()) / line.rows;
      for (long j = 0; j < links; ++j) largest = std::max(largest, Tension(line, r, j, links));
    }
    squares += largest * largest;
    ++rows;
  }
  return std::sqrt(squares / std::max(rows, 1));
}

// Through its snaps the split line (the defaults) hands them to explicit steps, and their loads
// are the explicit scheme's kind: the same measure and bound as the line's own test
// (ExplicitSnaps.SnappingLineDefaultAgainstTheExplicitScheme: a single snap peak is chaotic,
// the RMS over the 60 rows of snaps is steady; the line's default is within 25 % of it).
TEST(CoupledSnaps, TheSplitLineHandsItsSnapsToExplicitSteps) {
  const MemoryRun s = Simulate(ParseScene(SplitLine(""), "split.toml"));
  const MemoryRun e = Simulate(LineScene(10.0, IntegratorChoice::kExplicit));
  const StepStats& stats = s.run.summary.stats;
  std::printf("[ split ] snaps' RMS: split line %.1f N (%ld windows, %ld explicit steps of %ld), "
              "the line in explicit steps %.1f N\n",
              SnapRms(s), stats.snap_windows, stats.explicit_steps, stats.steps, SnapRms(e));
  EXPECT_GT(stats.snap_windows, 0);
  EXPECT_GT(stats.explicit_steps, 0);
  EXPECT_NEAR(SnapRms(s), SnapRms(e), 0.25 * SnapRms(e));
}

}  // namespace
}  // namespace cablefilm
