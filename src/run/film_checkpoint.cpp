#include "run/film_checkpoint.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {
namespace {

// A time [s] as a row of `grid`, rounded by `round` and held within the run's rows (in doubles
// first: a time of 1e9 s over rows of 1e-10 s is no long).
template <class Round>
long RowOf(double t, const TimeGrid& grid, Round round) {
  const double row = round(t / grid.interval);
  return static_cast<long>(std::clamp(std::isfinite(row) ? row : 0.0, 0.0,
                                      static_cast<double>(grid.outputs)));
}

long HalfRows(const FilmWindow& w, const TimeGrid& grid) {
  return RowOf(0.5 * w.peak_width, grid, [](double r) { return std::round(r); });
}

}  // namespace

RowSpan WindowRows(const FilmWindow& w, const TimeGrid& grid, double peak_t) {
  const long outputs = grid.outputs;
  if (w.peak_width > 0) {
    const long half = HalfRows(w, grid);
    const long peak = RowOf(peak_t, grid, [](double r) { return std::round(r); });
    return {std::max(peak - half, 0L), std::min(peak + half, outputs)};
  }
  if (w.end < 0) return {0, outputs};
  return {RowOf(w.start, grid, [](double r) { return std::floor(r + 1e-9); }),
          RowOf(w.end, grid, [](double r) { return std::ceil(r - 1e-9); })};
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
  if (w.peak_width > 0) return AroundPeak(HalfRows(w, grid));
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
