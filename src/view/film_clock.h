#pragma once
// When a film's frames are and how its second pass steps a run to them (film_pass.h). Frames are at k x speed / fps and, when
// the run's end falls between two, at its end (so the film shows every row). When a frame is
// a whole number of output rows (the default: a row a frame) the pass steps the run's own grid
// and repeats the first pass step for step (deterministic: a frame's state is its row's);
// otherwise it steps a grid of the frames' own with the run's step rule.
#include <string>
#include <vector>

#include "run/max_tension_log.h"
#include "run/time_grid.h"
#include "view/snapshot.h"

namespace cablefilm {

struct FilmClock {
  FilmClock(double speed, double fps, const TimeGrid& run);

  double interval = 0;      // simulated seconds per frame [s]
  double end = 0;           // the run's end [s]
  long whole = 0;           // frames 0..whole are at k x interval
  long last = 0;            // the last frame: whole, or whole + 1 at the run's end
  bool on_rows = false;     // a frame every rows_per_frame output rows
  long rows_per_frame = 0;  // on_rows

  double Time(long k) const { return k <= whole ? k * interval : end; }  // frame k's [s]
  // on_rows: the output row of frame k (the run's last, `outputs`, for a frame at its end).
  long Row(long k, long outputs) const { return k <= whole ? k * rows_per_frame : outputs; }
  // The grid the pass steps: the run's own on rows, else the frames' (steps no longer than the
  // run's dt, a whole number of them a frame).
  TimeGrid Grid(const TimeGrid& run) const;
  // Not on rows: the steps to the shorter last frame (frame k = last > whole) with the run's
  // step rule.
  int LastFrameSteps(const TimeGrid& run) const;
};

// The output rows (max_tension_log.h) after the previous frame and up to `until` [s] into
// `snap`: the first cursor's times as snap->row_t and each cursor's largest tensions as its
// line's row_max. Every cursor's rows have the same times (a run's lines, or runs of one
// scene); throws Error naming `names` (a name a cursor) where they do not.
void TakeRows(std::vector<MaxTensionLog::Cursor>& cursors, const std::vector<std::string>& names,
              double until, Snapshot* snap);

}  // namespace cablefilm
