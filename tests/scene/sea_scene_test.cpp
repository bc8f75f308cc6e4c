// An irregular sea as a scene gives it: [waves] with a spectrum, a table or a record, the keys
// refused where they do not belong, a recorded elevation reproduced at its point, and an end
// following the sea through its RAOs (x_rao pairs at every frequency, or a table by heading and
// frequency): a one-row table is the x_rao pair, and the end's motion is the sum of RAO x
// component over the components.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/sea_components.h"
#include "core/waves.h"
#include "scene/build_model.h"
#include "scene/scene_loader.h"

namespace cablefilm {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A scene of one chain from the bed to a fairlead that follows the waves, with `waves` as its
// [waves] table and `fairlead` the fairlead's motion keys.
std::string Scene(const std::string& waves, const std::string& fairlead) {
  return R"(title = "sea"
[environment]
fluid_density = 1025.0
[seabed]
y = -100.0
[waves]
)" + waves + R"(
[[material]]
name = "chain"
diameter = 0.137
area = 0.01465
mass_per_length = 115.0
youngs_modulus = 3.365e10
[cable]
[[cable.section]]
material = "chain"
length = 550.0
segments = 40
[ends.start]
position = [-500.0, -100.0]
[ends.end]
position = [0.0, -10.0]
motion = "wave"
)" + fairlead + R"(
[simulation]
duration = 60.0
[output]
film = false
)";
}

// A folder of its own for the test's files.
std::filesystem::path Folder(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("cablefilm_sea_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string Expect(const std::string& text, const std::string& file) {
  try {
    ParseScene(text, file);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(SeaScene, KeysBelongToTheirSea) {
  const std::string f = "scenes/sea.toml";
  const std::string jonswap = "spectrum = \"jonswap\"\nhs = 6.0\ntp = 10.0";
  const SceneDef s = ParseScene(Scene(jonswap, "y_rao = [1.0, 0.0]"), f);
  EXPECT_EQ(s.waves.sea, SeaKind::kJonswap);
  EXPECT_EQ(s.waves.height, 6.0);
  EXPECT_EQ(s.waves.period, 10.0);
  EXPECT_NEAR(s.waves.gamma, DnvJonswapGamma(6.0, 10.0), 1e-15);  // DNV's rule by default
  EXPECT_EQ(s.waves.components_made->size(), 200);
  EXPECT_EQ(s.waves.ramp_rate, 0.4);  // 4 / Tp
  struct Bad {
    std::string waves, key, says;
  } bad[] = {
      {jonswap + "\nheight = 2.0", "waves.height", "regular wave's"},
      {"height = 2.0\nperiod = 8.0\nhs = 2.0", "waves.hs", "irregular sea"},
      {jonswap + "\nband = [0.8, 0.5]", "waves.band", "0 < lowest < highest"},
      {jonswap + "\nseed = -1", "waves.seed", "from 0"},
      {jonswap + "\ncomponents = 0", "waves.components", "from 1"},
      {jonswap + "\ngamma = 0.5", "waves.gamma", "from 1 to 10"},
      {"spectrum = \"jonswap\"\nhs = 60.0\ntp = 5.0", "waves.hs", "Miche"},
      {"spectrum = \"table\"\nfile = \"none.csv\"", "waves.file", "none.csv"},
      {"spectrum = \"record\"\nfile = \"r.csv\"\nseed = 2", "waves.seed", "record's are its own"},
      {"spectrum = \"swell\"", "waves.spectrum", "jonswap"},
  };
  for (const Bad& b : bad) {
    const std::string message = Expect(Scene(b.waves, "y_rao = [1.0, 0.0]"), f);
    EXPECT_NE(message.find(f), std::string::npos) << message;
    EXPECT_NE(message.find(b.key), std::string::npos) << message;
    EXPECT_NE(message.find(b.says), std::string::npos) << message;
  }
}

// A record made of components at its own Fourier frequencies is reproduced at its point, at
// every sample, to round-off (the transform is exact there): 1e-9 m of a metre's waves.
TEST(SeaScene, RecordIsReproducedAtItsPoint) {
  const auto dir = Folder("record");
  const double dt = 0.5, n = 400;  // 200 s
  std::ofstream csv(dir / "eta.csv");
  csv << "t,eta\n";
  std::vector<double> eta;
  for (int i = 0; i < n; ++i) {
    const double t = 10 + i * dt;  // starting at 10 s: the phase must carry t0
    const double e = 0.3 + 0.8 * std::cos(2 * kPi * 9 * (t - 10) / (n * dt) + 0.4) +
                     0.5 * std::sin(2 * kPi * 23 * (t - 10) / (n * dt)) +
                     0.01 * std::cos(2 * kPi * 61 * (t - 10) / (n * dt) - 2);
    eta.push_back(e - 0.3);  // the mean is left out: the still water level stays
    char row[64];
    std::snprintf(row, sizeof row, "%.17g,%.17g\n", t, e);
    csv << row;
  }
  csv.close();
  const std::string file = (dir / "sea.toml").string();
  const SceneDef s = ParseScene(
      Scene("spectrum = \"record\"\nfile = \"eta.csv\"\nrecord_point = [40.0, -15.0]\n"
            "heading = 25.0\nramp_rate = 1e6",
            "y_rao = [1.0, 0.0]"),
      file);
  EXPECT_EQ(s.waves.components_made->size(), 3);
  EXPECT_NEAR(s.waves.period, 200.0 / 9, 1e-9);  // the largest component's
  EXPECT_NEAR(s.waves.components_made->repeat_period, 200.0, 1e-9);
  const Wave wave = MakeWave(MakeWaveSpec(s), s.environment.gravity);
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    const double t = 10 + i * dt;
    // The ramp of 1e6 / s is 1 within microseconds: after 1 s, 1 - 1e-400000.
    if (t < 11) continue;
    worst = std::max(worst, std::abs(SurfaceAt(wave, Vec(40.0, 0.0, -15.0), t) - eta[i]));
  }
  EXPECT_LT(worst, 1e-9);
}

// A one-row RAO table is the x_rao pair: the end's motion the same to round-off, in the regular
// wave; in a sea, a table of a heave RAO falling with frequency moves the end by the sum over
// the components of r(omega_i) a_i cos(theta_i(x0, t) + p(omega_i)), computed here from the
// components (1e-9 m), and its variance is sum r^2 a^2 / 2 (the motion's spectrum is |RAO|^2
// S) within the sampling error of three hours (3 x 3 %, as the elevation's in sea_test.cpp).
TEST(SeaScene, EndFollowsTheSeaThroughItsRaos) {
  const auto dir = Folder("rao");
  {
    std::ofstream one(dir / "one.csv");
    one << "heading,omega,x,x_phase,y,y_phase,z,z_phase\n0,0.6283185307179586,0.5,90,0.8,-20,0,0\n";
    std::ofstream falling(dir / "falling.csv");
    falling << "# heave falls from 1 to 0 between 0.4 and 1.2 rad/s, lagging more\n"
               "heading,omega,x,x_phase,y,y_phase,z,z_phase\n"
               "0,0.4,0,0,1.0,0,0,0\n0,0.8,0,0,0.6,-30,0,0\n0,1.2,0,0,0.0,-60,0,0\n"
               "90,0.4,0,0,1.0,0,0,0\n90,1.2,0,0,0.0,-60,0,0\n";
  }
  const std::string file = (dir / "sea.toml").string();
  const std::string regular = "height = 4.0\nperiod = 10.0\nheading = 0.0";
  const SceneDef pairs =
      ParseScene(Scene(regular, "x_rao = [0.5, 90.0]\ny_rao = [0.8, -20.0]"), file);
  const SceneDef table = ParseScene(Scene(regular, "rao_file = \"one.csv\""), file);
  const EndMotion a = MakeEndMotion(pairs.points[1].motion);
  const EndMotion b = MakeEndMotion(table.points[1].motion);
  for (double t : {0.0, 3.0, 17.5, 55.0}) EXPECT_LE((a.Position(t) - b.Position(t)).norm(), 1e-12);
  EXPECT_GT(a.Position(17.5).norm() - Vec(0.0, -10.0, 0.0).norm(), -5.0);  // it moves

  const std::string sea = "spectrum = \"jonswap\"\nhs = 4.0\ntp = 10.0\nseed = 5\nramp_rate = 1e6";
  const SceneDef s = ParseScene(Scene(sea, "rao_file = \"falling.csv\""), file);
  const SeaComponents& c = *s.waves.components_made;
  const EndMotion end = MakeEndMotion(s.points[1].motion);
  // The RAO at omega by hand: linear between the rows (heading 0 and 90 agree on the sea's 0).
  auto rao = [](double w) {
    if (w <= 0.4) return std::pair<double, double>{1.0, 0.0};
    if (w >= 1.2) return std::pair<double, double>{0.0, -60.0};
    if (w <= 0.8) {
      const double f = (w - 0.4) / 0.4;
      return std::pair<double, double>{1.0 - 0.4 * f, -30.0 * f};
    }
    const double f = (w - 0.8) / 0.4;
    return std::pair<double, double>{0.6 - 0.6 * f, -30.0 - 30.0 * f};
  };
  double variance = 0;
  for (int i = 0; i < c.size(); ++i)
    variance += 0.5 * std::pow(rao(c.omega[i]).first * c.amplitude[i], 2);
  double sum2 = 0, worst = 0;
  long samples = 0;
  for (double t = 2.0; t < 10800; t += 0.5) {
    double y = 0;
    for (int i = 0; i < c.size(); ++i) {
      const auto [r, p] = rao(c.omega[i]);
      y += r * c.amplitude[i] * std::cos(-c.omega[i] * t + c.phase[i] + p * kPi / 180);
    }
    const double moved = end.Position(t)[1] + 10.0;
    worst = std::max(worst, std::abs(moved - y));
    sum2 += moved * moved;
    ++samples;
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_NEAR(sum2 / samples, variance, 3 * 0.03 * variance);
}

}  // namespace
}  // namespace cablefilm
