#include "run/initial_state.h"

namespace cablefilm {

State MakeInitialState(const SceneDef& scene, const Model& m, EquilibriumReport* report,
                       const CancelFlag* cancel) {
  EquilibriumOptions options;
  options.cancel = cancel;
  if (scene.initial == InitialStateKind::kEquilibrium)
    return m.line.law == LinkLaw::kInextensible ? SolveInextensibleEquilibrium(m, report)
                                                : SolveEquilibrium(m, report, options);
  State s;
  s.x = StraightChord(m);
  s.v = Points::Zero(kDim, m.stations());
  return s;
}

}  // namespace cablefilm
