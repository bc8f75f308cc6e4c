#pragma once
// A system of lines (core/model.h) run as its scene says: the static equilibrium of the whole
// system, then the coupled implicit step (core/coupled_step.h) from output row to output row,
// each row handed to every line's sinks (the same sinks a single line's run writes: its CSV,
// its NetCDF file) and to the system's own (the points' forces).
#include <functional>
#include <string>
#include <vector>

#include "core/data.h"
#include "core/equilibrium.h"
#include "run/driver.h"
#include "run/max_tension_log.h"
#include "run/run_extent.h"
#include "run/run_summary.h"
#include "run/time_grid.h"
#include "scene/scene_def.h"

namespace cablefilm {

// Where the system's rows go (a row of every line at once). Row() false stops the run.
class SystemRowSink {
 public:
  virtual ~SystemRowSink() = default;
  virtual bool Row(const Data& sd) = 0;
};

struct SystemRun {
  Model sys;
  TimeGrid grid;                     // the output rows and the step's options (the tightest
                                     // line's tolerance)
  Inputs inputs;                     // the scene's (with the stop flag)
  EquilibriumReport equilibrium;
  double equilibrium_ms = 0;         // [ms]
  Data initial;                // t = 0
  std::vector<RunSummary> lines;     // each line's: its peak, its least tension
  std::vector<RunExtent> extents;    // each line's over every row: the film's colour range
                                     // and world box
  std::vector<MaxTensionLog> row_max;  // each line's largest link tension of every row: the
                                       // pictures' time plots
  RunSummary summary;                // the system's: the peak of all lines, how it ended
  int peak_line = -1;                // the line holding summary.peak
  std::vector<std::vector<std::string>> section_materials;  // each line's (run.h)
};

// Steps a Data from row to row of a grid, as RowStepper steps a line: the run and the
// film's second pass step alike, so that the film repeats the run step for step.
class SystemRowStepper {
 public:
  SystemRowStepper(const Model& sys, Data& sd, const Inputs& in,
                   const TimeGrid& grid)
      : sys_(sys), sd_(sd), in_(in), grid_(grid) {}
  long row() const { return row_; }  // the row reached: 0 is the initial state
  bool done() const { return row_ >= grid_.outputs; }
  // Steps to the next row, its time exactly row x interval (every line's too). Throws
  // BlowUpError, CancelledError (in.stop).
  void Next();

 private:
  const Model& sys_;
  Data& sd_;
  const Inputs& in_;
  const TimeGrid& grid_;
  long row_ = 0;
};

// The system's static equilibrium as its run starts from it (each line's state; the bodies'
// poses in `report`): Newton's, or where Newton fails from the scene's positions, the
// relaxation's (core/relaxation.h) with the run's step options; `solving` and
// `relaxing` told the fraction of their bounds used as Newton and the relaxation go on
// (EquilibriumOptions::solving, ::relaxing). Throws Error when the system has none,
// CancelledError when `stop` is raised.
std::vector<State> SystemStatics(const SceneDef& scene, const Model& sys,
                                 EquilibriumReport* report, const CancelFlag* stop,
                                 const std::function<void(double)>& relaxing = {},
                                 const std::function<void(double)>& solving = {});

// Throws Error when the system has no equilibrium, CancelledError when `stop` is raised.
// `relaxing`, `solving`: as SystemStatics'.
SystemRun PrepareSystemRun(const SceneDef& scene, Model sys, const CancelFlag* stop,
                           const std::function<void(double)>& relaxing = {},
                           const std::function<void(double)>& solving = {});

// `run` made ready to run again from its initial state (no statics) with the step settings of
// `scene` (run's scene with its [simulation] changed): what the snap check runs.
SystemRun RestartSystemRun(const SceneDef& scene, const SystemRun& run);

// Steps a copy of run.initial through the grid: every row to line i's `line_sinks[i]`, to
// `sinks`, and to the run's summaries.
void ExecuteSystemRun(SystemRun& run, const std::vector<std::vector<RowSink*>>& line_sinks,
                      const std::vector<SystemRowSink*>& sinks);

}  // namespace cablefilm
