#include "view/film_clock.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace cablefilm {

FilmClock::FilmClock(double speed, double fps, const TimeGrid& run)
    : interval(speed / fps), end(run.end()) {
  whole = static_cast<long>(std::floor(end / interval + 1e-9));
  last = whole + (end - whole * interval > 1e-9 * interval ? 1 : 0);
  const double rows = std::round(interval / run.interval);
  on_rows = rows >= 1 && std::fabs(rows * run.interval - interval) <= 1e-9 * interval;
  rows_per_frame = on_rows ? static_cast<long>(rows) : 0;
}

TimeGrid FilmClock::Grid(const TimeGrid& run) const {
  if (on_rows) return run;
  TimeGrid g = run;
  g.steps_per_output = std::max(1, static_cast<int>(std::ceil(interval / run.dt - 1e-9)));
  g.interval = interval;
  g.dt = interval / g.steps_per_output;
  g.outputs = whole;
  return g;
}

int FilmClock::LastFrameSteps(const TimeGrid& run) const {
  const double span = Time(last) - Time(last - 1);
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
