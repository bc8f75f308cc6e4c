#pragma once
// The stages of one generalized-alpha step of one line (implicit_step.h), which the one-line
// step and the step of a system of lines (system_step.h) both run: the predictor, Newton's
// system, the correction, the error estimate, the landings on the seabed, the commit; and the
// adaptive loop around them. A line's trial values live in its Data's scratch.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/cancel.h"
#include "core/data.h"
#include "core/implicit_step.h"

namespace cablefilm {

// Newton iterations a step may take before it is rejected (and retried shorter).
constexpr int kMaxNewtonIterations = 12;

// The trial step of size h: positions predicted with the pseudo-acceleration carried over,
// prescribed ends at their positions and velocities at t + h.
void PredictStep(const Model& m, Data& d, const Inputs& in, const GeneralizedAlpha& c,
                 double h);
// Newton's system at the trial positions: forces and tensions computed, the matrix
// ka M + d(M a)/dx - dF/dx - kv dF/dv and the residual F - M a in d.scratch.system (rows: the
// free stations).
void AssembleNewton(const Model& m, Data& d, const GeneralizedAlpha& c, double h);
// Adds the solution in d.scratch.system.rhs to the trial positions; returns its largest entry
// [m] (not finite if the solution is not).
double ApplyCorrection(const Model& m, Data& d);
// The converged trial step: its velocities, accelerations and tensions.
void FinishSolve(const Model& m, Data& d, const GeneralizedAlpha& c, double h);
// The local position error of the solved step [m].
double LocalError(const Model& m, const Data& d, const GeneralizedAlpha& c, double h);
// Brings to rest (vertically) the stations that landed on the seabed in the solved step.
void SettleLandings(const Model& m, Data& d, double h);
// Makes the solved step the state.
void Commit(const Model& m, Data& d, double h);
// The most stretched link now (a blow-up names it).
int WorstLink(const Model& m, const Data& d);

// The adaptive loop of an implicit step of dt [s], for one line or a system of them. `s`
// gives: double& Time(), double& ProposedStep(), long& Rejected(), bool Solve(h),
// double Error(h), void Accept(h) (settle and commit), int WorstLink(), and double
// NextKink(t): the first time after t [s] where a prescribed motion's velocity jumps (a linear
// table's rows; +infinity if none), on which a step is made to land rather than straddle it.
template <class Stepper>
void AdaptiveImplicitSteps(Stepper& s, double tolerance, const CancelFlag* stop, double dt) {
  constexpr int kMaxRejections = 40;
  constexpr double kSmallestStepFraction = 1e-9;  // of the interval asked of Step()
  double& t = s.Time();
  double& proposed = s.ProposedStep();
  const double t_end = t + dt;
  if (!(proposed > 0) || proposed > dt) proposed = dt;
  int failures = 0;  // consecutive rejections
  // A step this much smaller than the one asked for makes no useful progress: the motion (an
  // end's acceleration, a snap) is faster than any step can follow; say so rather than crawl.
  const double smallest = kSmallestStepFraction * dt;
  while (t < t_end - 1e-12 * dt) {
    ThrowIfCancelled(stop, "the implicit step");
    double h = std::min(proposed, t_end - t);
    // Land on a kink of a prescribed motion within reach (one closer than the smallest step
    // is taken as passed: t may sit a rounding short of a row it has landed on).
    const double kink = s.NextKink(t + smallest);
    if (kink - t < h) h = kink - t;
    if (h < smallest && h < t_end - t) {
      std::ostringstream os;
      os << "the implicit step fell to " << h << " s at t = " << t << " s (below "
         << kSmallestStepFraction << " of the " << dt << " s asked for, " << s.Rejected()
         << " steps rejected in all): the motion is faster than the scheme can follow (an "
            "end's motion too violent, or an unresolvable snap)";
      throw BlowUpError(os.str(), t, s.WorstLink());
    }
    const bool truncated = h < proposed;
    double error = 0;
    bool ok = s.Solve(h);
    if (ok && tolerance > 0) {
      error = s.Error(h);
      ok = error <= tolerance;
    }
    if (!ok) {
      ++s.Rejected();
      if (++failures > kMaxRejections) {
        std::ostringstream os;
        os << "the implicit step failed " << failures << " times in a row at t = " << t
           << " s, down to a step of " << h << " s";
        const int worst = s.WorstLink();
        throw BlowUpError(os.str() + "; the most stretched link is " + std::to_string(worst),
                          t, worst);
      }
      // Newton failed: halve. Error too large: the step that would just meet the tolerance
      // (the error grows as h^3), with a margin.
      proposed = error > 0 ? h * std::max(0.2, 0.9 * std::cbrt(tolerance / error)) : 0.5 * h;
      continue;
    }
    s.Accept(h);
    failures = 0;
    if (truncated) continue;  // a short last piece says nothing about the step size
    const double growth =
        tolerance > 0 ? std::min(2.0, 0.9 * std::cbrt(tolerance / std::max(error, 1e-300)))
                      : 2.0;
    proposed = std::min(dt, h * growth);
  }
  t = t_end;
}

}  // namespace cablefilm
