#pragma once
// A run of a scene held in memory, with no file written: every output row's time, station
// positions and link tensions (the doubles results.nc holds, computed by the same calls in the
// same order as `cablefilm run`), and what the film pass needs to draw it afterwards. For the
// Python module; the command line writes the same rows to files (commands.cpp).
#include <Eigen/Core>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "run/run_extent.h"
#include "run/simulation_run.h"
#include "core/cable_model.h"
#include "core/cancel.h"
#include "core/integrator.h"
#include "scene/scene_def.h"

namespace cablefilm {

struct MemoryRun {
  SceneDef scene;
  CableModel model;
  TimeGrid grid;
  EquilibriumReport equilibrium;    // filled when the initial state is the static equilibrium
  CableState initial;               // t = 0
  Eigen::VectorXd initial_tension;  // [N], size s
  RunExtent extent;                 // of every row (the film's colour range and box)
  std::string integrator;           // its name
  IntegratorStats stats;
  bool completed = false;           // false: stopped by `cancel`, or a blow-up (failure)
  std::string failure;              // a blow-up's message, as `run` prints it
  // Over the rows, as run_report.toml says them: the largest tension_max (the first row
  // holding it) and the smallest tension of any link (the first), their times and links.
  double peak = std::numeric_limits<double>::quiet_NaN();         // [N]
  double peak_t = std::numeric_limits<double>::quiet_NaN();       // [s]
  int peak_link = -1;
  double min_tension = std::numeric_limits<double>::quiet_NaN();  // [N]
  double min_tension_t = std::numeric_limits<double>::quiet_NaN();  // [s]
  int min_tension_link = -1;
  // The rows (t = 0 first), row-major:
  long rows = 0;
  std::vector<double> time;         // [s], rows
  std::vector<double> x, y;         // station positions [m], rows x (s + 1)
  std::vector<double> tension;      // link tensions [N], rows x s (0 when slack)
};

// Validates nothing: `model` is BuildModel(scene), checked by CheckModelLimits. Simulates from
// the scene's initial state to its end, or until `cancel` is raised or `keep_going` (called
// after every row, may be empty) returns false. A blow-up ends the run with completed false
// and its message in `failure` (the rows so far kept). Throws Error when the initial state
// cannot be found.
MemoryRun RunInMemory(const SceneDef& scene, const CableModel& model, const CancelFlag* cancel,
                      const std::function<bool()>& keep_going = {});

}  // namespace cablefilm
