#pragma once
// The one stepping loop of a run: a Data stepped from output row to output row of its time
// grid, each row (t = 0 first) handed to every sink that wants it (FFmpeg's mux.c: one loop,
// many outputs): the CSV and NetCDF files, the rows in memory, the run's summary, a film's
// frames, a progress line. The live view steps the core itself (StepSpan), paced to the clock.
#include <functional>
#include <string>
#include <vector>

#include "core/data.h"
#include "core/inputs.h"
#include "core/model.h"
#include "run/time_grid.h"

namespace cablefilm {

// Where the rows go. Row() may return false to stop the run there (the rows so far stand).
class RowSink {
 public:
  virtual ~RowSink() = default;
  virtual bool Row(const Data& d) = 0;
};

// A sink of a function (a test's, a front end's own bookkeeping).
class RowFunction : public RowSink {
 public:
  explicit RowFunction(std::function<bool(const Data&)> f) : f_(std::move(f)) {}
  bool Row(const Data& d) override { return f_(d); }

 private:
  std::function<bool(const Data&)> f_;
};

// Steps a Data from row to row of a grid (core/step.h between them), so that several runs can
// go in lockstep (a film of two models).
class RowStepper {
 public:
  RowStepper(const Model& m, Data& d, const Inputs& in, const TimeGrid& grid)
      : m_(m), d_(d), in_(in), grid_(grid), row_(grid.first_output) {}
  long row() const { return row_; }  // the row reached: grid.first_output is the initial state
  bool done() const { return row_ >= grid_.outputs; }
  // Steps to the next row, its time exactly row x interval (every line's; no round-off drift
  // over long runs). Throws BlowUpError, CancelledError (in.stop; the state part way to the
  // row).
  void Next();

 private:
  const Model& m_;
  Data& d_;
  const Inputs& in_;
  const TimeGrid& grid_;
  long row_;
};

// How a run ended.
struct RunEnd {
  bool completed = false;  // every row
  bool stopped = false;    // a sink said stop, or in.stop was raised
  std::string failure;     // a blow-up's message (the rows up to it were handed out)
  double failure_time = 0; // [s]
};

// Hands the row of `d` (t = 0, or the grid's first_output's time) to the sinks, then every row
// of the grid after it.
RunEnd Drive(const Model& m, Data& d, const Inputs& in, const TimeGrid& grid,
             const std::vector<RowSink*>& sinks);

}  // namespace cablefilm
