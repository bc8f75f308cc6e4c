#pragma once
// A run of a scene held in memory, with no file written, for the Python module: each line's
// output rows (its time, station positions, link tensions and end loads: the doubles its
// results.nc holds, the same run, the same rows) and the points' and bodies' rows (what
// points.csv and body.csv print: core/point_loads.h's PointLoads, here as doubles). The
// command line writes the same rows to files.
#include <string>
#include <vector>

#include "core/end_loads.h"
#include "core/point_loads.h"
#include "run/driver.h"
#include "run/run.h"
#include "scene/scene_def.h"

namespace cablefilm {

// One line's every row, row-major (t = 0 first).
struct MemoryRows {
  long rows = 0;
  std::vector<double> time;       // [s], rows
  std::vector<double> x;          // station positions [m], rows x (s + 1) x kDim: each row a
                                  // State::x as it lies in memory (a column of x, y, z a
                                  // station), so rows x stations x 3 and each axis alike are
                                  // views of it
  std::vector<double> tension;    // link tensions [N], rows x s (0 when slack)
  std::vector<double> end_load;   // end loads [N], rows x 2 x kDim (core/end_loads.h: the
                                  // force the line exerts on what holds its start, its end)
};

// The points' and bodies' rows, row-major (t = 0 first).
struct MemoryPointRows {
  long rows = 0;
  std::vector<double> point_position;  // [m], rows x points x 3
  std::vector<double> point_force;     // [N], rows x points x 3 (the lines' pull on the point)
  std::vector<double> body_pose;       // [m, rad], rows x bodies x 6: x, y, z, about x, y, z
  std::vector<double> body_load;       // [N, N m], rows x bodies x 6: force, moment about the
                                       // reference point
};

struct MemoryRun {
  SceneDef scene;
  Run run;
  std::vector<MemoryRows> lines;  // line i's rows
  MemoryPointRows points;
};

// `model` is BuildModel(scene), checked by CheckModelLimits. Simulates from the scene's initial
// state to its end, or until `stop` is raised, as `cablefilm run` does. A blow-up ends the run
// with run.summary.completed false and its message in run.summary.failure (the rows so far
// kept). Throws Error when the initial state cannot be found.
MemoryRun RunInMemory(const SceneDef& scene, Model model, const CancelFlag* stop);

// The scene's static equilibrium (its free bodies at their equilibrium poses, whatever their
// initial offsets) as a run's first row: run.initial, rows holding that one row. Throws Error
// when there is none.
MemoryRun EquilibriumInMemory(const SceneDef& scene, Model model, const CancelFlag* stop);

}  // namespace cablefilm
