#pragma once
// Static equilibrium of the cable with its ends at rest at their t = 0 positions: the initial
// state of the paper. Newton's method on the free stations' positions, continued in the
// current, with pseudo-transient continuation as the fallback; the Jacobian is block
// tridiagonal (kDim x kDim blocks), so each iteration costs O(s).
#include <Eigen/Core>

#include <string>

#include "core/line_model.h"
#include "core/cancel.h"
#include "core/error.h"
#include "core/line_data.h"
#include "core/inputs.h"

namespace cablefilm {

// The statics of a line at most, in station-passes: each pass over its stations (a residual, an
// energy, a step along the links, a Newton matrix assembled, factored and solved) counts them,
// its coarse copies' solves included (coarse_guess.h). A long line's statics take 9 to 19
// passes (a chain on the seabed in a sheared current: 9 at 2 x 10^6 links, 13 at 10^6; a
// catenary in vacuum: 19), at 0.1 to 0.16 us a station-pass; 4e7 (some 5 s) lets a line of
// 10^6 links take twice that, and gives up in seconds on one that would take minutes.
constexpr double kMostLineStaticsWork = 4e7;
// The passes a long line's statics take at the least (a residual, two Newton matrices with
// their steps along the links and residuals, the residual at the answer; measured 9 and more):
// a line whose stations times these exceed what is left of the bound is refused before its
// problem is made (and by the scene's checks: scene_checks.h).
constexpr double kLeastStaticPasses = 8;

// The bound's error: not a line without an equilibrium, but one too large to look for it in the
// time allowed (the fallbacks that catch Error, a coarse guess's or the relaxation, let it
// through).
class StaticsWorkError : public Error {
 public:
  explicit StaticsWorkError(const std::string& what) : Error(what) {}
};

struct LineEquilibriumReport {
  int iterations = 0;       // Newton iterations, all continuation steps together
  int current_steps = 0;    // continuation steps in the current (0 without current)
  double residual = 0;      // largest out-of-balance force on a station at the end [N]
  double force_scale = 0;   // the force the residual is measured against [N]
  double roundoff_floor = 0;  // the residual the link tensions' round-off allows [N]: an
                              // iteration that stalls below it has converged
  bool fallback = false;    // Newton failed and pseudo-transient continuation took over
  int fallback_iterations = 0;  // of `iterations`, those of the pseudo-transient fallback
  double work = 0;          // station-passes (kMostLineStaticsWork), its coarse copies' not
  // The forces on stations 0 and s at the answer, in its water without waves [N] (a held end's:
  // what holds it; coupled_equilibrium.h).
  Vec start_force = Vec::Zero(), end_force = Vec::Zero();
};

struct LineEquilibriumOptions {
  int max_iterations = 500;     // Newton iterations in all
  double tolerance = 1e-9;      // converged when residual <= tolerance * force_scale
  int max_current_steps = 64;   // continuation steps in the current
  int max_pseudo_transient_iterations = 5000;  // the fallback's steps when Newton fails
  const CancelFlag* cancel = nullptr;  // polled every iteration: CancelledError when raised
  bool warm_start = false;      // the guess is an equilibrium nearby in the same current (a
                                // held end moved a little): Newton from it in the full current
                                // first, the continuation only if that fails
  double max_work = kMostLineStaticsWork;  // station-passes at most: StaticsWorkError past it
  // Where the passes are added up against max_work, across solves that share the bound (a
  // line's and its coarse copies'); null: this solve's own, from 0.
  double* work = nullptr;
};

// The static load the residual is measured against [N]: net weights plus the current's drag
// (the scene's current, or that of `water`).
double StaticForceScale(const LineModel& m);
double StaticForceScale(const LineModel& m, const Water& water);

// A first guess that is close for most cables: an elastic catenary of the mean net weight
// through the two ends (straight and uniformly stretched when taut), or a line hanging from
// the prescribed end along the net weight when the other end is free. A catenary that sags
// through a seabed is replaced by the catenary with a grounded part (lying along the bed from
// the lower end, leaving it tangentially); any station still below the bed is raised onto it.
Points EquilibriumGuess(const LineModel& m);

// The stations evenly spaced on the chord between the ends (the "straight" initial state and
// the poorest reasonable start of the solver).
Points StraightChord(const LineModel& m);

// Throws Error with the iterations and the residual if it does not converge.
State SolveLineEquilibrium(const LineModel& m, const Points& guess,
                            LineEquilibriumReport* report = nullptr,
                            const LineEquilibriumOptions& options = {});
State SolveLineEquilibrium(const LineModel& m, LineEquilibriumReport* report = nullptr,
                            const LineEquilibriumOptions& options = {});

// Static equilibrium of the inextensible cable: the elastic equilibrium with a stiffness so
// high that the stretch is negligible, extrapolated to infinite stiffness, projected exactly
// onto the rest lengths. Throws Error if the ends are further apart than the cable is long.
// Its two solves share one bound of max_work station-passes.
State SolveInextensibleEquilibrium(const LineModel& m, LineEquilibriumReport* report,
                                  const CancelFlag* cancel = nullptr,
                                  double max_work = kMostLineStaticsWork);

// Throws StaticsWorkError when the least a solve of `m` takes (kLeastStaticPasses over its
// stations) exceeds what is left of options' bound: before anything of its size is made.
void RefuseIfTooLarge(const LineModel& m, const LineEquilibriumOptions& options);

}  // namespace cablefilm
