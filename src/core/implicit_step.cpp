#include "core/implicit_step.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/implicit_stages.h"

namespace cablefilm {
namespace {

// One line through the adaptive loop (implicit_stages.h).
struct LineStepper {
  const Model& m;
  Data& d;
  const Inputs& in;
  GeneralizedAlpha c;

  double& Time() { return d.state.t; }
  double& ProposedStep() { return d.proposed_step; }
  long& Rejected() { return d.stats.rejected; }
  int WorstLink() const { return cablefilm::WorstLink(m, d); }
  double Error(double h) const { return LocalError(m, d, c, h); }
  double NextKink(double t) const {
    if (!ClockAsScene(in)) return std::numeric_limits<double>::infinity();
    return std::min(m.ends.start.NextKink(t), m.ends.end.NextKink(t));
  }
  void Accept(double h) {
    SettleLandings(m, d, h);
    Commit(m, d, h);
  }
  // Solves one step of size h into the scratch's trial values; false if Newton did not
  // converge.
  bool Solve(double h) {
    PredictStep(m, d, in, c, h);
    for (int it = 1; it <= kMaxNewtonIterations; ++it) {
      AssembleNewton(m, d, c, h);
      if (!d.scratch.system.Solve()) return false;
      const double dx_max = ApplyCorrection(m, d);
      if (!std::isfinite(dx_max)) return false;
      if (dx_max <= d.scratch.newton_tolerance) {
        FinishSolve(m, d, c, h);
        return true;
      }
    }
    return false;
  }
};

}  // namespace

GeneralizedAlpha GeneralizedAlphaCoefficients(double rho_inf) {
  GeneralizedAlpha c;
  c.am = (2.0 * rho_inf - 1.0) / (rho_inf + 1.0);
  c.af = rho_inf / (rho_inf + 1.0);
  c.gamma = 0.5 + c.af - c.am;
  c.beta = 0.25 * (c.gamma + 0.5) * (c.gamma + 0.5);
  return c;
}

void ImplicitStep(const Model& m, Data& d, const Inputs& in, double dt) {
  LineStepper stepper{m, d, in, GeneralizedAlphaCoefficients(d.options.rho_inf)};
  AdaptiveImplicitSteps(stepper, d.options.tolerance, in.stop, dt);
  CheckStateSane(m, d.state, d.forces.geometry.length);
}

}  // namespace cablefilm
