#pragma once
// The time grid of a run: its output rows (every `interval`, up to the scene's duration), the
// step asked of the scheme between them, and the scheme's options (core/line_data.h).
#include "core/line_data.h"
#include "core/model.h"
#include "core/stability.h"
#include "scene/scene_def.h"

namespace cablefilm {

// The implicit and the inextensible schemes' local position error per step when time_step =
// "auto" and no tolerance is given, as a fraction of the cable's length: case P63's peak tension
// is then within 0.1 % of the converged value at 60 to 6000 links (see bench_integrators); a
// 5 m inextensible chain released from a horizontal line is within 0.1 mm of the exact N-link
// pendulum over its first second (see tests/run/inextensible_test.cpp).
constexpr double kDefaultRelativeTolerance = 1e-6;

// While the motion starts, the implicit scheme's default tolerance is divided by this: case
// P63's start excites the 0.5 s axial ringing of its weight on the nylon, and at the default
// tolerance its phase drifts to 0.5 % of the peak by t = 2.5 s (the step at the 1/30 s rows);
// a twentieth keeps every row within 0.08 % of the converged, low-passed explicit run at 60 and
// 600 links for 24 % more steps (docs/validation.md, "Start-up accuracy"). Dividing it throughout cost
// 2.2 and 2.9 times the steps there and on the grounded mooring, for nothing after the start.
constexpr double kStartToleranceDivisor = 20;

// How long the motion takes to start [s]: the longest of the ramps of eq. (3) (the ends' and
// the waves') to within 4 % of their amplitude, R(t) = 1 - (1 + nu t) exp(-nu t) at nu t = 5;
// a motion without a ramp (nu = 0) starts in one period. 0 when nothing moves.
double StartDuration(const LineModel& m);

struct TimeGrid {
  StepOptions options;       // the scheme and its settings
  double interval = 0;       // between outputs [s]
  double dt = 0;             // the step asked of the scheme [s], interval / steps_per_output
  int steps_per_output = 1;
  long outputs = 0;          // outputs after t = 0; the run ends at outputs * interval
  long first_output = 0;     // the row the run starts at (a window of a run: its first row)
  bool automatic = true;     // dt chosen by the program (else the scene's time_step)
  StabilityLimit limit;      // of the explicit scheme
  double safety_factor = 0.8;
  double end() const { return outputs * interval; }  // [s]
};

// The largest step not above the requested one that divides the interval. "auto" is, for the
// explicit scheme, the safety factor times its stability limit (which its integrator refines
// where links go slack or snap taut); for the implicit and the inextensible schemes an adaptive
// step below the output interval, chosen by a local error estimate (independent of the
// stations; the inextensible one also below its transverse-wave limit).
TimeGrid ChooseLineGrid(const LineModel& m, const SimulationDef& sim, double interval);

// The model's grid: each line's own (ChooseLineGrid); the finest step asked, and with "auto"
// the longest line's tolerance (1e-6 of its length: the model's scale; the shortest line's
// would make a short pendant set the steps of the whole mooring), the stricter start's until
// the last of its lines' moving ends has started. A model of one line: its line's.
TimeGrid ChooseTimeGrid(const Model& model, const SimulationDef& sim, double interval);

}  // namespace cablefilm
