#pragma once
// cablefilm sweep: one scene run over the cross product of values of some of its keys (or the
// rows of a CSV of cases), each case `cablefilm run` in a child process of its own, in a folder
// of its own, at most `jobs` at a time; the summary in DIR/sweep.csv.
#include <string>
#include <vector>

#include "app/commands.h"
#include "run/sweep_plan.h"

namespace cablefilm {

struct SweepOptions {
  std::vector<SweepKey> sets;  // the --set options, in their order
  std::string cases_csv;       // --cases: empty for none
  int jobs = 0;                // cases at a time; 0: one per core
  bool prepare = false;        // write the case folders and sweep.csv ("not run"), run nothing
  bool summary_only = false;   // run the cases on threads of this process and write sweep.csv
                               // alone (no case folders, no per-case files)
  RunOptions run;              // out_dir: the sweep's folder; the rest goes to every case's run
};

int SweepCommand(const std::string& scene_path, const SweepOptions& options);

}  // namespace cablefilm
