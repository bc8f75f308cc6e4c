#include "run/peak_windows.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {

std::unique_ptr<PeakWindows> SnapCheckWindows(const Run& run) {
  const long span = static_cast<long>(std::ceil(kPeakSpan / run.grid.interval - 1e-9));
  if (!run.model.free_bodies.empty() || run.grid.outputs < kLeastSpans * span) return nullptr;
  return std::make_unique<PeakWindows>(run.grid.interval, span, kPeakWindows);
}

PeakWindows::PeakWindows(double interval, long span_rows, int keep)
    : interval_(interval), span_rows_(std::max(1L, span_rows)), keep_(std::max(1, keep)) {}

bool PeakWindows::Row(const Data& d) {
  const long row = std::lround(d.t / interval_);
  last_row_ = row;
  if (start_row_ < 0 || row % span_rows_ == 0) {  // a span starts here
    if (start_row_ >= 0 && row > start_row_) Offer(Open(row));  // the one before it ends
    before_ = std::move(start_);
    before_anchors_ = std::move(start_anchors_);
    before_row_ = start_row_;
    start_.clear();
    start_anchors_.clear();
    for (const LineData& l : d.lines) {
      start_.push_back(l.state);
      start_anchors_.push_back(l.forces.geometry.friction_anchor);
    }
    start_row_ = row;
    peak_ = -1;
  }
  double top = 0;
  for (const LineData& l : d.lines)
    if (l.tension().size() > 0) top = std::max(top, l.tension().maxCoeff());
  if (top > peak_) {
    peak_ = top;
    peak_t_ = d.t;
  }
  return true;
}

PeakWindow PeakWindows::Open(long last_row) const {
  PeakWindow w;
  const bool lead_in = before_row_ >= 0;  // the span before it, where there is one
  w.first_row = lead_in ? before_row_ : start_row_;
  w.last_row = last_row;
  w.peak = peak_;
  w.peak_t = peak_t_;
  w.states = lead_in ? before_ : start_;
  w.anchors = lead_in ? before_anchors_ : start_anchors_;
  return w;
}

void PeakWindows::Offer(const PeakWindow& w) {
  kept_.push_back(w);
  std::sort(kept_.begin(), kept_.end(),
            [](const PeakWindow& a, const PeakWindow& b) { return a.peak > b.peak; });
  if (static_cast<int>(kept_.size()) > keep_) kept_.pop_back();
}

std::vector<PeakWindow> PeakWindows::Windows() const {
  std::vector<PeakWindow> all = kept_;
  if (start_row_ >= 0 && last_row_ > start_row_) all.push_back(Open(last_row_));  // still open
  std::sort(all.begin(), all.end(),
            [](const PeakWindow& a, const PeakWindow& b) { return a.peak > b.peak; });
  if (static_cast<int>(all.size()) > keep_) all.resize(keep_);
  return all;
}

}  // namespace cablefilm
