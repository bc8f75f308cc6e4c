#pragma once
// The run layer's loop (run/driver.h) as the tests drive it: a Stepper (test_support.h) from a
// state over a time grid, every row to a function of the state and its tensions.
#include <functional>

#include "run/driver.h"
#include "run/time_grid.h"
#include "test_support.h"

namespace cablefilm::testing {

inline std::unique_ptr<Stepper> MakeStepper(const LineModel&, const TimeGrid& grid) {
  return std::make_unique<Stepper>(grid.options);
}

// Drives `stepper` from `state` through `grid` (Drive), each row to `on_row`; `state` ends as
// the last row's. True if every row was reached; rethrows a blow-up as BlowUpError.
inline bool Simulate(const LineModel& m, Stepper& stepper, State& state, const TimeGrid& grid,
                     const std::function<bool(const State&, const Eigen::VectorXd&)>& on_row,
                     const CancelFlag* stop = nullptr) {
  stepper.set_cancel(stop);
  stepper.Initialize(m, state);
  RowFunction sink([&](const LineData& d) { return on_row(d.state, d.tension()); });
  const RunEnd end = Drive(m, stepper.data(), stepper.inputs(), grid, {&sink});
  state = stepper.data().state;
  if (!end.failure.empty()) throw BlowUpError(end.failure, end.failure_time, 0);
  return end.completed;
}

}  // namespace cablefilm::testing
