#pragma once
// A model of a scene run once: what its files, its pictures and its report are made from. The
// command line writes its rows to files as they come (io/), the Python module keeps them in
// memory (memory_run.h), the film steps a copy of its initial LineData again (view/film_pass.h).
#include <string>
#include <vector>

#include "core/cancel.h"
#include "core/line_data.h"
#include "core/end_loads.h"
#include "core/line_equilibrium.h"
#include "core/inputs.h"
#include "core/line_model.h"
#include "run/driver.h"
#include "run/max_tension_log.h"
#include "run/run_extent.h"
#include "run/run_summary.h"
#include "run/time_grid.h"
#include "scene/scene_def.h"

namespace cablefilm {

struct Run {
  std::string label;               // the model's name: "elastic", "inextensible"
  LineModel model;
  TimeGrid grid;
  Inputs inputs;                   // the scene's (with the stop flag)
  LineEquilibriumReport equilibrium;   // with [initial] state = "equilibrium"
  double equilibrium_ms = 0;       // the time it took [ms]
  LineData initial;                    // t = 0: the initial state, its tensions, the scheme's start
  RunExtent extent;                // of every row: the film's colour range and world box
  MaxTensionLog row_max;           // the largest link tension of every row
  RunSummary summary;
  EndLoads row_ends;               // of the row the sinks are given (ExecuteRun's record, first)
  std::vector<std::string> section_materials;  // each section's material name (the summary's
                                               // utilisation_material)
};

// The name of each section's material.
std::vector<std::string> SectionMaterials(const SceneDef& scene,
                                          const std::vector<SectionDef>& sections);

// The run of `model` as `scene` says: its time grid, its initial state (the static equilibrium
// or the straight chord) and the LineData it starts from. Throws Error when the equilibrium is not
// found, CancelledError when `stop` is raised during it.
Run PrepareRun(const SceneDef& scene, LineModel model, std::string label, const CancelFlag* stop);

// Steps a copy of run.initial through the grid (run/driver.h), every row to `sinks` and to the
// run's own record (extent, row maxima, summary: how it ended, its steps, its warnings). The
// record sees each row first: `sinks` may read its end loads, run.row_ends.
void ExecuteRun(Run& run, const std::vector<RowSink*>& sinks);

// The name of a link law, as runs are labelled: "elastic", "inextensible".
const char* LawName(LinkLaw law);

}  // namespace cablefilm
