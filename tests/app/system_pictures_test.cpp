// A system of lines gets its pictures as a line does: max_tension.png (a curve a line) and the
// film (a second, deterministic pass over the system), whose time plot and reported peak are
// the lines' rows: the largest tension_max of any line's timeseries.csv.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.h"
#include "../core/text_support.h"

namespace cablefilm {
namespace {

namespace fs = std::filesystem;

using cablefilm_test::ReadText;
using cablefilm_test::Replace;

struct Row {
  double t, tension_max;
};

// t and tension_max of every row of a line's timeseries.csv.
std::vector<Row> ReadRows(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "t,x_end,y_end,z_end,tension_start,tension_end,tension_max,link_max"
            ",fx_start,fy_start,fz_start,fx_end,fy_end,fz_end,angle_start,angle_end") << p;
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::vector<double> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(std::stod(cell));
    if (cells.size() == 16) rows.push_back({cells[0], cells[6]});
  }
  return rows;
}

class SystemPictures : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cablefilm_system_pictures_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // The clump system (two lines, a free clump between them, a fairlead in orbit) for
  // `duration` s, a row every 0.1 s, a small film of `fps` frames a second.
  std::string Scene(const std::string& duration, const std::string& fps) {
    const fs::path scenes = fs::path(CABLEFILM_SOURCE_DIR) / "tests" / "scenes" / "system";
    std::string text = ReadText(scenes / "clump_system.toml");
    text = Replace(text, "duration = 20.0", "duration = " + duration);
    text = Replace(text, "film = false", "film = true");
    text += "\n[film]\nfps = " + fps + "\nwidth = 320\nheight = 180\n";
    const fs::path p = dir_ / "clump_system.toml";
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  // The largest tension_max of every line's rows, and its time.
  Row Peak() const {
    Row peak{0, -1};
    for (const char* line : {"lower", "upper"})
      for (const Row& r : ReadRows(dir_ / "out" / "lines" / line / "timeseries.csv"))
        if (r.tension_max > peak.tension_max) peak = r;
    return peak;
  }
  fs::path dir_;
};

TEST_F(SystemPictures, FilmAndFigureShowEveryLinesRows) {
  RunOptions o;
  o.out_dir = (dir_ / "out").string();
  o.frames = 1;
  RunReport r;
  ASSERT_EQ(RunCommand(Scene("4.0", "5"), o, &r), 0);
  const fs::path out = dir_ / "out";
  EXPECT_TRUE(fs::exists(out / "film.mp4"));
  EXPECT_TRUE(fs::exists(out / "max_tension.png"));
  EXPECT_FALSE(fs::exists(out / "film.partial.mp4"));
  // 4 s at 5 frames a second: frames at 0, 0.2, ..., 4.0, each a PNG too.
  EXPECT_EQ(r.film.frames, 21);
  int pngs = 0;
  for (const auto& e : fs::directory_iterator(out / "frames"))
    pngs += e.path().extension() == ".png";
  EXPECT_EQ(pngs, 21);
  EXPECT_TRUE(fs::exists(out / "frames" / "frame_000020.png"));
  // The peak: the run's, the CSVs' (10 significant digits), the figure's and the film's.
  const Row csv = Peak();
  std::printf("[ peaks ] run %.10g N at %.4g s; csv %.10g N at %.4g s; figure %.10g N; film "
              "%.10g N at %.4g s\n",
              r.summary.peak, r.summary.peak_t, csv.tension_max, csv.t, r.figure.peak,
              r.film.peak, r.film.peak_t);
  EXPECT_GT(csv.tension_max, 1e4);  // a chain with a 3 t clump: tens of kN
  EXPECT_NEAR(r.summary.peak, csv.tension_max, 1e-9 * csv.tension_max);
  EXPECT_DOUBLE_EQ(r.summary.peak_t, csv.t);
  EXPECT_EQ(r.figure.peak, r.summary.peak);
  EXPECT_EQ(r.film.peak, r.summary.peak);
  EXPECT_EQ(r.film.peak_t, r.summary.peak_t);
  // A frame every 2 rows: the second pass repeats the run step for step, so the last frame's
  // lines are the last row's, bit for bit.
  EXPECT_DOUBLE_EQ(r.film.last_frame_t, 4.0);
  EXPECT_EQ(r.film.last_frame_max, r.film.last_row_max);
  double last = 0;
  for (const char* line : {"lower", "upper"})
    last = std::max(last, ReadRows(out / "lines" / line / "timeseries.csv").back().tension_max);
  EXPECT_NEAR(r.film.last_frame_max, last, 1e-9 * last);
}

TEST_F(SystemPictures, FramesOffTheRowsEndWithAFrameAtTheRunsEnd) {
  // 3 frames a second do not fall on the 0.1 s rows: the pass steps the frames' own grid, and
  // the run's end, 2.1 s, is not a frame (2.0 is the last whole one).
  RunOptions o;
  o.out_dir = (dir_ / "out").string();
  RunReport r;
  ASSERT_EQ(RunCommand(Scene("2.1", "3"), o, &r), 0);
  EXPECT_EQ(r.film.frames, 8);  // 0, 1/3, ..., 2.0 and 2.1
  EXPECT_DOUBLE_EQ(r.film.last_frame_t, 2.1);
  EXPECT_EQ(r.film.peak, r.summary.peak);  // the time plot has every row, not the frames'
  EXPECT_TRUE(fs::exists(dir_ / "out" / "film.mp4"));
}

TEST_F(SystemPictures, NoFilmStillDrawsTheFigure) {
  RunOptions o;
  o.out_dir = (dir_ / "out").string();
  o.film = 0;
  RunReport r;
  ASSERT_EQ(RunCommand(Scene("2.0", "5"), o, &r), 0);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "max_tension.png"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "film.mp4"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "frames"));
  EXPECT_EQ(r.figure.peak, r.summary.peak);
  EXPECT_NEAR(r.figure.peak, Peak().tension_max, 1e-9 * r.figure.peak);
  EXPECT_EQ(r.film.frames, 0);
}

}  // namespace
}  // namespace cablefilm
