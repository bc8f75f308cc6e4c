#pragma once
// The one step of the model (MuJoCo's mj_step): advances the Data by dt [s] under the inputs,
// each island (model.h) on its own: an island of one line by the line's scheme (StepLine), a
// coupled island by the coupled step of the scheme (coupled_step.h, coupled_explicit_step.h),
// each taking the substeps it needs. The water (current, waves) is the inputs' at the middle
// of dt, held over it; a prescribed end moves as the inputs move it at every stage. Throws
// BlowUpError if the new state is not finite or a link is stretched beyond any physical
// meaning (a model of several lines names the line), CancelledError when inputs.stop is
// raised (the state then part way). Allocates nothing. Every line's clock is then exactly
// d.t + dt.
#include "core/data.h"

namespace cablefilm {

void Step(const Model& m, Data& d, const Inputs& in, double dt);

// One line's step of dt [s] with the scheme of d.options (explicit_step.h, implicit_step.h,
// inextensible_step.h): what an island of one line takes.
void StepLine(const LineModel& m, LineData& d, const Inputs& in, double dt);

// Advances the Data by `seconds` [s] in `steps` equal steps (each adaptive within itself when
// the options' tolerance asks), polling in.stop; its time (every line's) then exactly
// t0 + seconds. What a row of RowStepper takes, and a frame of the live view.
void StepSpan(const Model& m, Data& d, const Inputs& in, double seconds, int steps);

}  // namespace cablefilm
