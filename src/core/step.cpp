#include "core/step.h"

#include "core/explicit_step.h"
#include "core/implicit_step.h"
#include "core/inextensible_step.h"

namespace cablefilm {

void StepLine(const LineModel& m, LineData& d, const Inputs& in, double dt) {
  UpdateWater(m, in, d.state.t + 0.5 * dt, &d.water);
  switch (d.options.scheme) {
    case Scheme::kExplicit:
      return ExplicitStep(m, d, in, dt);
    case Scheme::kImplicit:
      return ImplicitStep(m, d, in, dt);
    case Scheme::kInextensible:
      return InextensibleStep(m, d, in, dt);
  }
}

}  // namespace cablefilm
