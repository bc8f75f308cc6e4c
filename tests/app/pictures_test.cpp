// Issue 11, defect 11: what the results and the pictures claim. The run's reported peak, the
// CSV, max_tension.png and the film's time plot come from the same output rows, so they agree
// on the peak even when it falls between film frames; max_tension.png is written by every run.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../core/text_support.h"
#include "app/commands.h"
#include "run/max_tension_log.h"
#include "run/run_summary.h"
#include "core/error.h"

namespace cablefilm {
namespace {

namespace fs = std::filesystem;

using cablefilm_test::ReadText;
using cablefilm_test::Replace;

struct Row {
  double t, tension_max;
};

// t and tension_max of every row of a timeseries.csv.
std::vector<Row> ReadRows(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "t,x_end,y_end,z_end,tension_start,tension_end,tension_max,link_max"
            ",fx_start,fy_start,fz_start,fx_end,fy_end,fz_end,angle_start,angle_end");
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::vector<double> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(std::stod(cell));
    EXPECT_EQ(cells.size(), 16u) << line;
    if (cells.size() == 16) rows.push_back({cells[0], cells[6]});
  }
  return rows;
}

class Pictures : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cablefilm_pictures_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // catenary.toml (a chain released from its straight chord: it falls, snaps taut and
  // whips) with a row every 0.01 s and a film of 2 frames a second: its snap loads peak
  // between the film's frames.
  std::string Scene(const std::string& duration = "2.0") {
    std::string text = ReadText(fs::path(CABLEFILM_SOURCE_DIR) / "scenes" / "catenary.toml");
    text = Replace(text, "interval = 0.05", "interval = 0.01");
    text = Replace(text, "duration = 2.0", "duration = " + duration);
    text = Replace(text, "film = false", "film = true");
    text += "\n[film]\nfps = 2\nwidth = 320\nheight = 180\n";
    const fs::path p = dir_ / "snap.toml";
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  // The clump system (two lines, a free clump between them, a fairlead in orbit) for
  // `duration` s, a row every 0.1 s, a small film of `fps` frames a second.
  std::string ClumpSystem(const std::string& duration, const std::string& fps) {
    const fs::path scenes = fs::path(CABLEFILM_SOURCE_DIR) / "tests" / "scenes" / "system";
    std::string text = ReadText(scenes / "clump_system.toml");
    text = Replace(text, "duration = 20.0", "duration = " + duration);
    text = Replace(text, "film = false", "film = true");
    text += "\n[film]\nfps = " + fps + "\nwidth = 320\nheight = 180\n";
    const fs::path p = dir_ / "clump_system.toml";
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  // The largest tension_max of every line's rows of the clump system, and its time.
  Row SystemPeak() const {
    Row peak{0, -1};
    for (const char* line : {"lower", "upper"})
      for (const Row& r : ReadRows(dir_ / "out" / "lines" / line / "timeseries.csv"))
        if (r.tension_max > peak.tension_max) peak = r;
    return peak;
  }
  fs::path dir_;
};

TEST_F(Pictures, PeakBetweenFilmFramesIsTheSameInTheReportCsvFigureAndFilm) {
  RunOptions o;
  o.out_dir = (dir_ / "out").string();
  RunReport r;
  ASSERT_EQ(RunCommand(Scene(), o, &r), 0);
  const std::vector<Row> rows = ReadRows(dir_ / "out" / "timeseries.csv");
  ASSERT_EQ(rows.size(), 201u);
  EXPECT_EQ(r.summary.rows, 201);
  Row csv_peak{0, -1}, frames_peak{0, -1};
  for (const Row& row : rows) {
    if (row.tension_max > csv_peak.tension_max) csv_peak = row;
    const bool on_a_frame = std::fabs(row.t * 2 - std::round(row.t * 2)) < 1e-9;  // 2 frames/s
    if (on_a_frame && row.tension_max > frames_peak.tension_max) frames_peak = row;
  }
  std::printf("[ peaks ] run %.10g N at t = %.4g s; csv %.10g N at %.4g s; figure %.10g N; "
              "film %.10g N at %.4g s; the frames' rows only %.10g N at %.4g s\n",
              r.summary.peak, r.summary.peak_t, csv_peak.tension_max, csv_peak.t, r.figure.peak, r.film.peak,
              r.film.peak_t, frames_peak.tension_max, frames_peak.t);
  // The case is one the film used to miss: the peak is far above every frame's.
  EXPECT_LT(frames_peak.tension_max, 0.8 * csv_peak.tension_max);
  EXPECT_GT(std::fabs(csv_peak.t * 2 - std::round(csv_peak.t * 2)), 0.01);
  // The report and the CSV (printed to 10 significant digits).
  EXPECT_NEAR(r.summary.peak, csv_peak.tension_max, 1e-9 * csv_peak.tension_max);
  EXPECT_DOUBLE_EQ(r.summary.peak_t, csv_peak.t);
  // The figure and the film's time plot: the very same number.
  EXPECT_EQ(r.figure.peak, r.summary.peak);
  EXPECT_EQ(r.film.peak, r.summary.peak);
  EXPECT_EQ(r.film.peak_t, r.summary.peak_t);
  // A frame every 50 rows: the film's cable is the rows' state, bit for bit (the "now").
  EXPECT_EQ(r.film.frames, 5);
  EXPECT_DOUBLE_EQ(r.film.last_frame_t, 2.0);
  EXPECT_EQ(r.film.last_frame_max, r.film.last_row_max);
  EXPECT_NEAR(r.film.last_frame_max, rows.back().tension_max, 1e-9 * rows.back().tension_max);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "max_tension.png"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "film.mp4"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "max_tension.partial.png"));
}

TEST_F(Pictures, MaxTensionFigureWithoutAFilm) {
  RunOptions o;
  o.out_dir = (dir_ / "out").string();
  o.film = 0;
  RunReport r;
  ASSERT_EQ(RunCommand(Scene(), o, &r), 0);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "max_tension.png"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "film.mp4"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "film.partial.mp4"));
  EXPECT_EQ(r.figure.peak, r.summary.peak);
  EXPECT_GT(r.summary.peak, 1e4);  // the snap loads: tens of kN
  EXPECT_TRUE(std::isnan(r.film.peak));
  EXPECT_EQ(r.film.frames, 0);
}

TEST_F(Pictures, RunEndingBetweenFramesGetsALastFrameAtItsEnd) {
  // 2.2 s at 2 frames a second: frames at 0, 0.5, ..., 2.0 and one more at 2.2, so the film's
  // time plot ends with the run's last row.
  RunOptions o;
  o.out_dir = (dir_ / "out").string();
  RunReport r;
  ASSERT_EQ(RunCommand(Scene("2.2"), o, &r), 0);
  const std::vector<Row> rows = ReadRows(dir_ / "out" / "timeseries.csv");
  ASSERT_EQ(rows.size(), 221u);
  EXPECT_EQ(r.film.frames, 6);
  EXPECT_DOUBLE_EQ(r.film.last_frame_t, 2.2);
  EXPECT_EQ(r.film.last_frame_max, r.film.last_row_max);
  EXPECT_NEAR(r.film.last_frame_max, rows.back().tension_max, 1e-9 * rows.back().tension_max);
  EXPECT_EQ(r.film.peak, r.summary.peak);
  EXPECT_EQ(r.figure.peak, r.summary.peak);
}

TEST_F(Pictures, BlowUpLeavesAPartialFigureOfTheRowsSoFar) {
  // The same chain at 3x the explicit scheme's stability limit blows up part way.
  std::string text = ReadText(Scene());
  text = Replace(text, "time_step = \"auto\"", "integrator = \"explicit\"\ntime_step = 3.4e-3");
  text = Replace(text, "interval = 0.01", "interval = 3.4e-3");
  const fs::path scene = dir_ / "blowup.toml";
  std::ofstream(scene, std::ios::binary) << text;
  RunOptions o;
  o.out_dir = (dir_ / "out").string();
  RunReport r;
  std::string message;
  try {
    RunCommand(scene.string(), o, &r);
  } catch (const Error& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("max_tension.partial.png"), std::string::npos) << message;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "max_tension.partial.png"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "max_tension.png"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "film.mp4"));
  const std::vector<Row> rows = ReadRows(dir_ / "out" / "timeseries.partial.csv");
  ASSERT_GE(rows.size(), 1u);
  EXPECT_EQ(r.summary.rows, static_cast<long>(rows.size()));
  EXPECT_EQ(r.figure.peak, r.summary.peak);
}

TEST_F(Pictures, FigureThatCannotBeDrawnIsAnErrorSayingSo) {
  // A folder (not empty) where max_tension.png goes: the figure cannot be written. The CSV
  // files stand; the run fails with a message naming the figure (before, --no-film skipped
  // the figure silently).
  fs::create_directories(dir_ / "out" / "max_tension.png");
  std::ofstream(dir_ / "out" / "max_tension.png" / "keep") << "not ours\n";
  RunOptions o;
  o.out_dir = (dir_ / "out").string();
  o.film = 0;
  std::string message;
  try {
    RunCommand(Scene(), o);
  } catch (const Error& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("max_tension.png could not be drawn: "), std::string::npos) << message;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "timeseries.csv"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "equilibrium.csv"));
  EXPECT_FALSE(fs::is_regular_file(dir_ / "out" / "max_tension.png"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "max_tension.png" / "keep"));  // left alone
}

TEST(MaxTensionLog, RowsComeBackExactlyInOrderAndTheSummaryHasTheirPeak) {
  MaxTensionLog log;
  RunSummary summary;
  EXPECT_TRUE(std::isnan(summary.peak));
  const int n = 10000;  // beyond one block: some rows in the file, the last ones pending
  // Two rows hold the largest value: the first of them is the peak.
  auto value = [](int i) { return i == 4321 || i == 7000 ? 2000.0 : 1000 + 100 * std::sin(0.37 * i); };
  for (int i = 0; i < n; ++i) {
    log.Append(i * 0.1, value(i));
    Eigen::VectorXd row = Eigen::VectorXd::Constant(7, 500.0);  // the largest in link i % 7
    row[i % 7] = value(i);
    summary.AddRow(i * 0.1, row);
  }
  EXPECT_EQ(log.rows(), n);
  EXPECT_EQ(summary.rows, n);
  EXPECT_EQ(summary.peak, 2000.0);
  EXPECT_EQ(summary.peak_t, 4321 * 0.1);
  EXPECT_EQ(summary.peak_link, 4321 % 7);
  MaxTensionLog::Cursor c(log);
  double t, v;
  int i = 0;
  // Up to a time, then the rest.
  while (c.Next(500.0, &t, &v)) {
    ASSERT_EQ(t, i * 0.1);
    ++i;
  }
  EXPECT_EQ(i, 5001);  // 0 .. 500.0
  EXPECT_FALSE(c.Next(500.0, &t, &v));
  EXPECT_EQ(c.position(), 5001);
  while (c.Next(INFINITY, &t, &v)) {
    ASSERT_EQ(t, i * 0.1);
    ASSERT_EQ(v, value(i));
    ++i;
  }
  EXPECT_EQ(i, n);
  // Moved, it keeps its rows.
  MaxTensionLog moved(std::move(log));
  MaxTensionLog::Cursor again(moved);
  int count = 0;
  while (again.Next(INFINITY, &t, &v)) ++count;
  EXPECT_EQ(count, n);
}

// A system of lines gets its pictures as a line does: max_tension.png (a curve a line) and the
// film (a second, deterministic pass over the system), whose time plot and reported peak are
// the lines' rows: the largest tension_max of any line's timeseries.csv.
TEST_F(Pictures, SeveralLinesFilmAndFigureShowEveryLinesRows) {
  RunOptions o;
  o.out_dir = (dir_ / "out").string();
  o.frames = 1;
  RunReport r;
  ASSERT_EQ(RunCommand(ClumpSystem("4.0", "5"), o, &r), 0);
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
  const Row csv = SystemPeak();
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

TEST_F(Pictures, SeveralLinesFramesOffTheRowsEndWithAFrameAtTheRunsEnd) {
  // 3 frames a second do not fall on the 0.1 s rows: the pass steps the frames' own grid, and
  // the run's end, 2.1 s, is not a frame (2.0 is the last whole one).
  RunOptions o;
  o.out_dir = (dir_ / "out").string();
  RunReport r;
  ASSERT_EQ(RunCommand(ClumpSystem("2.1", "3"), o, &r), 0);
  EXPECT_EQ(r.film.frames, 8);  // 0, 1/3, ..., 2.0 and 2.1
  EXPECT_DOUBLE_EQ(r.film.last_frame_t, 2.1);
  EXPECT_EQ(r.film.peak, r.summary.peak);  // the time plot has every row, not the frames'
  EXPECT_TRUE(fs::exists(dir_ / "out" / "film.mp4"));
}

TEST_F(Pictures, SeveralLinesNoFilmStillDrawsTheFigure) {
  RunOptions o;
  o.out_dir = (dir_ / "out").string();
  o.film = 0;
  RunReport r;
  ASSERT_EQ(RunCommand(ClumpSystem("2.0", "5"), o, &r), 0);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "max_tension.png"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "film.mp4"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "frames"));
  EXPECT_EQ(r.figure.peak, r.summary.peak);
  EXPECT_NEAR(r.figure.peak, SystemPeak().tension_max, 1e-9 * r.figure.peak);
  EXPECT_EQ(r.film.frames, 0);
}

// A window of the run (film.window) is filmed from the state the run kept at its first row (a
// copy of the run's Data, which stepped on goes on as the run did): its frames are the run's
// rows bit for bit, as the whole film's are, and its time plot holds the window's rows alone.
// `rows`: the run's; `first`, `last`: the window's times [s].
void ExpectWindowFilm(const RunReport& r, const std::vector<Row>& rows, double first, double last,
                      long frames) {
  EXPECT_EQ(r.film.frames, frames);
  EXPECT_DOUBLE_EQ(r.film.last_frame_t, last);
  Row in{0, -1}, at_last{0, -1};
  for (const Row& row : rows) {
    if (row.t >= first - 1e-9 && row.t <= last + 1e-9 && row.tension_max > in.tension_max)
      in = row;
    if (std::fabs(row.t - last) < 1e-9) at_last = row;
  }
  ASSERT_GT(at_last.tension_max, 0) << "no row at " << last << " s";
  // The last frame's cable is its row's, bit for bit: the CSV's 10 significant digits.
  EXPECT_NEAR(r.film.last_frame_max, at_last.tension_max, 1e-9 * at_last.tension_max);
  EXPECT_EQ(r.film.last_frame_max, r.film.last_row_max);
  // The time plot: the window's rows, its peak theirs.
  EXPECT_NEAR(r.film.peak, in.tension_max, 1e-9 * in.tension_max);
  EXPECT_DOUBLE_EQ(r.film.peak_t, in.t);
}

// The options of a run into dir/out whose film is the window from `start` to `end` [s].
RunOptions WindowOptions(const fs::path& dir, double start, double end) {
  RunOptions o;
  o.out_dir = (dir / "out").string();
  o.window_given = true;
  o.window.start = start;
  o.window.end = end;
  return o;
}

TEST_F(Pictures, AWindowOfTheRunIsFilmedFromItsStateThere) {
  const RunOptions o = WindowOptions(dir_, 0.5, 1.5);
  RunReport r;
  ASSERT_EQ(RunCommand(Scene(), o, &r), 0);
  const std::vector<Row> rows = ReadRows(dir_ / "out" / "timeseries.csv");
  ASSERT_EQ(rows.size(), 201u);  // the run is whole: only its film is the window
  ExpectWindowFilm(r, rows, 0.5, 1.5, 3);  // frames at 0.5, 1.0 and 1.5 s
  EXPECT_TRUE(fs::exists(dir_ / "out" / "film.mp4"));
}

TEST_F(Pictures, APeakWindowIsTheSecondsAroundTheRunsPeak) {
  // 0.2 s around the peak at 20 frames a second (a frame every 5 rows): the run keeps its state
  // every 10 rows, 20 times over, and the window starts 10 rows before the peak.
  RunOptions o;
  o.out_dir = (dir_ / "out").string();
  o.fps = 20;
  o.window_given = true;
  o.window.peak_width = 0.2;
  RunReport r;
  ASSERT_EQ(RunCommand(Scene(), o, &r), 0);
  const std::vector<Row> rows = ReadRows(dir_ / "out" / "timeseries.csv");
  const double first = std::max(0.0, r.summary.peak_t - 0.1);
  const double last = std::min(2.0, r.summary.peak_t + 0.1);
  std::printf("[ window ] peak %.10g N at %.4g s: frames %.4g to %.4g s\n", r.summary.peak,
              r.summary.peak_t, first, last);
  ASSERT_GT(r.summary.peak_t, 0.2);  // a window the run reaches by its checkpoints
  // A frame every 0.05 s from the first, and one at the last if it falls between two.
  const long whole = std::lround(std::floor((last - first) / 0.05 + 1e-9));
  ExpectWindowFilm(r, rows, first, last, whole + 1 + (last - first - whole * 0.05 > 1e-9));
  EXPECT_EQ(r.film.peak, r.summary.peak);
  EXPECT_EQ(r.film.peak_t, r.summary.peak_t);
}

TEST_F(Pictures, AWindowOffTheRowsStepsItsFramesFromItsFirstRow) {
  // 3 frames a second do not fall on the 0.1 s rows: frames at 1.0, 4/3, 5/3 and 2.0 s, stepped
  // from the clump system's state at its row of 1.0 s (its free clump's motion in it).
  const RunOptions o = WindowOptions(dir_, 1.0, 2.0);
  RunReport r;
  ASSERT_EQ(RunCommand(ClumpSystem("3.0", "3"), o, &r), 0);
  EXPECT_EQ(r.film.frames, 4);
  EXPECT_DOUBLE_EQ(r.film.last_frame_t, 2.0);
  const Row peak = SystemPeak();
  if (peak.t >= 1.0 - 1e-9 && peak.t <= 2.0 + 1e-9) {
    EXPECT_EQ(r.film.peak, r.summary.peak);
  }
  EXPECT_LE(r.film.peak, r.summary.peak);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "film.mp4"));
}

TEST_F(Pictures, AWindowOfASystemIsItsRowsBitForBit) {
  // On the rows (5 frames a second, 0.1 s rows), from the state kept at 1.0 s: the lines and the
  // free clump go on as the run did.
  const RunOptions o = WindowOptions(dir_, 1.0, 2.0);
  RunReport r;
  ASSERT_EQ(RunCommand(ClumpSystem("3.0", "5"), o, &r), 0);
  EXPECT_EQ(r.film.frames, 6);
  EXPECT_DOUBLE_EQ(r.film.last_frame_t, 2.0);
  double at_end = 0;
  for (const char* line : {"lower", "upper"})
    for (const Row& row : ReadRows(dir_ / "out" / "lines" / line / "timeseries.csv"))
      if (std::fabs(row.t - 2.0) < 1e-9) at_end = std::max(at_end, row.tension_max);
  EXPECT_NEAR(r.film.last_frame_max, at_end, 1e-9 * at_end);
}

TEST_F(Pictures, AWindowOutsideTheRunIsRefusedBeforeItRuns) {
  const RunOptions o = WindowOptions(dir_, 1.0, 5.0);
  try {
    RunCommand(Scene(), o, nullptr);
    FAIL() << "a window past the run's end was taken";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "--film-window: expected a window within the run, from 0 to 2 s, got 1 to 5 s"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "out" / "timeseries.csv"));
}

}  // namespace
}  // namespace cablefilm
