#pragma once
// The program's commands. Each returns the process exit status; errors are thrown as Error.
#include <limits>
#include <string>

#include "app/run_options.h"
#include "app/run_support.h"

namespace cablefilm {

// Simulates the scene into its output folder (io/run_files.h), draws max_tension.png and the
// film.
int RunCommand(const std::string& scene_path, const RunOptions& options,
               RunReport* report = nullptr);
// Validates the scene and finds its initial state, printing what it is.
int CheckCommand(const std::string& scene_path);
// Runs the scene with the elastic and the inextensible model (each line that can run
// inextensible: a line between points that hold it), the second's files named *_inextensible,
// max_tension.png with both (the paper's Figure 1), the film of both.
int CompareCommand(const std::string& scene_path, const RunOptions& options);
// `convert`: a MoorDyn v2 input file's equivalent scene (TOML) to `out_path` (empty or "-":
// standard output); what it leaves out as warnings on standard error.
int ConvertCommand(const std::string& path, const std::string& out_path);

}  // namespace cablefilm
