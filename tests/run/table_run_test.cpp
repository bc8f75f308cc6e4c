// A motion table driving a run (scene key `interpolation`, the table's last row): a chain with
// axial damping pulled by its fairlead at a steady speed, the table ending while it still
// moves. A run that ends at the table's last row must keep the tension a run going on with the
// motion extended has there (before the fix the last row was a standstill and the damping's
// share of the tension vanished at it); a linear table runs through its kinks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "run/memory_run.h"
#include "scene/build_model.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"
#include "scene_line.h"

namespace cablefilm {
namespace {

// The fairlead's horizontal offset [m]: at rest until 1 s, its speed raised smoothly (C2) to
// v = 0.5 m/s over 1..3 s, steady after: x' = v (3 s^2 / T^2 - 2 s^3 / T^3), s = t - 1, T = 2.
double Pull(double t) {
  const double v = 0.5, T = 2.0;
  if (t <= 1) return 0;
  if (t <= 3) {
    const double s = t - 1;
    return v * (s * s * s / (T * T) - s * s * s * s / (2 * T * T * T));
  }
  return Pull(3.0) + v * (t - 3.0);
}

// Writes the table (rows every `dt` s to `last` s) and a scene running to `duration` s with
// `interpolation`; returns the scene's path.
std::string WriteScene(const std::string& name, double last, double dt, double duration,
                       const std::string& interpolation) {
  const std::string dir = ::testing::TempDir();
  {
    std::ofstream csv(dir + "/" + name + ".csv");
    csv << "t,x,y\n";
    const int rows = static_cast<int>(std::lround(last / dt));
    char line[96];
    for (int i = 0; i <= rows; ++i) {
      std::snprintf(line, sizeof line, "%.17g,%.17g,0\n", i * dt, Pull(i * dt));
      csv << line;
    }
  }
  const std::string path = dir + "/" + name + ".toml";
  std::ofstream toml(path);
  toml << "title = \"chain pulled by a table\"\n"
          "[environment]\ngravity = 9.80665\nfluid_density = 1025.0\n"
          "[[material]]\nname = \"chain\"\ndiameter = 0.137\narea = 0.0295\n"
          "mass_per_length = 126.0\naxial_stiffness = 7.5e8\naxial_damping_ratio = 0.8\n"
          "drag_coefficient = 2.4\n"
          "[cable]\nmodel = \"elastic\"\n"
          "[[cable.section]]\nmaterial = \"chain\"\nlength = 100.0\nsegments = 20\n"
          "[ends.start]\nposition = [0.0, 0.0]\nmotion = \"fixed\"\n"
          "[ends.end]\nposition = [82.0, 50.0]\nmotion = \"table\"\n"
          "file = \"" << name << ".csv\"\n"
          "interpolation = \"" << interpolation << "\"\n"
          "[simulation]\nduration = " << duration << "\n"
          "[output]\ninterval = 0.1\nfilm = false\n";
  return path;
}

// The run's largest tension [N] of every row, the fairlead link's, and its steps.
struct Peaks {
  std::vector<double> t, tension, fairlead;
  long steps = 0;
};

Peaks Simulate(const std::string& path) {
  const SceneDef scene = LoadScene(path);
  const LineModel m = LineOf(scene);
  CheckModelLimits(scene, BuildModel(scene));
  const MemoryRun r = RunInMemory(scene, BuildModel(scene), nullptr);
  EXPECT_TRUE(r.run.summary.completed) << r.run.summary.failure;
  Peaks p;
  p.steps = r.run.summary.stats.steps;
  const int links = m.line.links;
  for (long i = 0; i < r.lines[0].rows; ++i) {
    double top = 0;
    for (int k = 0; k < links; ++k) top = std::max(top, r.lines[0].tension[i * links + k]);
    p.t.push_back(r.lines[0].time[i]);
    p.tension.push_back(top);
    p.fairlead.push_back(r.lines[0].tension[i * links + links - 1]);
  }
  return p;
}

class TableRun : public ::testing::TestWithParam<const char*> {};

TEST_P(TableRun, EndingAtTheLastRowKeepsItsTension) {
  const std::string how = GetParam();
  // Rows every 0.25 s (the linear table's kinks inside the 0.1 s output intervals).
  const Peaks at_end = Simulate(WriteScene("pull_to_10_" + how, 10.0, 0.25, 10.0, how));
  const Peaks beyond = Simulate(WriteScene("pull_to_15_" + how, 15.0, 0.25, 10.5, how));
  ASSERT_EQ(at_end.t.size(), 101u);
  ASSERT_GE(beyond.t.size(), 101u);
  ASSERT_NEAR(at_end.t[100], 10.0, 1e-12);
  ASSERT_NEAR(beyond.t[100], 10.0, 1e-12);
  const double last = at_end.fairlead[100], truth = beyond.fairlead[100];
  std::printf("%s: fairlead tension at the last row (t = 10 s) %.6g N, the run going on %.6g N "
              "(relative difference %.2g), the row before %.6g N; largest tension %.6g N; %ld "
              "steps\n",
              how.c_str(), last, truth, std::abs(last - truth) / truth, at_end.fairlead[99],
              at_end.tension[100], at_end.steps);
  // Up to t = 10 s both runs have the same motion (the rows agree; the steady tail makes the
  // natural splines' second derivatives there zero to round-off, and the linear ones are the
  // same segments) and the same steps, so the same state: the truth is the run going on, to
  // round-off (measured 0; 1e-9 of the tension leaves room for the splines' last bits). Before
  // the fix the last row was a standstill: 247.6 kN against 334.6 kN at the fairlead, the
  // axial damping's share gone.
  EXPECT_NEAR(last, truth, 1e-9 * truth);
  // And the whole history agrees row by row, every link's largest too.
  for (size_t i = 0; i <= 100; ++i) {
    EXPECT_NEAR(at_end.fairlead[i], beyond.fairlead[i], 1e-9 * beyond.tension[i]) << i;
    EXPECT_NEAR(at_end.tension[i], beyond.tension[i], 1e-9 * beyond.tension[i]) << i;
  }
  // The steady pull raises the tension smoothly: the last row continues the rows before it
  // (the extrapolation of rows 98 and 99 within 2 % of the tension; the standstill fell 26 %).
  const double extrapolated = 2 * at_end.fairlead[99] - at_end.fairlead[98];
  EXPECT_NEAR(last, extrapolated, 0.02 * last);
}

INSTANTIATE_TEST_SUITE_P(Interpolations, TableRun, ::testing::Values("spline", "linear"));

TEST(TableRun, CheckWarnsOfARunPastAMovingTablesEnd) {
  std::vector<std::string> notes, warnings;
  DescribeTables(LoadScene(WriteScene("warn_past", 10.0, 0.25, 10.5, "linear")), &notes,
                 &warnings);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("41 rows from t = 0 to 10 s, linear between rows"), std::string::npos)
      << notes[0];
  // The speed at the last row is the pull's: 0.5 m/s.
  EXPECT_NE(notes[0].find("0.5 m/s at its last"), std::string::npos) << notes[0];
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("ends.end: the run goes on to t = 10.5 s, past the table's last "
                             "row at t = 10 s, where it still moves at 0.5 m/s"),
            std::string::npos)
      << warnings[0];
  warnings.clear();
  DescribeTables(LoadScene(WriteScene("warn_at", 10.0, 0.25, 10.0, "spline")), nullptr, &warnings);
  EXPECT_TRUE(warnings.empty());
}

}  // namespace
}  // namespace cablefilm
