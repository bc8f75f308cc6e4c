#pragma once
// What changes while a model runs without the model changing (MuJoCo's controls): the current,
// the waves' height and period, the driven ends' amplitude and clock. A run takes the scene's
// own (SceneInputs: every schedule constant); the live view ramps them along SmoothSchedule,
// so that nothing a control changes jumps; the static equilibrium's continuation raises the
// current through current_scale. StepLine() evaluates them into the Water of the step (the current
// and the wave it holds over the step, at its middle) and the ends' motion at every stage.
#include "core/cancel.h"
#include "core/line_model.h"
#include "core/model.h"
#include "core/smooth_schedule.h"

namespace cablefilm {

struct Inputs {
  SmoothSchedule current{0};       // c [m/s], the uniform part (a profile adds to it)
  SmoothSchedule current_heading{0};  // the current's direction [rad] from +x towards +z
  double current_scale = 1;        // times the whole current, uniform and profile
  SmoothSchedule wave_height{0};   // H [m] (with waves)
  SmoothSchedule wave_period{0};   // T [s] (with waves)
  SmoothSchedule wave_heading{0};  // the direction the waves travel [rad] from +x towards +z
  Vec wave_phase_point = Vec::Zero();  // where a change of period or heading keeps the wave's
                                       // phase [m]
  SmoothSchedule end_scale{1};     // the driven ends' orbit (or table) amplitude, times the scene's
  SmoothSchedule end_clock{1};     // the rate of their motion's clock, times real time
  // The live view's horizontal offset of a system's vessel [m] (x, z; y is up), added to the
  // ends it carries (EndMotion::carried): 0 and constant in a run.
  SmoothSchedule offset_x{0}, offset_z{0};
  const CancelFlag* stop = nullptr;  // polled within a step (each substep, each Newton step):
                                     // when raised, Step throws CancelledError
};

// The driven ends' clock runs as the scene's (constant 1): their motions' times (a table's
// rows) are the run's.
inline bool ClockAsScene(const Inputs& in) {
  return in.end_clock.constant() && in.end_clock.target() == 1.0;
}

// The model's own inputs: its current and waves, its ends as the scene moves them (one
// environment: any line's are the model's).
Inputs SceneInputs(const LineModel& m);
Inputs SceneInputs(const Model& m);

// The heading [rad] from +x towards +z of a horizontal direction.
double HeadingOf(const Vec& direction);

// The water over a step: the current and the waves it holds.
struct Water {
  double current = 0;        // c [m/s], uniform part
  double current_scale = 1;  // times the whole current (Inputs::current_scale)
  Vec current_direction = Vec(1.0, 0.0, 0.0);  // horizontal unit vector
  Wave wave;                 // the waves (wave.spec.present as the model's)
};

// The model's water, as the scene gives it at t = 0 (scaled by `current_scale`).
Water SceneWater(const LineModel& m, double current_scale = 1.0);
// The water of the inputs at time t [s], from the water of the step before (`water`): the
// current (speed and heading; a current history's factor and heading at t) and the waves'
// height at t; a new period or heading with the
// phase kept at wave_phase_point (where a ship would see the wave change), so the waves' phase
// carries over; the height held at Miche's breaking limit of the period at t. Exactly the
// model's water while the inputs are the scene's.
void UpdateWater(const LineModel& m, const Inputs& in, double t, Water* water);

// The current's velocity at elevation y [m/s] and its y-derivative [1/s].
// Inline, as CurrentProfile's.
inline Vec CurrentAt(const LineModel& m, const Water& w, double y) {
  const CurrentProfile& p = m.env.current_profile;
  const double c = w.current * w.current_scale;
  return (p.empty() ? c : c + p.At(y, w.current_scale)) * w.current_direction;
}
inline Vec CurrentSlope(const LineModel& m, const Water& w, double y) {
  const CurrentProfile& p = m.env.current_profile;
  return (p.empty() ? 0.0 : p.Slope(y, w.current_scale)) * w.current_direction;
}
// The water's velocity at `position` [m] and time t [s]: the current at its elevation and,
// with waves, their orbital velocity there (held at the surface's above it) [m/s].
Vec WaterVelocityAt(const LineModel& m, const Water& w, const Vec& position, double t);
bool HasCurrent(const LineModel& m, const Water& w);    // anywhere non-zero
double MaxCurrent(const LineModel& m, const Water& w);  // the largest |c(y)| over all y [m/s]

// A prescribed end's position [m], velocity [m/s] and acceleration [m/s^2] at t [s] (j = 0 or
// s), as the inputs move it (a carried end with the offset's).
Vec EndPosition(const LineModel& m, const Inputs& in, int j, double t);
Vec EndVelocity(const LineModel& m, const Inputs& in, int j, double t);
Vec EndAcceleration(const LineModel& m, const Inputs& in, int j, double t);

}  // namespace cablefilm
