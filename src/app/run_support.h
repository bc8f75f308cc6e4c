#pragma once
// What the commands that run a scene share: the signals that stop a run cleanly, the output
// folder, results.nc's attributes, the stricter step control of the snap check.
#include <atomic>
#include <string>

#include "app/run_options.h"
#include "io/results_nc.h"
#include "io/out_dir_lock.h"
#include "run/run_summary.h"
#include "scene/scene_def.h"

namespace cablefilm {

// The signal that asked the work to stop (0: none yet). The first SIGINT or SIGTERM sets it
// (the run stops at its next row, partial results kept); a second exits at once.
extern std::atomic<int> g_signal;
void InstallSignalHandlers();
// The exit status after a signal stopped the work (128 + its number).
int InterruptedExitStatus();

// results.nc's attributes: the scene (its path and text), the model's name ("elastic"), the
// program's version; and the rows a complete run writes (its storage: DeflateResults).
NetcdfResultsInfo MakeNetcdfInfo(const SceneDef& scene, const char* model, long rows);

// The run's output folder (options.out_dir, or output/<scene name>), created and locked
// (`lock` holds it until the run ends: one run at a time in a folder), with the results of an
// earlier run removed. Throws Error.
std::string PrepareOutDir(const SceneDef& scene, const RunOptions& options, OutDirLock& lock);

// Snaps unresolved in time make the peak depend on where the steps fall (SnapMonitor): a run
// and a system's run are made again, in memory, with their step control four to ten times
// stricter, to say by how much (issue 21, item 4). Makes `sim` (the scene's, run with the
// automatic tolerance `tolerance` [m], 0 for fixed steps, and `snap_windows` explicit windows
// through snaps) that stricter one; returns how, for the report. Implicit with the automatic
// step: the tolerance / 10 (the local error grows as h^3: steps about 2.2 times shorter), and
// the safety factor / 4 of its explicit steps through snaps if it took any; a fixed step: / 4;
// the explicit "auto": its safety factor / 4.
std::string RefineStepControl(SimulationDef& sim, double tolerance, long snap_windows);
// Sets s's refinement, refined_peak and refined_peak_change from the summary of the run made
// again as `how` says (not completed: a failure or an interruption, said in s's refinement),
// and prints them ("snap check: ...").
void ReportRefinement(const std::string& how, const RunSummary& refined, RunSummary* s);
// A run whose snaps were all stepped explicitly (explicit windows, core/explicit_snaps.h) is
// checked all the same: the implicit steps after each window take the ringing the snap left at
// the line's highest axial frequencies, which the refined run (without numerical damping)
// keeps. The warning that makes its peak not converged when the refined peak differs by more
// than kRingingTolerance (or the refined run did not finish); empty if within it.
constexpr double kRingingTolerance = 0.02;
std::string RingingWarning(const RunSummary& s);

}  // namespace cablefilm
