#pragma once
// The one step of the model (MuJoCo's mj_step): advances the LineData by dt [s] under the inputs,
// with the scheme of data.options (explicit_step.h, implicit_step.h, inextensible_step.h),
// taking the substeps that scheme needs. The water (current, waves) is the inputs' at the
// middle of dt, held over it; a prescribed end moves as the inputs move it at every stage.
// Throws BlowUpError if the new state is not finite or a link is stretched beyond any
// physical meaning, CancelledError when inputs.stop is raised (the state then at the last
// substep completed). Allocates nothing.
#include "core/line_data.h"

namespace cablefilm {

void StepLine(const LineModel& m, LineData& d, const Inputs& in, double dt);

}  // namespace cablefilm
