#pragma once
// A system's static equilibrium that Newton's method (equilibrium.h) does not reach
// from the scene's first guess: a float at the water's surface, whose lumped stations float
// and sink one at a time; a body given above the anchor it hangs below. Found then from where
// the system's own motion brings it when let go at the first guess, damped by its fluid (as
// MoorDyn finds its initial state, by "dynamic relaxation"), Newton tried again every few
// seconds of that motion. The scene's clock stands still meanwhile: its ends and bodies where
// they are at t = 0, its sea calm.
#include <vector>

#include "core/coupled_equilibrium.h"
#include "core/inputs.h"
#include "core/line_data.h"

namespace cablefilm {

// The relaxation's motion at most [s]: a mooring's slowest swings (tens of seconds) damped a
// few times over.
constexpr double kLongestRelaxation = 60.0;
// Its steps at most: a motion that needs more (a float's stations slapping the surface, snaps)
// is not settling, and the statics should fail in seconds, not minutes (20 runs' worth of steps
// at the rows' 1/30 s; a MoorDyn float of 30 links settles in 10 s of motion, 6.4 s).
constexpr long kMostRelaxationSteps = 36000;
// And its work at most: steps, accepted and rejected, times the system's stations (36 000 steps
// of 2 000 stations, some 20 s). A line cut into 100 000 links (a fuzzed file's) would have
// stepped for hours.
constexpr double kMostRelaxationStationSteps = 7.2e7;

// SolveCoupledEquilibrium's answer; when it throws Error, the relaxation's (report->relaxed
// says how many seconds of motion it took). Throws the first Error when the relaxation finds
// none either (or the motion blows up), CancelledError when options.cancel is raised.
// `step`: the implicit scheme's options (MakeData).
// `sys` is the island's own (a copy): its lines are held in place (their ends put back after).
std::vector<State> SolveCoupledEquilibriumRelaxing(Model& sys, const Inputs& in,
                                                   const StepOptions& step,
                                                   EquilibriumReport* report,
                                                   const EquilibriumOptions& options);

}  // namespace cablefilm
