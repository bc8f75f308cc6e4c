#pragma once
// The program's commands. Each returns the process exit status; errors are thrown as Error.
#include <limits>
#include <string>

#include "app/run_options.h"
#include "app/run_support.h"

namespace cablefilm {

int RunCommand(const std::string& scene_path, const RunOptions& options,
               RunReport* report = nullptr);
int CheckCommand(const std::string& scene_path);
// Runs the scene with the elastic and the inextensible model: timeseries.csv and
// timeseries_inextensible.csv, max_tension.png with both (the paper's Figure 1), the film.
int CompareCommand(const std::string& scene_path, const RunOptions& options);

}  // namespace cablefilm
