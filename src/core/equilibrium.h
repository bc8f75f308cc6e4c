#pragma once
// Static equilibrium of the cable with its ends at rest at their t = 0 positions: the initial
// state of the paper. Newton's method on the free stations' positions, continued in the
// current, with pseudo-transient continuation as the fallback; the Jacobian is block
// tridiagonal (2x2 blocks), so each iteration costs O(s).
#include <Eigen/Core>

#include "core/cable_model.h"
#include "core/cable_state.h"
#include "core/cancel.h"

namespace cablefilm {

struct EquilibriumReport {
  int iterations = 0;       // Newton iterations, all continuation steps together
  int current_steps = 0;    // continuation steps in the current (0 without current)
  double residual = 0;      // largest out-of-balance force on a station at the end [N]
  double force_scale = 0;   // the force the residual is measured against [N]
  double roundoff_floor = 0;  // the residual the link tensions' round-off allows [N]: an
                              // iteration that stalls below it has converged
  bool fallback = false;    // Newton failed and pseudo-transient continuation took over
  int fallback_iterations = 0;  // of `iterations`, those of the pseudo-transient fallback
};

struct EquilibriumOptions {
  int max_iterations = 500;     // Newton iterations in all
  double tolerance = 1e-9;      // converged when residual <= tolerance * force_scale
  int max_current_steps = 64;   // continuation steps in the current
  int max_pseudo_transient_iterations = 5000;  // the fallback's steps when Newton fails
  const CancelFlag* cancel = nullptr;  // polled every iteration: CancelledError when raised
};

// The static load the residual is measured against [N]: net weights plus the current's drag.
double StaticForceScale(const CableModel& m);

// A first guess that is close for most cables: an elastic catenary of the mean net weight
// through the two ends (straight and uniformly stretched when taut), or a line hanging from
// the prescribed end along the net weight when the other end is free. A catenary that sags
// through a seabed is replaced by the catenary with a grounded part (lying along the bed from
// the lower end, leaving it tangentially); any station still below the bed is raised onto it.
Eigen::Matrix2Xd EquilibriumGuess(const CableModel& m);

// The stations evenly spaced on the chord between the ends (the "straight" initial state and
// the poorest reasonable start of the solver).
Eigen::Matrix2Xd StraightChord(const CableModel& m);

// Throws Error with the iterations and the residual if it does not converge.
CableState SolveEquilibrium(const CableModel& m, const Eigen::Matrix2Xd& guess,
                            EquilibriumReport* report = nullptr,
                            const EquilibriumOptions& options = {});
CableState SolveEquilibrium(const CableModel& m, EquilibriumReport* report = nullptr,
                            const EquilibriumOptions& options = {});

}  // namespace cablefilm
