#pragma once
// The stages of one generalized-alpha step of one line (implicit_step.h), which the one-line
// step and the step of a system of lines (coupled_step.h) both run: the predictor, Newton's
// system, the correction, the error estimate, the landings on the seabed, the commit; and the
// adaptive loop around them. A line's trial values live in its LineData's scratch.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/cancel.h"
#include "core/line_data.h"
#include "core/step_landing.h"
#include "core/implicit_step.h"

namespace cablefilm {

// Newton iterations a step may take before it is rejected (and retried shorter).
constexpr int kMaxNewtonIterations = 12;
// After the first iteration of a step Newton keeps its matrix (and its factors) while the
// corrections contract at least this fast, and assembles it anew when they do not: within a
// step the matrix changes by the tiny corrections only, so the kept one contracts by about
// 1e-3 at a fraction of the cost (no Jacobian, no factoring: P63 at 60 and 600 links in half
// the time). A station that crosses the seabed's level changes the matrix's contact: a fresh
// one follows; and a correction of the kept matrix larger than the last is not applied (a new
// matrix is made at the same iterate instead), since a contact it does not know can throw the
// iterate far off (the spread mooring's touchdowns did: 2.5 times the rejected steps).
constexpr double kFrozenJacobianRate = 0.1;

// When Newton's corrections have converged: the last one below the tolerance (whatever the
// rate, as before), or, from the second on, the error the iterations still leave below it. Newton contracts the error by
// theta = |dx_k| / |dx_{k-1}| (the rate it shows), so what remains after correction k is at
// most theta / (1 - theta) |dx_k| (Hairer & Wanner, Solving ODEs II, IV.8, eq. (8.10)); a rate
// of 1 or more is no contraction. With the tolerance at 1e-9 of the shortest link the second
// correction is typically 1e-7 m at a rate of 1e-3, so it leaves 1e-10 m: a third iteration
// that would only confirm it (a third of Newton's work) is not done.
class NewtonConvergence {
 public:
  explicit NewtonConvergence(double tolerance) : tolerance_(tolerance) {}
  // The size of correction k [m] (k = 1, 2, ... in turn; not finite: not converged).
  bool Converged(double dx) {
    const double previous = last_;
    last_ = dx;
    ++corrections_;
    theta_ = previous > 0 ? dx / previous : 0.0;
    if (dx <= tolerance_) return true;
    return previous > 0 && theta_ < 1 && theta_ / (1 - theta_) * dx <= tolerance_;
  }
  // Not converging: from the third correction on, one no smaller than the one before. A
  // station at the seabed's contact can cycle (in the bed, thrown out, in again: the linear
  // model sees the bed only where the iterate is): it never converges at this step, and the
  // iterations up to kMaxNewtonIterations would be lost before the step is halved anyway.
  bool Stalled() const { return corrections_ >= 3 && !(theta_ < 1); }
  // A correction that was not applied whole (ApplyCorrection's `cut`): not converged, and the
  // next one is measured as a first (no rate from this one).
  void Cut() {
    last_ = 0;
    theta_ = 0;
    ++corrections_;
  }
  // The last correction's rate theta (0 after the first), and its size.
  double rate() const { return theta_; }
  double last() const { return last_; }

 private:
  double tolerance_;
  double last_ = 0;    // the last correction's size [m]; 0 before the first
  double theta_ = 0;   // the last rate
  int corrections_ = 0;
};

// The trial step of size h: positions predicted with the pseudo-acceleration carried over
// (and its change over the last step while the line is taut), prescribed ends at their
// positions and velocities at t + h.
void PredictStep(const LineModel& m, LineData& d, const Inputs& in, const GeneralizedAlpha& c,
                 double h);
// Newton's system at the trial positions: forces and tensions computed, the matrix
// ka M + d(M a)/dx - dF/dx - kv dF/dv and the residual F - M a in d.scratch.system (rows: the
// free stations). Without `jacobian` the residual alone, the matrix left as it was (and its
// factors: a simplified Newton iteration, BlockTridiagonal::SolveFactored); false then when a
// link went slack or taut since that matrix was made (its axial stiffness EA / l is in it or
// not: the kept matrix no longer holds).
bool AssembleNewton(const LineModel& m, LineData& d, const GeneralizedAlpha& c, double h,
                    bool jacobian = true);
// Whether a line's Newton iterations may keep their matrix (kFrozenJacobianRate): not with
// seabed friction, whose sticking stations hold by a shear spring far stiffer than the line
// and let go of it when they slide: a kept matrix that still holds them converges along the
// bed as slowly as that ratio, which the rate of the largest correction does not show (the
// rotated grounded chain of rotational_invariance_test drifted by 2 % of its peak tension).
bool KeepsNewtonMatrix(const LineModel& m);
// Newton's linear model on the taut side for links that a step snaps taut. A slack link
// (shorter than at rest) has no stiffness in the matrix, so a step that stretches it past its
// rest length is blind to its tension: one link an iteration went taut while a tension wave
// ran down a slack grounded stretch (4 to 12 iterations instead of 2 in a tenth of a spread
// mooring's steps). After a solve with a fresh matrix, FindSnappingLinks marks the slack links
// that the solution in d.scratch.system.rhs stretches past their rest length (true if it
// marked a new one); ClearSnappingLinks forgets them. AddSnappingLinks puts back the residual
// kept before the solve (KeepResidual) with the marked links' Hooke force EA (L - l) / l t
// (compressive: they are shorter than l) added, and adds the newly marked links' axial
// stiffness EA / l t t^T to the matrix (whose blocks a factoring leaves as they are: the
// caller solves again), which then holds them as taut (Scratch::matrix_taut). Newton's model
// of a link is then the piece of Hooke's law its step lands on; the model is exact where it is
// used, so the converged step is the same.
bool FindSnappingLinks(const LineModel& m, LineData& d);
void ClearSnappingLinks(LineData& d);
void AddSnappingLinks(const LineModel& m, LineData& d);
// The residual in d.scratch.system.rhs kept before a solve, and put back (a line solved again
// on its kept factors beside one that is re-solved for its snapping links).
void KeepResidual(LineData& d);
void RestoreResidual(LineData& d);
// At most this many re-solves per Newton iteration for links found snapping. A re-solve
// refactors the whole line, a serial chain of 3x3 inverses: on the spread mooring one pass
// took 0.86-0.93 of the CPU of none (paired runs), three passes 1.02 for 13 % fewer iterations.
constexpr int kSnappingPasses = 1;
// The size of the solution in d.scratch.system.rhs: its largest station correction |dx_j| [m]
// (NaN if one is). The length of each station's correction, not its largest coordinate: a
// turned scene's Newton stops at the same iteration as the scene's own, where the largest
// coordinate stopped them an iteration apart now and then, and a sticking station on the
// seabed kept the difference (rotational_invariance_test: 3e-7 of the peak tension, 1.2e-5
// once sliding stations' steps were cut in their stick zones; 2e-11 now). It is at least the
// largest coordinate, so the tolerance holds in every direction.
double CorrectionSize(const LineModel& m, const LineData& d);
// Adds the solution in d.scratch.system.rhs to the trial positions; returns its size as
// CorrectionSize [m] (not finite if the solution is not). kv: the step's d v / d x [1/s]
// (GeneralizedAlpha::VelocityPerPosition). `contact_changed` (optional): set when a station
// crossed the seabed's level (the matrix's contact then no longer holds). `cut` (optional):
// set when a grounded station's step along the bed was cut short in its stick zone
// (implicit_stages.cpp, FrictionStep): the iterate did not move by the solution then, which
// says nothing of how near it is (NewtonConvergence::Cut).
double ApplyCorrection(const LineModel& m, LineData& d, double kv, bool* contact_changed = nullptr,
                       bool* cut = nullptr);
// The converged trial step: its velocities, accelerations and tensions.
void FinishSolve(const LineModel& m, LineData& d, const GeneralizedAlpha& c, double h);
// The local position error of the solved step [m].
double LocalError(const LineModel& m, const LineData& d, const GeneralizedAlpha& c, double h);
// Brings to rest (vertically) the stations that landed on the seabed in the solved step.
void SettleLandings(const LineModel& m, LineData& d, double h);
// Makes the solved step the state.
void Commit(const LineModel& m, LineData& d, double h);
// The most stretched link now (a blow-up names it).
int WorstLink(const LineModel& m, const LineData& d);

// The adaptive loop of an implicit step of dt [s], for one line or a system of them. `s`
// gives: double& Time(), double& ProposedStep(), long& Rejected(), bool Solve(h),
// double Error(h), void Accept(h) (settle and commit), int WorstLink(), double
// NextKink(t): the first time after t [s] where a prescribed motion's velocity jumps (a linear
// table's rows; +infinity if none), on which a step is made to land rather than straddle it,
// and bool HandsOff(h): whether a solved step within the tolerance is to be left to another
// scheme (explicit_snaps.h) instead of taken. The error is held below `options`' tolerance at
// the step's start (StepOptions::ToleranceAt; 0: the steps asked, uncontrolled). Returns true
// when dt is done, false when a step was handed off (the time then at that step's start).
// `largest` [s]: the longest step (the interval asked of StepLine(), of which dt may be the rest;
// 0: dt).
template <class Stepper>
bool AdaptiveImplicitSteps(Stepper& s, const StepOptions& options, const CancelFlag* stop,
                           double dt, double largest = 0) {
  constexpr int kMaxRejections = 40;
  constexpr double kSmallestStepFraction = 1e-9;  // of the interval asked of StepLine()
  // The next step is this fraction of the one that would just meet the tolerance (the error
  // grows as h^3). 0.9 left a quarter of the spread mooring's steps rejected (its error
  // estimate varies step to step as touchdowns move and links snap taut); 0.8 halved them
  // for 8 % more accepted steps and 10 % fewer Newton iterations in all (docs/validation.md).
  constexpr double kStepSafety = 0.8;
  double& t = s.Time();
  double& proposed = s.ProposedStep();
  const double t_end = t + dt;
  if (!(largest > 0)) largest = dt;
  if (!(proposed > 0) || proposed > largest) proposed = largest;
  int failures = 0;  // consecutive rejections
  long taken = 0;    // steps tried in this call (options.most_steps)
  // A step this much smaller than the one asked for makes no useful progress: the motion (an
  // end's acceleration, a snap) is faster than any step can follow; say so rather than crawl.
  const double smallest = kSmallestStepFraction * largest;
  while (!Landed(t, t_end, largest)) {
    ThrowIfCancelled(stop, "the implicit step");
    if (options.most_steps > 0 && ++taken > options.most_steps) {
      std::ostringstream os;
      os << "the implicit steps reached their bound of " << options.most_steps
         << " steps at t = " << t << " s (the last " << proposed << " s long)";
      throw Error(os.str());
    }
    const double tolerance = options.ToleranceAt(t);
    // Land on a kink of a prescribed motion within reach (one closer than the smallest step
    // is taken as passed: t may sit a rounding short of a row it has landed on). Not in equal
    // steps to it: that made the number of steps, and so the results, jump with a rounding of
    // the step asked (two runs of the same system drifted apart by the step's own error; full
    // steps and a last short one keep them together at 3 % of the spread mooring's work). A
    // last piece under a hundredth of a step joins the step before (step_landing.h).
    const double kink = s.NextKink(t + smallest);
    const double h = StepToward(t, std::min(kink, t_end), proposed);
    if (h < smallest && h < t_end - t) {
      std::ostringstream os;
      os << "the implicit step fell to " << h << " s at t = " << t << " s (below "
         << kSmallestStepFraction << " of the " << largest << " s asked for, " << s.Rejected()
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
      proposed = error > 0 ? h * std::max(0.2, kStepSafety * std::cbrt(tolerance / error)) : 0.5 * h;
      continue;
    }
    if (s.HandsOff(h)) return false;
    s.Accept(h);
    failures = 0;
    if (truncated) continue;  // a short last piece says nothing about the step size
    const double growth =
        tolerance > 0 ? std::min(2.0, kStepSafety * std::cbrt(tolerance / std::max(error, 1e-300)))
                      : 2.0;
    // A step that would shrink by less than a tenth is kept: a dead band, or every row of P63
    // that its error fills above half the tolerance ends in a sliver (323 steps in its first
    // 10 s against the rows' 300).
    proposed = std::min(largest, h * (growth >= 0.9 && growth < 1 ? 1.0 : growth));
  }
  t = t_end;
  return true;
}

}  // namespace cablefilm
