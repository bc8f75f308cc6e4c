#include "run/film_checkpoint.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {
namespace {

long HalfRows(const FilmWindow& w, double interval) {
  return std::lround(0.5 * w.peak_width / interval);
}

}  // namespace

RowSpan WindowRows(const FilmWindow& w, const TimeGrid& grid, double peak_t) {
  const long outputs = grid.outputs;
  if (w.peak_width > 0) {
    const long half = HalfRows(w, grid.interval);
    const long peak = std::isfinite(peak_t) ? std::lround(peak_t / grid.interval) : 0;
    return {std::clamp(peak - half, 0L, outputs), std::clamp(peak + half, 0L, outputs)};
  }
  if (w.end < 0) return {0, outputs};
  const long first = static_cast<long>(std::floor(w.start / grid.interval + 1e-9));
  const long last = static_cast<long>(std::ceil(w.end / grid.interval - 1e-9));
  return {std::clamp(first, 0L, outputs), std::clamp(last, 0L, outputs)};
}

std::unique_ptr<FilmCheckpoint> FilmCheckpoint::AtRow(long row) {
  return std::unique_ptr<FilmCheckpoint>(new FilmCheckpoint(1, 0, row));
}

std::unique_ptr<FilmCheckpoint> FilmCheckpoint::AroundPeak(long half_rows) {
  return std::unique_ptr<FilmCheckpoint>(
      new FilmCheckpoint(std::max(1L, half_rows), half_rows, -1));
}

std::unique_ptr<FilmCheckpoint> FilmCheckpoint::For(const FilmWindow& w, const TimeGrid& grid) {
  if (w.whole()) return nullptr;
  if (w.peak_width > 0) return AroundPeak(HalfRows(w, grid.interval));
  return AtRow(WindowRows(w, grid, 0).first);
}

void FilmCheckpoint::Keep(const Data& d, long row) {
  int slot = 0;  // not the newest (a peak in the next stride starts from it), not the peak's
  while (slot == newest_ || slot == before_peak_) ++slot;
  slots_[slot] = d;  // the same sizes after the first: no allocation
  slot_row_[slot] = row;
  newest_ = slot;
}

bool FilmCheckpoint::Row(const Data& d) {
  const long row = row_++;
  if (only_row_ >= 0) {
    if (row == only_row_) Keep(d, row);
    return true;
  }
  if (row % stride_ == 0) Keep(d, row);
  double top = 0;  // the row's largest tension, as the run's peak is found [N]
  for (const LineData& l : d.lines)
    if (l.tension().size() > 0) top = std::max(top, l.tension().maxCoeff());
  if (top > peak_) {  // the first row of the highest, as the run's summary keeps it
    peak_ = top;
    const long first = std::max(0L, row - half_);
    before_peak_ = -1;
    for (int s = 0; s < 3; ++s)  // the latest kept at or before the window's first row
      if (slot_row_[s] >= 0 && slot_row_[s] <= first &&
          (before_peak_ < 0 || slot_row_[s] > slot_row_[before_peak_]))
        before_peak_ = s;
  }
  return true;
}

const Data* FilmCheckpoint::StartFor(long first, long* row) const {
  int best = -1;
  for (int s = 0; s < 3; ++s)
    if (slot_row_[s] >= 0 && slot_row_[s] <= first &&
        (best < 0 || slot_row_[s] > slot_row_[best]))
      best = s;
  if (best < 0) return nullptr;
  *row = slot_row_[best];
  return &slots_[best];
}

}  // namespace cablefilm
