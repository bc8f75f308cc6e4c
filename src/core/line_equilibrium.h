#pragma once
// Static equilibrium of the cable with its ends at rest at their t = 0 positions: the initial
// state of the paper. Newton's method on the free stations' positions, continued in the
// current, with pseudo-transient continuation as the fallback; the Jacobian is block
// tridiagonal (kDim x kDim blocks), so each iteration costs O(s).
#include <Eigen/Core>

#include "core/line_model.h"
#include "core/cancel.h"
#include "core/line_data.h"
#include "core/inputs.h"

namespace cablefilm {

struct LineEquilibriumReport {
  int iterations = 0;       // Newton iterations, all continuation steps together
  int current_steps = 0;    // continuation steps in the current (0 without current)
  double residual = 0;      // largest out-of-balance force on a station at the end [N]
  double force_scale = 0;   // the force the residual is measured against [N]
  double roundoff_floor = 0;  // the residual the link tensions' round-off allows [N]: an
                              // iteration that stalls below it has converged
  bool fallback = false;    // Newton failed and pseudo-transient continuation took over
  int fallback_iterations = 0;  // of `iterations`, those of the pseudo-transient fallback
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
State SolveInextensibleEquilibrium(const LineModel& m, LineEquilibriumReport* report,
                                  const CancelFlag* cancel = nullptr);

}  // namespace cablefilm
