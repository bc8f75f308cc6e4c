// The windows of a long run's snap check (run/peak_windows.h): spans of rows, the highest
// spans' row peaks, each window from the checkpoint one span before its span (the lead-in) to
// its span's end, holding the lines' states at its first row.
#include <gtest/gtest.h>

#include <vector>

#include "run/peak_windows.h"

namespace cablefilm {
namespace {

// Rows every 0.5 s, t = 0 to `last` rows, one line of two links whose larger tension is
// `tension(row)` [N]; its first station's x is the row, to tell the checkpoints apart.
std::vector<PeakWindow> WindowsOf(long last, long span_rows, int keep, double (*tension)(long)) {
  PeakWindows windows(0.5, span_rows, keep);
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
    windows.Row(d);
  }
  return windows.Windows();
}

// Spans of 4 rows (2 s): 40 N in span 0 (row 2), 50 N in span 2 (row 9), 70 N in span 4
// (row 18), 10 N elsewhere.
double Peaks(long row) { return row == 2 ? 40 : row == 9 ? 50 : row == 18 ? 70 : 10; }

TEST(PeakWindows, TheHighestSpansFromTheCheckpointBeforeThem) {
  const std::vector<PeakWindow> w = WindowsOf(20, 4, 3, Peaks);
  ASSERT_EQ(w.size(), 3u);
  // Span 4 (rows 16 to 19) from the checkpoint of span 3 (row 12) to row 20.
  EXPECT_EQ(w[0].peak, 70);
  EXPECT_EQ(w[0].peak_t, 9.0);
  EXPECT_EQ(w[0].first_row, 12);
  EXPECT_EQ(w[0].last_row, 20);
  ASSERT_EQ(w[0].states.size(), 1u);
  EXPECT_EQ(w[0].states[0].t, 6.0);
  EXPECT_EQ(w[0].states[0].x(0, 0), 12.0);
  // Span 2 from row 4 to row 12.
  EXPECT_EQ(w[1].peak, 50);
  EXPECT_EQ(w[1].first_row, 4);
  EXPECT_EQ(w[1].last_row, 12);
  EXPECT_EQ(w[1].states[0].x(0, 0), 4.0);
  // Span 0 has no span before it: from its own start.
  EXPECT_EQ(w[2].peak, 40);
  EXPECT_EQ(w[2].first_row, 0);
  EXPECT_EQ(w[2].last_row, 4);
  EXPECT_EQ(w[2].states[0].x(0, 0), 0.0);
  // Two kept: the two highest.
  const std::vector<PeakWindow> two = WindowsOf(20, 4, 2, Peaks);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0].peak, 70);
  EXPECT_EQ(two[1].peak, 50);
}

// A run that ends within a span: that span counts, to the last row.
TEST(PeakWindows, TheSpanOpenAtTheEndCounts) {
  const std::vector<PeakWindow> w = WindowsOf(18, 4, 1, Peaks);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].peak, 70);
  EXPECT_EQ(w[0].first_row, 12);
  EXPECT_EQ(w[0].last_row, 18);
}

// The snap check's choice: a run of at least ten 60 s spans is refined over the 3 windows of
// its highest peaks; a shorter one, or one with free bodies, again whole.
TEST(PeakWindows, ASnapCheckRefinesWindowsOfRunsOfTenSpans) {
  cablefilm::Run run;
  run.grid.interval = 0.5;  // spans of 120 rows
  run.grid.outputs = 10 * 120 - 1;
  EXPECT_EQ(SnapCheckWindows(run), nullptr);
  run.grid.outputs = 10 * 120;
  std::unique_ptr<PeakWindows> w = SnapCheckWindows(run);
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->span_rows(), 120);
  EXPECT_EQ(w->keep(), 3);
  run.grid.interval = 0.7;  // spans of whole rows, at least 60 s: 86 rows
  run.grid.outputs = 860;
  w = SnapCheckWindows(run);
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->span_rows(), 86);
  run.model.free_bodies.push_back(0);  // a free body's motion is not in the lines' checkpoint
  EXPECT_EQ(SnapCheckWindows(run), nullptr);
}

}  // namespace
}  // namespace cablefilm
