#pragma once
// What the commands that run a scene share: the signals that stop a run cleanly, the output
// folder, results.nc's attributes.
#include <atomic>
#include <string>

#include "app/run_options.h"
#include "io/results_nc.h"
#include "io/out_dir_lock.h"
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

}  // namespace cablefilm
