#pragma once
// The static equilibrium of a system of lines (system.h): the paper's initial state for a
// mooring. Each line is in equilibrium (SolveEquilibrium, equilibrium.h) with its ends at its
// points; the shared points (free points where several lines meet) are where the forces of
// their lines balance: Newton's method on their positions, kDim unknowns per point, with a
// Jacobian of finite differences (each column re-solves the lines at one point, from their
// last equilibrium) and a backtracking line search.
#include <vector>

#include "core/equilibrium.h"
#include "core/system.h"

namespace cablefilm {

struct SystemEquilibriumReport {
  int iterations = 0;         // Newton iterations on the shared points
  double residual = 0;        // the largest out-of-balance force on a shared point at the end [N]
  double force_scale = 0;     // the load it is measured against: the lines' (StaticForceScale)
  std::vector<EquilibriumReport> lines;  // each line's last solve
};

struct SystemEquilibriumOptions {
  int max_iterations = 100;   // Newton iterations on the shared points
  double tolerance = 1e-9;    // converged when residual <= tolerance * force_scale
  const CancelFlag* cancel = nullptr;
};

// Each line's state at rest (t = 0). Throws Error naming the line that has no equilibrium, or
// the points when they do not balance.
std::vector<State> SolveSystemEquilibrium(const SystemModel& sys,
                                          SystemEquilibriumReport* report = nullptr,
                                          const SystemEquilibriumOptions& options = {});

// The net force on each shared point (column: the shared point's index) of the lines' static
// states [N]: the sum of its end stations' forces (its own weight, buoyancy and thrust on its
// owner's). Zero at equilibrium.
Points SharedPointResiduals(const SystemModel& sys, const std::vector<State>& states);

}  // namespace cablefilm
