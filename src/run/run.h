#pragma once
// A model of a scene run once: what its files, its pictures and its report are made from. The
// command line writes its rows to files as they come (io/), the Python module keeps them in
// memory (memory_run.h), the film steps a copy of its initial Data again (view/film_pass.h).
#include <string>
#include <vector>

#include "core/cancel.h"
#include "core/data.h"
#include "core/end_loads.h"
#include "core/equilibrium.h"
#include "core/inputs.h"
#include "core/model.h"
#include "run/driver.h"
#include "run/end_tension_pass.h"
#include "run/initial_state.h"
#include "run/max_tension_log.h"
#include "run/run_extent.h"
#include "run/run_summary.h"
#include "run/time_grid.h"
#include "scene/scene_def.h"

namespace cablefilm {

// One line's record of the rows, as they come.
struct LineRecord {
  RunExtent extent;          // over every row: the film's colour range and world box
  MaxTensionLog row_max;     // the largest link tension of every row (the pictures' time plots)
                             // and its end links' (the end tensions' second pass)
  RunningMoments end_moments[2];  // of tension_start and tension_end over the rows
  EndTensionSpectrum spectrum;    // theirs after the run (tension_spectrum.csv)
  RunSummary summary;        // its peak, least tension, end loads, utilisation, steps
  EndLoads row_ends;         // of the row the sinks are given (ExecuteRun's record, first)
  std::vector<std::string> section_materials;  // each section's material name (the
                                               // summary's utilisation_material)
};

struct Run {
  std::string label;               // the run's name among others: "elastic", "inextensible"
  Model model;                     // its free bodies placed where the run starts them
  TimeGrid grid;
  Inputs inputs;                   // the scene's (with the stop flag)
  EquilibriumReport equilibrium;   // with [initial] state = "equilibrium"
  double equilibrium_ms = 0;       // the time it took [ms]
  Data initial;                    // t = 0: the initial state, its tensions, the schemes' start
  std::vector<LineRecord> lines;   // each line's
  RunSummary summary;              // the run's: a model of one line its line's; of several the
                                   // peak of all lines, its line, how it ended
  int peak_line = -1;              // the line holding summary.peak
};

// The name of each section's material.
std::vector<std::string> SectionMaterials(const SceneDef& scene,
                                          const std::vector<SectionDef>& sections);

// The run of `model` (BuildModel(scene)) as `scene` says: its time grid, its initial state
// (MakeInitialState: the static equilibrium or the straight chords) and the Data it starts
// from. Throws Error when the equilibrium is not found, CancelledError when `stop` is raised
// during it; `progress` told how the statics go on.
Run PrepareRun(const SceneDef& scene, Model model, std::string label, const CancelFlag* stop,
               const StaticsCallbacks& progress = {});

// `run` made ready to run again from its initial state (no statics) with the step settings of
// `scene` (run's scene with its [simulation] changed): what the snap check runs.
Run RestartRun(const SceneDef& scene, const Run& run);

// A window of `run` (of a model without free bodies) made ready to run again with the step
// settings of `scene`, as RestartRun: from the lines' `states` at row `first_row` (their
// positions and velocities, and their stick-slip anchors `friction_anchors`: the schemes
// started afresh there) to row `last_row` of its grid. What the snap check of a long run runs.
Run WindowRun(const SceneDef& scene, const Run& run, const std::vector<State>& states,
              const std::vector<Points>& friction_anchors, long first_row, long last_row);

// Steps a copy of run.initial through the grid (run/driver.h), every row to `sinks` and to the
// run's own record (each line's extent, row maxima, summary; the run's summary: how it ended,
// its steps, its warnings); then each line's end tensions' statistics and spectrum from the
// rows it kept (run/end_tension_pass.h). The record sees each row first: `sinks` may read its end loads,
// run.lines[i].row_ends.
void ExecuteRun(Run& run, const std::vector<RowSink*>& sinks);

// The name of a link law, as runs are labelled: "elastic", "inextensible".
const char* LawName(LinkLaw law);

// The run's name for a model: "elastic" unless every line is inextensible.
const char* ModelLawName(const Model& model);

}  // namespace cablefilm
