#pragma once
// run_report.toml: what a finished run says about itself (run/run_summary.h), beside its
// results, so a script or a later reader sees what the run printed.
#include <string>
#include <vector>

#include "run/run_summary.h"

namespace cablefilm {

// Writes a run's summary to `path` (run_report.toml, run_report_inextensible.toml), whole or not
// at all.
void WriteRunReport(const std::string& path, const RunSummary& summary);

// The summary a run_report.toml holds (the numbers a sweep's row shows); false when `path` is
// none such.
bool ReadRunReport(const std::string& path, RunSummary* summary);

}  // namespace cablefilm
