#pragma once
// When a film's frames are and how its second pass steps a run to them (film_pass.h). Frames
// are at the film's start (0, or its window's first row) plus k x speed / fps and, when its end
// falls between two, at its end (so the film shows every row). When a frame is a whole number
// of output rows (the default: a row a frame) the pass steps the run's own grid and repeats the
// first pass step for step (deterministic: a frame's state is its row's); otherwise it steps
// the frames with the run's step rule.
#include <string>
#include <vector>

#include "run/max_tension_log.h"
#include "run/time_grid.h"
#include "view/snapshot.h"

namespace cablefilm {

struct FilmClock {
  // The film of the run of grid `run` from row first_row to row last_row (a window of it, or
  // 0 and run.outputs: the whole run).
  FilmClock(double speed, double fps, const TimeGrid& run, long first_row, long last_row);

  double interval = 0;      // simulated seconds per frame [s]
  double start = 0;         // the first frame's time: first_row's [s]
  double end = 0;           // the last frame's: last_row's [s]
  long first_row = 0, last_row = 0;
  long whole = 0;           // frames 0..whole are at start + k x interval
  long last = 0;            // the last frame: whole, or whole + 1 at the end
  bool on_rows = false;     // a frame every rows_per_frame output rows
  long rows_per_frame = 0;  // on_rows
  int steps_per_frame = 0;  // not on rows: a whole frame's steps with the run's step rule

  double Time(long k) const { return k <= whole ? start + k * interval : end; }  // frame k's [s]
  // on_rows: the output row of frame k (last_row for a frame at the end).
  long Row(long k) const { return k <= whole ? first_row + k * rows_per_frame : last_row; }
  // Not on rows: the steps to frame k (k >= 1) with the run's step rule (steps no longer than
  // its dt, a whole number of them a frame; the shorter last frame its own).
  int FrameSteps(long k, const TimeGrid& run) const;
};

// The output rows (max_tension_log.h) after the previous frame and up to `until` [s] into
// `snap`: the first cursor's times as snap->row_t and each cursor's largest tensions as its
// line's row_max. Every cursor's rows have the same times (a run's lines, or runs of one
// scene); throws Error naming `names` (a name a cursor) where they do not.
void TakeRows(std::vector<MaxTensionLog::Cursor>& cursors, const std::vector<std::string>& names,
              double until, Snapshot* snap);

}  // namespace cablefilm
