#include "run/driver.h"

#include "core/cancel.h"
#include "core/step.h"

namespace cablefilm {

void RowStepper::Next() {
  // grid.dt is interval / steps_per_output (time_grid.cpp): the same steps as ever.
  for (int i = 0; i < grid_.steps_per_output; ++i) {
    ThrowIfCancelled(in_.stop, "the simulation");
    Step(m_, d_, in_, grid_.dt);
  }
  d_.t = ++row_ * grid_.interval;
  for (LineData& line : d_.lines) line.state.t = d_.t;
}

RunEnd Drive(const Model& m, Data& d, const Inputs& in, const TimeGrid& grid,
             const std::vector<RowSink*>& sinks) {
  RunEnd end;
  auto hand = [&] {
    bool go_on = true;
    for (RowSink* s : sinks) go_on = s->Row(d) && go_on;
    return go_on;
  };
  if (!hand()) {
    end.stopped = true;
    return end;
  }
  RowStepper stepper(m, d, in, grid);
  while (!stepper.done()) {
    try {
      stepper.Next();
    } catch (const CancelledError&) {
      end.stopped = true;  // the rows so far stand; the state is part way to the next row
      return end;
    } catch (const BlowUpError& e) {
      end.failure = e.what();
      end.failure_time = e.time;
      return end;
    }
    if (!hand()) {
      end.stopped = true;
      return end;
    }
  }
  end.completed = true;
  return end;
}

}  // namespace cablefilm
