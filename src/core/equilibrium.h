#pragma once
// The static equilibrium of a system of lines (model.h): the paper's initial state for a
// mooring. Each line is in equilibrium (SolveLineEquilibrium, line_equilibrium.h) with its ends at its
// points; the shared points (free points where several lines meet) are where the forces of
// their lines balance, and a free body (body.h) is where its lines' loads balance its own:
// Newton's method on the shared points' positions (kDim unknowns per point) and the free
// bodies' poses (6 per body), with a Jacobian of finite differences (each column re-solves
// the lines at one point or body, from their last equilibrium), Broyden's updates and a
// backtracking line search.
#include <functional>
#include <vector>

#include "core/line_equilibrium.h"
#include "core/model.h"

namespace cablefilm {

struct EquilibriumReport {
  int iterations = 0;         // Newton iterations on the shared points and free bodies
  int chains = 0;             // chains of lines solved as one line first (chain_guess.h)
  double residual = 0;        // the largest out-of-balance force on a shared point or body at
                              // the end [N] (a body's moment divided by its size [m])
  double force_scale = 0;     // the load it is measured against: the lines' (StaticForceScale)
  double line_work = 0;       // the held lines' solves, in station-iterations
  std::vector<LineEquilibriumReport> lines;  // each line's last solve
  std::vector<Vec6> body_poses;          // each body's pose (a free body's as solved)
  double relaxed = 0;  // s of the system's damped motion it took to get near enough for Newton
                       // (relaxation.h); 0: none, from the scene's first guess
};

// The held lines' solves at most, in station-iterations (each solve's Newton iterations times
// its line's stations, summed): a system that needs more is not near its equilibrium, and the
// statics should give way (to the relaxation: relaxation.h) in seconds, not minutes
// (some 10 s at 0.5 us a station-iteration). The shipped scenes and MoorDyn's own inputs
// use 2e2 to 8e5; a fuzzed file's tether of 100 000 links used 6.8e6 before Newton's first
// step (its first guess and the first Jacobian's differences) and ran for minutes.
constexpr double kMostStaticLineWork = 2e7;

struct EquilibriumOptions {
  int max_iterations = 100;   // Newton iterations on the shared points
  int stall_iterations = 0;   // given up when so many in a row gain less than 1 % (0: never)
  double tolerance = 1e-9;    // converged when residual <= tolerance * force_scale
  double max_line_work = kMostStaticLineWork;  // station-iterations, above
  // Where the held lines' work is added up, across calls that share one bound (the
  // relaxation's tries); null: this call's own, from 0.
  double* line_work = nullptr;
  const CancelFlag* cancel = nullptr;
  // A state of the lines to start from (a line each: the shared points where their end
  // stations are, the lines' shapes their warm starts) and every body's pose [m, rad], in
  // place of the scene's positions and the chains' guesses; null: those.
  const std::vector<State>* guess = nullptr;
  const Vec6* guess_poses = nullptr;
  // Called as the relaxation's motion goes on (relaxation.h), with the fraction of its
  // bound used so far (its seconds or its steps, whichever is nearer theirs); none: not called.
  std::function<void(double)> relaxing;
  // Called at each Newton iteration with the fraction of its bounds used so far (its
  // iterations or its work, whichever is nearer); none: not called.
  std::function<void(double)> solving;
};

// The lines held at the first guess the statics start from (each in its own equilibrium with
// its ends there) and the bodies' poses: a state of the whole system, not yet balanced at its
// shared points and free bodies.
struct HeldFirstGuess {
  std::vector<State> states;
  std::vector<Vec6> body_poses;
};
HeldFirstGuess HoldAtFirstGuess(const Model& sys,
                                  const EquilibriumOptions& options = {});

// Each line's state at rest (t = 0). Throws Error naming the line that has no equilibrium, or
// the points and bodies when they do not balance.
std::vector<State> SolveEquilibrium(const Model& sys,
                                          EquilibriumReport* report = nullptr,
                                          const EquilibriumOptions& options = {});

// The force on station j of a line at rest in its scene's water [N]: its links' tensions, its
// weight, buoyancy, the current's drag and the seabed's reaction (an end station's: what its
// point holds).
Vec StaticStationForce(const LineModel& m, const State& s, int j);

// The net force on each shared point (column: the shared point's index) of the lines' static
// states [N]: the sum of its end stations' forces (its own weight, buoyancy and thrust on its
// owner's). Zero at equilibrium.
Points SharedPointResiduals(const Model& sys, const std::vector<State>& states);

// The static load of the lines on body b at `pose` [N, N m about its reference point]: the sum
// of the forces of the end stations at its points (each end link's tension and the station's
// lumped share of weight, buoyancy and the current's drag), with their moments.
Vec6 LinesLoadOnBody(const Model& sys, const std::vector<State>& states, int b,
                     const Vec6& pose);

}  // namespace cablefilm
