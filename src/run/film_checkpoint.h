#pragma once
// The film of a span of a run (film.window: T0 to T1, or the seconds around the run's peak)
// without simulating the run twice: while the run goes, this sink keeps a copy of its Data at
// the rows a window may start from (a complete checkpoint, core/data.h: stepped on, it goes on
// exactly as the run did), and the film's pass steps from there (view/film_pass.h).
#include <array>
#include <memory>

#include "core/data.h"
#include "run/driver.h"
#include "run/time_grid.h"
#include "scene/scene_def.h"

namespace cablefilm {

// The output rows a film shows, first to last (inclusive).
struct RowSpan {
  long first = 0, last = 0;
};

// The rows `window` shows of a run of `grid` whose peak row is at peak_t [s]: a span's (its
// start down to a row, its end up to one, within the run), or the half width's rows either side
// of the peak's row (rounded to rows), cut at the run's start and end; the whole run's.
RowSpan WindowRows(const FilmWindow& window, const TimeGrid& grid, double peak_t);

class FilmCheckpoint : public RowSink {
 public:
  // Keeps the Data at row `row` (a window known before the run).
  static std::unique_ptr<FilmCheckpoint> AtRow(long row);
  // Keeps what a window of half_rows rows either side of the run's peak row needs, whatever
  // that row turns out to be: the states at every half_rows rows (three of them held: the
  // newest, the one before, and the one before the highest row so far).
  static std::unique_ptr<FilmCheckpoint> AroundPeak(long half_rows);
  // The checkpoint `window` needs in a run of `grid` (null for the whole run).
  static std::unique_ptr<FilmCheckpoint> For(const FilmWindow& window, const TimeGrid& grid);

  bool Row(const Data& d) override;
  // After the run: the latest Data kept at or before row `first`, and its row (null: none).
  const Data* StartFor(long first, long* row) const;

 private:
  FilmCheckpoint(long stride, long half_rows, long only_row)
      : stride_(stride), half_(half_rows), only_row_(only_row) {}
  void Keep(const Data& d, long row);

  long stride_, half_, only_row_;  // only_row_ >= 0: that row alone
  std::array<Data, 3> slots_;
  std::array<long, 3> slot_row_{-1, -1, -1};
  int newest_ = -1, before_peak_ = -1;  // slots: the latest, and the one the peak needs
  long row_ = 0;
  double peak_ = -1;                    // the highest row tension so far [N]
};

}  // namespace cablefilm
