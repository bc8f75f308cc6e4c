#pragma once
// The static equilibrium of a model (model.h), its initial state at rest with its ends at
// their t = 0 positions (the paper's): each island on its own. An island of one line between
// points that hold it is the line's statics (line_equilibrium.h: Newton continued in the
// current, from its coarse copies' shape for a long one: coarse_guess.h; the inextensible
// line's own), within a bound on its work (kMostLineStaticsWork); a coupled
// island's shared points and free bodies are where their lines' loads balance
// (coupled_equilibrium.h), found, where Newton does not reach them from the scene's positions,
// from where the island's own damped motion brings it (relaxation.h).
#include <functional>
#include <optional>
#include <vector>

#include "core/inputs.h"
#include "core/line_data.h"
#include "core/line_equilibrium.h"
#include "core/model.h"

namespace cablefilm {

struct EquilibriumReport {
  int iterations = 0;         // Newton iterations on the shared points and free bodies
  int chains = 0;             // chains of lines solved as one line first (chain_guess.h)
  double residual = 0;        // the largest out-of-balance force on a shared point or body at
                              // the end [N] (a body's moment divided by its size [m])
  double force_scale = 0;     // the load it is measured against: the lines' (StaticForceScale)
  double line_work = 0;       // the lines' solves, in station-passes (a single line's its own,
                              // a coupled island's its held lines' and its chains')
  std::vector<LineEquilibriumReport> lines;  // each line's (last) solve
  std::vector<Vec6> body_poses;          // each body's pose (a free body's as solved)
  double relaxed = 0;  // s of the system's damped motion it took to get near enough for Newton
                       // (relaxation.h); 0: none, from the scene's first guess
};

// The held lines' solves at most, in station-passes (each pass over a line's stations: a
// residual, a step along its links, a Newton matrix; kMostLineStaticsWork, summed over the
// solves of a coupled island's lines, a chain's solve as one line not counted): a system that
// needs more is not near its equilibrium, and the statics should give way (to the relaxation:
// relaxation.h) in seconds, not minutes (some 5 to 15 s at 0.05 to 0.15 us a station-pass).
// The shipped scenes and MoorDyn's own inputs use 2e2 to 4e6 (a clump chain of 10^6 links
// between two lines: 5e6); a fuzzed file's tether of 100 000 links used 6.8e6
// station-iterations before Newton's first step and ran for minutes.
constexpr double kMostStaticLineWork = 1e8;

struct EquilibriumOptions {
  // Where Newton fails on a coupled island: the relaxation's steps (the run's scheme and
  // tolerance, relaxation.h); none: Newton alone, and its failure thrown.
  std::optional<StepOptions> relaxation;
  Inputs inputs;              // the relaxation's (the scene's: SceneInputs)
  int max_iterations = 100;   // Newton iterations on the shared points
  int stall_iterations = 0;   // given up when so many in a row gain less than 1 % (0: never)
  double tolerance = 1e-9;    // converged when residual <= tolerance * force_scale
  double max_line_work = kMostStaticLineWork;  // station-passes, above
  // Each line's solve at most (a single line's, a chain's as one line, a held line's), in
  // station-passes (kMostLineStaticsWork): StaticsWorkError past it, which no fallback catches.
  double max_line_statics = kMostLineStaticsWork;
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

// Each line's state at rest (t = 0), island by island (a single line's statics from its
// coarse line's shape and continued in the current, unless options.guess gives a state to
// start from). Throws Error naming the line that has no equilibrium, or the points and bodies
// that do not balance; CancelledError when options.cancel is raised.
std::vector<State> SolveEquilibrium(const Model& model, EquilibriumReport* report = nullptr,
                                    const EquilibriumOptions& options = {});

// Every line on the chord between its ends at rest, at rest (the "straight" initial state).
std::vector<State> StraightStart(const Model& model);

}  // namespace cablefilm
