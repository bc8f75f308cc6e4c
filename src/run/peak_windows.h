#pragma once
// The windows of a long run around its highest peaks, for its snap check (app/commands.cpp):
// the run cut into spans of `span_rows` rows, the lines' states kept at each span's start
// (their positions, velocities and stick-slip anchors: a checkpoint), and for the `keep` spans with the highest
// row peaks the checkpoint one span before (the lead-in that carries the ringing into it) and
// the span's end. Refining those windows from their checkpoints measures the peak's
// convergence where the peak is, without running the whole storm again.
#include <memory>
#include <vector>

#include "core/line_data.h"
#include "run/driver.h"
#include "run/run.h"

namespace cablefilm {

struct PeakWindow {
  long first_row = 0, last_row = 0;  // the window: from its checkpoint's row to its span's end
  double peak = 0;                   // the coarse run's highest row tension in its span [N]
  double peak_t = 0;                 // when [s]
  std::vector<State> states;         // each line's at first_row
  std::vector<Points> anchors;       // and its stick-slip anchors (empty: none)
};

class PeakWindows : public RowSink {
 public:
  // Rows of `interval` [s]; spans of span_rows rows; the `keep` highest spans' windows.
  PeakWindows(double interval, long span_rows, int keep);
  long span_rows() const { return span_rows_; }
  int keep() const { return keep_; }
  bool Row(const Data& d) override;
  // The windows, highest peak first (the span still open counted: call after the run).
  std::vector<PeakWindow> Windows() const;

 private:
  void Offer(const PeakWindow& w);  // kept if among the `keep` highest
  PeakWindow Open(long last_row) const;  // the span open now, as a window ending there

  double interval_;
  long span_rows_;
  int keep_;
  std::vector<State> before_, start_;  // the checkpoints of the span before and this one
  std::vector<Points> before_anchors_, start_anchors_;
  long before_row_ = -1, start_row_ = -1;
  double peak_ = -1, peak_t_ = 0;      // this span's so far
  long last_row_ = 0;
  std::vector<PeakWindow> kept_;
};

// The snap check of a long run refines only windows around its highest peaks: spans of
// kPeakSpan [s] (whole rows), the kPeakWindows spans with the highest row peaks, each run again
// from the checkpoint one span before it (the lead-in that brings the ringing of the snaps
// before it). A run of fewer than kLeastSpans spans, or with free bodies (whose motion a
// checkpoint of the lines does not hold), is run again whole.
constexpr double kPeakSpan = 60;
constexpr int kPeakWindows = 3;
constexpr long kLeastSpans = 10;

// The windows' sink for `run`, whose snap check may refine windows; null when it would run
// again whole.
std::unique_ptr<PeakWindows> SnapCheckWindows(const Run& run);

}  // namespace cablefilm
