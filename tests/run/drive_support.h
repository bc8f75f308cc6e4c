#pragma once
// A line's rows as a run steps them (run/driver.h's RowStepper, for a line alone): a Stepper
// (test_support.h) from a state over a time grid, every row to a function of the state and its
// tensions.
#include <functional>

#include "core/cancel.h"
#include "core/step.h"
#include "run/time_grid.h"
#include "../core/test_support.h"

namespace cablefilm::testing {

inline std::unique_ptr<Stepper> MakeStepper(const LineModel&, const TimeGrid& grid) {
  return std::make_unique<Stepper>(grid.options);
}

// Drives `stepper` from `state` through `grid` (each row the grid's steps, its time exactly
// row x interval), each row to `on_row` (false: stop there); `state` ends as the last row's.
// True if every row was reached; a blow-up propagates as BlowUpError.
inline bool Simulate(const LineModel& m, Stepper& stepper, State& state, const TimeGrid& grid,
                     const std::function<bool(const State&, const Eigen::VectorXd&)>& on_row,
                     const CancelFlag* stop = nullptr) {
  stepper.set_cancel(stop);
  stepper.Initialize(m, state);
  LineData& d = stepper.data();
  bool go_on = on_row(d.state, d.tension());
  for (long row = 1; go_on && row <= grid.outputs; ++row) {
    try {
      for (int i = 0; i < grid.steps_per_output; ++i) {
        ThrowIfCancelled(stop, "the simulation");
        StepLine(m, d, stepper.inputs(), grid.dt);
      }
    } catch (const CancelledError&) {
      state = d.state;
      return false;
    }
    d.state.t = row * grid.interval;
    go_on = on_row(d.state, d.tension());
  }
  state = d.state;
  return go_on;
}

}  // namespace cablefilm::testing
