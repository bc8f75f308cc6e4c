#include "core/implicit_step.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/explicit_snaps.h"
#include "core/implicit_stages.h"

namespace cablefilm {
namespace {

// One line through the adaptive loop (implicit_stages.h).
struct LineStepper {
  const LineModel& m;
  LineData& d;
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
  double handed_off = 0;  // the step it left to explicit ones [s]
  bool HandsOff(double h) {
    if (!StepsThroughSnaps(d) || !SnapsUnresolved(m, d, h)) return false;
    handed_off = h;
    return true;
  }
  void Accept(double h) {
    SettleLandings(m, d, h);
    Commit(m, d, h);
  }
  // Solves one step of size h into the scratch's trial values; false if Newton did not
  // converge.
  bool Solve(double h) {
    PredictStep(m, d, in, c, h);
    NewtonConvergence newton(d.scratch.newton_tolerance);
    BlockTridiagonal& system = d.scratch.system;
    const bool keep = KeepsNewtonMatrix(m);
    const double kv = c.VelocityPerPosition(h);  // d v / d x [1/s]
    bool fresh = true;  // this iteration's matrix is assembled anew (else the last one's factors)
    for (int it = 1; it <= kMaxNewtonIterations; ++it) {
      const bool holds = AssembleNewton(m, d, c, h, fresh);
      if (fresh) {
        ClearSnappingLinks(d);
        KeepResidual(d);
        if (!system.Solve()) return false;
        for (int pass = 0; pass < kSnappingPasses && FindSnappingLinks(m, d); ++pass) {
          AddSnappingLinks(m, d);
          if (!system.Solve()) return false;
        }
      } else {
        if (holds) system.SolveFactored(system.rhs);
        // The kept matrix no longer holds, does not contract here, or its step snaps a slack
        // link taut that it does not hold as taut: a new one at this iterate.
        if (!holds || !(CorrectionSize(m, d) <= newton.last()) || FindSnappingLinks(m, d)) {
          fresh = true;
          --it;  // not an iteration: none was applied
          continue;
        }
      }
      bool contact_changed = false, cut = false;
      const double dx_max = ApplyCorrection(m, d, kv, &contact_changed, &cut);
      if (!std::isfinite(dx_max)) return false;
      if (cut) {
        newton.Cut();
      } else if (newton.Converged(dx_max)) {
        FinishSolve(m, d, c, h);
        return true;
      }
      if (fresh && newton.Stalled()) return false;
      fresh = !keep || contact_changed || !(newton.rate() <= kFrozenJacobianRate);
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

void ImplicitStep(const LineModel& m, LineData& d, const Inputs& in, double dt) {
  LineStepper stepper{m, d, in, GeneralizedAlphaCoefficients(d.options.rho_inf)};
  const double t_end = d.state.t + dt;
  // Implicit steps, and explicit ones through the snaps they hand off (explicit_snaps.h).
  double rest = dt;  // [s] (dt itself unless a window took part of it: t + dt - t is not dt)
  for (;;) {
    if (d.state.t < d.explicit_until) {
      StepExplicitWindow(m, d, in, t_end);
      if (!(d.state.t < t_end)) break;
      rest = t_end - d.state.t;
    }
    if (AdaptiveImplicitSteps(stepper, d.options, in.stop, rest, dt)) break;
    EnterExplicitWindow(m, d, in, stepper.handed_off);
    rest = t_end - d.state.t;
  }
  d.state.t = t_end;
  CheckStateSane(m, d.state, d.forces.geometry.length);
}

}  // namespace cablefilm
