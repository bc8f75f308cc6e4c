#include "view/film_clock.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace cablefilm {

FilmClock::FilmClock(double speed, double fps, const TimeGrid& run, long first, long last_row_)
    : interval(speed / fps),
      start(first * run.interval),
      end(last_row_ * run.interval),
      first_row(first),
      last_row(last_row_) {
  whole = static_cast<long>(std::floor((end - start) / interval + 1e-9));
  last = whole + (end - Time(whole) > 1e-9 * interval ? 1 : 0);
  const double rows = std::round(interval / run.interval);
  on_rows = rows >= 1 && std::fabs(rows * run.interval - interval) <= 1e-9 * interval;
  rows_per_frame = on_rows ? static_cast<long>(rows) : 0;
  steps_per_frame = std::max(1, static_cast<int>(std::ceil(interval / run.dt - 1e-9)));
}

int FilmClock::FrameSteps(long k, const TimeGrid& run) const {
  if (k <= whole) return steps_per_frame;
  const double span = Time(k) - Time(k - 1);
  return std::max(1, static_cast<int>(std::ceil(span / run.dt - 1e-9)));
}

void TakeRows(std::vector<MaxTensionLog::Cursor>& cursors, const std::vector<std::string>& names,
              double until, Snapshot* snap) {
  double t, v;
  while (cursors[0].Next(until, &t, &v)) {
    snap->row_t.push_back(t);
    snap->lines[0].row_max.push_back(v);
  }
  for (std::size_t r = 1; r < cursors.size(); ++r)
    for (std::size_t i = 0; i < snap->row_t.size(); ++i) {
      if (!cursors[r].Next(until, &t, &v) || t != snap->row_t[i])
        throw Error("film: the output rows of " + names[r] + " do not line up with those of " +
                    names[0] + " at t = " + std::to_string(snap->row_t[i]) + " s");
      snap->lines[r].row_max.push_back(v);
    }
}

}  // namespace cablefilm
