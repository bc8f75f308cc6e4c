// An irregular sea as a scene gives it: [waves] with a spectrum, a table or a record, the keys
// refused where they do not belong, a recorded elevation reproduced at its point, and an end
// following the sea through its RAOs (x_rao pairs at every frequency, or a table by heading and
// frequency): a one-row table is the x_rao pair, and the end's motion is the sum of RAO x
// component over the components.
#include <gtest/gtest.h>

#include <algorithm>
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
#include "sea_chain_scene.h"

namespace cablefilm {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The chain in a sea of `waves`, its fairlead moving by `fairlead`, for 60 s.
std::string Scene(const std::string& waves, const std::string& fairlead) {
  return SeaChainScene(waves, fairlead, 60.0);
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

// A record's band filters it (the components outside it left out), a record of more
// components than a sea may hold is refused naming waves.file and the band that would take it,
// and a record shorter than the run is said to repeat.
TEST(SeaScene, RecordBandFiltersAndBoundsIt) {
  const auto dir = Folder("record_band");
  const auto write = [&](const std::string& name, int n, double dt) {
    std::ofstream csv(dir / name);
    csv << "t,eta\n";
    for (int i = 0; i < n; ++i) {  // components 9, 23 and 61 of the record's Fourier series
      const double t = i * dt, span = n * dt;
      csv << t << "," << 0.8 * std::cos(2 * kPi * 9 * t / span) +
                             0.5 * std::sin(2 * kPi * 23 * t / span) +
                             0.01 * std::cos(2 * kPi * 61 * t / span) + 1e-3 * std::sin(static_cast<double>(i) * i)
          << "\n";
    }
  };
  write("short.csv", 400, 0.1);  // 40 s: omega_j = 2 pi j / 40 s, 9 -> 1.41, 23 -> 3.61 rad/s
  const std::string file = (dir / "sea.toml").string();
  const std::string record = "spectrum = \"record\"\nfile = \"short.csv\"";
  const SceneDef all = ParseScene(Scene(record, "y_rao = [1.0, 0.0]"), file);
  const SceneDef band = ParseScene(Scene(record + "\nband = [1.0, 2.0]", "y_rao = [1.0, 0.0]"), file);
  EXPECT_GT(all.waves.components_made->size(), 100);  // the noise's 199 (1e-3 m of it)
  ASSERT_EQ(band.waves.components_made->size(), 6);   // j = 7 to 12: 1.10 to 1.88 rad/s
  for (int i = 0; i < 6; ++i) {
    EXPECT_GE(band.waves.components_made->omega[i], 1.0);
    EXPECT_LE(band.waves.components_made->omega[i], 2.0);
  }
  std::vector<std::string> notes, warnings;
  DescribeTables(all, &notes, &warnings);  // 60 s of run, 40 s of record
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("waves.file"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("repeats the record after 40 s"), std::string::npos) << warnings[0];

  write("long.csv", 50000, 0.05);  // 24 999 components, more than 20 000
  const std::string big = "spectrum = \"record\"\nfile = \"long.csv\"";
  const std::string message = Expect(Scene(big, "y_rao = [1.0, 0.0]"), file);
  EXPECT_NE(message.find("waves.file"), std::string::npos) << message;
  EXPECT_NE(message.find("more than 20000"), std::string::npos) << message;
  EXPECT_NE(message.find("band"), std::string::npos) << message;
  EXPECT_EQ(ParseScene(Scene(big + "\nband = [0.2, 2.0]", "y_rao = [1.0, 0.0]"), file)
                .waves.components_made->size(),
            716);  // j = 80 to 795 at 2 pi / 2500 s: ceil(0.2 / d omega) to floor(2 / d omega)
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


// A drift table on a wave-following end (drift_file, joined linearly): the end's motion is the
// waves' plus the table's offsets, by hand at and between its rows; in an irregular sea as in
// the regular wave; its rows are named in check's notes.
TEST(SeaScene, ADriftIsAddedToTheWavesMotion) {
  const auto dir = Folder("drift");
  std::ofstream(dir / "drift.csv") << "t,x,y,z\n0,0,0,0\n300,-20,0.5,6\n600,-20,0.5,6\n";
  const std::string file = (dir / "sea.toml").string();
  for (const std::string& waves :
       {std::string("height = 4.0\nperiod = 10.0"),
        std::string("spectrum = \"jonswap\"\nhs = 4.0\ntp = 10.0\ncomponents = 50")}) {
    SCOPED_TRACE(waves);
    const std::string rao = "x_rao = [0.8, 90.0]\ny_rao = [1.0, 0.0]";
    const SceneDef plain = ParseScene(Scene(waves, rao), file);
    const SceneDef drifting = ParseScene(
        Scene(waves, rao + "\ndrift_file = \"drift.csv\"\ninterpolation = \"linear\""), file);
    const EndMotion a = MakeEndMotion(plain.points[1].motion);
    const EndMotion b = MakeEndMotion(drifting.points[1].motion);
    for (double t : {0.0, 75.0, 300.0, 451.0}) {
      const double f = std::min(t, 300.0) / 300.0;
      const Vec offset(-20.0 * f, 0.5 * f, 6.0 * f);
      EXPECT_LT((b.Position(t) - a.Position(t) - offset).norm(), 1e-12) << t;
      const Vec rate = t <= 300 ? Vec(Vec(-20.0, 0.5, 6.0) / 300.0) : Vec(Vec::Zero());
      EXPECT_LT((b.Velocity(t) - a.Velocity(t) - rate).norm(), 1e-13) << t;
    }
    std::vector<std::string> notes, warnings;
    DescribeTables(drifting, &notes, &warnings);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("drift table drift.csv, 3 rows"), std::string::npos) << notes[0];
    EXPECT_TRUE(warnings.empty());  // at rest at its last row
  }
  // Where a drift_file is not expected, or not readable: named.
  const std::string bad = Expect(
      Scene("height = 4.0\nperiod = 10.0", "y_rao = [1.0, 0.0]\ndrift_file = \"none.csv\""), file);
  EXPECT_NE(bad.find("ends.end.drift_file"), std::string::npos) << bad;
  EXPECT_NE(bad.find("none.csv"), std::string::npos) << bad;
}


// A body's drift turns it too: its angle columns added to the waves' angles (in radians), or
// alone where the waves do not turn it.
TEST(SeaScene, ADriftTurnsABodyToo) {
  EndDef e;
  e.motion = EndMotionKind::kTrochoid;
  e.follows_wave = true;
  e.period = 10.0;
  e.ramp_rate = 0.4;
  e.table = {{0, 0, 0, 0, 0, 0, 0}, {100, 1, 0, 0, 2, 0, -4}};
  e.interpolation = TableInterpolation::kLinear;
  const Vec rest(0.1, 0.0, 0.2);
  const double deg = kPi / 180;
  const EndMotion alone = MakeTurnMotion(e, rest);  // no wave angles: the drift's
  EXPECT_LT((alone.Position(50.0) - rest - Vec(1.0, 0.0, -2.0) * deg).norm(), 1e-15);
  e.rx_amplitudes = {3.0, 0.0};  // 3 degrees of roll in the wave
  const EndMotion both = MakeTurnMotion(e, rest);
  e.table.clear();
  const EndMotion wave = MakeTurnMotion(e, rest);
  EXPECT_LT((both.Position(50.0) - wave.Position(50.0) - Vec(1.0, 0.0, -2.0) * deg).norm(),
            1e-15);
}

}  // namespace
}  // namespace cablefilm
