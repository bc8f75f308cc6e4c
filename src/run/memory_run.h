#pragma once
// A run of a scene held in memory, with no file written: every output row's time, station
// positions and link tensions (the doubles results.nc holds: the same run, the same rows), for
// the Python module; the command line writes the same rows to files.
#include <string>
#include <vector>

#include "core/end_loads.h"
#include "run/driver.h"
#include "run/run.h"
#include "scene/scene_def.h"

namespace cablefilm {

// Every row, row-major (t = 0 first).
struct MemoryRows : RowSink {
  long rows = 0;
  std::vector<double> time;       // [s], rows
  std::vector<double> x;          // station positions [m], rows x (s + 1) x kDim: each row a
                                  // State::x as it lies in memory (a column of x, y, z a
                                  // station), so rows x stations x 3 and each axis alike are
                                  // views of it
  std::vector<double> tension;    // link tensions [N], rows x s (0 when slack)
  std::vector<double> end_load;   // end loads [N], rows x 2 x kDim (core/end_loads.h: the
                                  // force the line exerts on what holds its start, its end)
  bool Row(const LineData& d) override;
  // Rows for `m`, whose end loads are computed in `in` (both outlive the rows' filling).
  void Reserve(const LineModel& m, const Inputs& in, long rows);

 private:
  const LineModel* model_ = nullptr;
  const Inputs* inputs_ = nullptr;
  EndLoads ends_;
};

struct MemoryRun {
  SceneDef scene;
  Run run;
  MemoryRows rows;
};

// `model` is BuildModel(scene), checked by CheckModelLimits. Simulates from the scene's initial
// state to its end, or until `stop` is raised. A blow-up ends the run with
// run.summary.completed false and its message in run.summary.failure (the rows so far kept).
// Throws Error when the initial state cannot be found.
MemoryRun RunInMemory(const SceneDef& scene, const LineModel& model, const CancelFlag* stop);

}  // namespace cablefilm
