#pragma once
// The static equilibrium of a coupled island (model.h, Island; or of any model, its islands
// together): the paper's initial state for a mooring. Each line is in equilibrium (SolveLineEquilibrium, line_equilibrium.h) with its ends at its
// points; the shared points (free points where several lines meet) are where the forces of
// their lines balance, and a free body (body.h) is where its lines' loads balance its own:
// Newton's method on the shared points' positions (kDim unknowns per point) and the free
// bodies' poses (6 per body), with a Jacobian of finite differences (each column re-solves
// the lines at one point or body, from their last equilibrium), Broyden's updates and a
// backtracking line search.
#include <vector>

#include "core/equilibrium.h"

namespace cablefilm {

// The lines held at the first guess the statics start from (each in its own equilibrium with
// its ends there) and the bodies' poses: a state of the whole system, not yet balanced at its
// shared points and free bodies.
struct HeldFirstGuess {
  std::vector<State> states;
  std::vector<Vec6> body_poses;
};
HeldFirstGuess HoldAtFirstGuess(const Model& sys,
                                  const EquilibriumOptions& options = {});
// The same with `models`, sys.lines or a copy of them, held where they are (their ends moved,
// and put back as they were before it returns or throws): no copy of a long line's model.
HeldFirstGuess HoldAtFirstGuessInPlace(const Model& sys, std::vector<LineModel>& models,
                                       const EquilibriumOptions& options);

// Each line's state at rest (t = 0), Newton's alone (from options.guess when given). Throws
// Error naming the line that has no equilibrium, or the points and bodies when they do not
// balance.
std::vector<State> SolveCoupledEquilibrium(const Model& sys, EquilibriumReport* report = nullptr,
                                           const EquilibriumOptions& options = {});
// The same with `models` held in place, as HoldAtFirstGuessInPlace.
std::vector<State> SolveCoupledEquilibriumInPlace(const Model& sys,
                                                  std::vector<LineModel>& models,
                                                  EquilibriumReport* report,
                                                  const EquilibriumOptions& options);

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
