#pragma once
// run_report.toml: what a finished run says about itself (run/run_summary.h), beside its
// results, so a script or a later reader sees what the run printed.
#include <string>
#include <vector>

#include "run/run_summary.h"

namespace cablefilm {

// Writes run_report<suffix>.toml into out_dir, whole or not at all.
void WriteRunReport(const std::string& path, const RunFacts& facts,
                    const std::vector<std::string>& warnings);

}  // namespace cablefilm
