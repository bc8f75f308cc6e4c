// The start of a film of part of a run (run/film_checkpoint.h): the rows a window shows, and the
// Data the run keeps for it while it goes, the latest at or before the window's first row.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "run/film_checkpoint.h"

namespace cablefilm {
namespace {

// Rows every 0.5 s, t = 0 to `last` rows, into `sink`: one line of two links whose larger
// tension is `tension(row)` [N]; its first station's x is the row, to tell the Data apart.
void Rows(FilmCheckpoint& sink, long last, double (*tension)(long)) {
  Data d;
  d.lines.resize(1);
  LineData& line = d.lines[0];
  line.forces.tension = Eigen::VectorXd::Zero(2);
  line.state.x = Points::Zero(kDim, 3);
  line.state.v = Points::Zero(kDim, 3);
  for (long row = 0; row <= last; ++row) {
    d.t = line.state.t = 0.5 * row;
    line.state.x(0, 0) = static_cast<double>(row);
    line.forces.tension << 1.0, tension(row);
    sink.Row(d);
  }
}

// The row of the Data kept for a window from `first`, checked to be that row's (-1: none).
long StartRow(const FilmCheckpoint& sink, long first) {
  long row = -1;
  const Data* d = sink.StartFor(first, &row);
  if (!d) return -1;
  EXPECT_EQ(d->lines[0].state.x(0, 0), static_cast<double>(row));
  EXPECT_EQ(d->t, 0.5 * row);
  EXPECT_LE(row, first);
  return row;
}

// 50 N at row 9, the highest, 70 N, at row 29, 10 N elsewhere.
double TwoPeaks(long row) { return row == 9 ? 50 : row == 29 ? 70 : 10; }
double Early(long row) { return row == 2 ? 90 : 10; }
double Late(long row) { return row == 38 ? 90 : 10; }
double Rising(long row) { return static_cast<double>(row); }

TEST(FilmCheckpoint, AroundThePeakItKeepsTheStateBeforeTheWindowsFirstRow) {
  // 4 rows either side of the peak: the state every 4 rows, three held at a time.
  auto kept = [](double (*tension)(long), long first) {
    std::unique_ptr<FilmCheckpoint> sink = FilmCheckpoint::AroundPeak(4);
    Rows(*sink, 40, tension);
    return StartRow(*sink, first);
  };
  EXPECT_EQ(kept(TwoPeaks, 29 - 4), 24);  // kept through the 3 later checkpoints
  EXPECT_EQ(kept(Early, 0), 0);           // the window cut at the run's start
  EXPECT_EQ(kept(Late, 38 - 4), 32);
  EXPECT_EQ(kept(Rising, 40 - 4), 36);    // a new peak every row
}

TEST(FilmCheckpoint, AtARowItKeepsThatRow) {
  std::unique_ptr<FilmCheckpoint> sink = FilmCheckpoint::AtRow(13);
  Rows(*sink, 40, TwoPeaks);
  EXPECT_EQ(StartRow(*sink, 13), 13);
  EXPECT_EQ(StartRow(*sink, 20), 13);
  EXPECT_EQ(StartRow(*sink, 12), -1);  // nothing before: the film steps from the run's start
}

TEST(FilmCheckpoint, TheRowsOfAWindow) {
  TimeGrid grid;
  grid.interval = 0.5;
  grid.outputs = 40;  // 20 s
  FilmWindow span;
  span.start = 1.26;
  span.end = 3.1;
  RowSpan r = WindowRows(span, grid, 7.0);  // its start down to a row, its end up
  EXPECT_EQ(r.first, 2);
  EXPECT_EQ(r.last, 7);
  span.start = 10;
  span.end = 20;  // to the end, exactly
  r = WindowRows(span, grid, 7.0);
  EXPECT_EQ(r.first, 20);
  EXPECT_EQ(r.last, 40);
  FilmWindow peak;
  peak.peak_width = 4;  // 2 s, 4 rows, either side of the peak's row
  r = WindowRows(peak, grid, 7.0);
  EXPECT_EQ(r.first, 10);
  EXPECT_EQ(r.last, 18);
  r = WindowRows(peak, grid, 1.0);  // cut at the start
  EXPECT_EQ(r.first, 0);
  EXPECT_EQ(r.last, 6);
  r = WindowRows(peak, grid, 19.5);  // and at the end
  EXPECT_EQ(r.first, 35);
  EXPECT_EQ(r.last, 40);
  r = WindowRows(FilmWindow{}, grid, 7.0);  // the whole run
  EXPECT_EQ(r.first, 0);
  EXPECT_EQ(r.last, 40);
  // Times of no row a long holds (1e9 s over rows of 1e-10 s), and no peak: within the run.
  TimeGrid fine;
  fine.interval = 1e-10;
  fine.outputs = 100;
  peak.peak_width = 1e9;
  r = WindowRows(peak, fine, std::nan(""));
  EXPECT_EQ(r.first, 0);
  EXPECT_EQ(r.last, 100);
  span.start = 1e8;
  span.end = 1e9;
  r = WindowRows(span, fine, 0.0);
  EXPECT_EQ(r.first, 100);
  EXPECT_EQ(r.last, 100);
}

}  // namespace
}  // namespace cablefilm
