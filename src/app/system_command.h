#pragma once
// `check` and `run` of a system of lines ([[line]] and [[point]]): its summary and static
// equilibrium; its results, a folder per line (lines/<name>/: equilibrium.csv,
// timeseries.csv, results.nc, run_report.toml, as a single line writes them), points.csv and
// the system's run_report.toml.
#include <string>

#include "app/run_options.h"
#include "scene/scene_def.h"

namespace cablefilm {

int CheckSystem(const SceneDef& scene);
// `convert`: a MoorDyn v2 input file's equivalent scene (TOML) to `out_path` (empty or "-":
// standard output); what it leaves out as warnings on standard error.
int ConvertCommand(const std::string& path, const std::string& out_path);
int RunSystem(const SceneDef& scene, const RunOptions& options, RunReport* report);

}  // namespace cablefilm
