#pragma once
// A run of a system of lines (system_run.h) held in memory, with no file written, for the
// Python module: each line's rows as a single line's run keeps them (memory_run.h: the
// doubles of lines/<name>/results.nc), and the points' and bodies' rows (what points.csv and
// body.csv print, core/coupled_step.h's PointLoads, here as doubles). Each line is also a
// MemoryRun of its own (its model, its summary, its rows), so that a line of a system reads
// like a single line's run.
#include <vector>

#include "core/cancel.h"
#include "run/memory_run.h"
#include "run/system_run.h"
#include "scene/scene_def.h"

namespace cablefilm {

// The points' and bodies' rows, row-major (t = 0 first).
struct MemorySystemRows {
  long rows = 0;
  std::vector<double> point_position;  // [m], rows x points x 3
  std::vector<double> point_force;     // [N], rows x points x 3 (the lines' pull on the point)
  std::vector<double> body_pose;       // [m, rad], rows x bodies x 6: x, y, z, about x, y, z
  std::vector<double> body_load;       // [N, N m], rows x bodies x 6: force, moment about the
                                       // reference point
};

struct MemorySystemRun {
  SceneDef scene;
  SystemRun run;
  std::vector<MemoryRun> lines;  // line i: its model, summary and rows (run.lines[i]'s)
  MemorySystemRows rows;
};

// `sys` is BuildSystem(scene). Simulates from the system's equilibrium (its free bodies at
// their initial offsets) to the scene's end, or until `stop` is raised, as `cablefilm run`
// does. A blow-up ends the run with run.summary.completed false and its message in
// run.summary.failure (the rows so far kept). Throws Error when the system has no equilibrium.
MemorySystemRun RunSystemInMemory(const SceneDef& scene, Model sys, const CancelFlag* stop);

// The system's static equilibrium (its free bodies at their equilibrium poses, whatever their
// initial offsets) as a run's first row: run.initial, rows holding that one row. Throws Error
// when there is none.
MemorySystemRun SystemEquilibriumInMemory(const SceneDef& scene, Model sys,
                                          const CancelFlag* stop);

}  // namespace cablefilm
