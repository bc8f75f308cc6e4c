#pragma once
// The maxima of a sweep's runs (one storm run with several random seeds, or any sweep): each
// finished case's largest tension (peak_tension) and largest end tensions (tension_start_max,
// tension_end_max), and with at least kMinGumbelMaxima of them a Gumbel fit (run/gumbel_fit.h):
// its mode, the most probable maximum of one run, and its 90 % quantile. Printed at the sweep's
// end and written as sweep_maxima.toml beside sweep.csv.
#include <string>
#include <vector>

#include "run/gumbel_fit.h"
#include "run/sweep.h"

namespace cablefilm {

struct SweepMaxima {
  const char* name;                 // the column of sweep.csv: "peak_tension", ...
  std::vector<std::size_t> cases;   // the finished cases (status "ok") with a finite maximum
  std::vector<double> maxima;       // theirs [N]
  bool fitted = false;              // at least kMinGumbelMaxima: `fit` holds the fit
  GumbelFit fit;
};

// The maxima of the finished cases among `outcomes`, column by column.
std::vector<SweepMaxima> CollectSweepMaxima(const std::vector<CaseOutcome>& outcomes);

// sweep_maxima.toml's text: a table per column, its cases and maxima, and the fit's numbers.
std::string SweepMaximaToml(const std::vector<SweepMaxima>& columns);

// A line per fitted column, as the sweep prints it: "peak_tension: Gumbel fit of 10 maxima:
// most probable maximum (mode) ... N, 90 % quantile ... N (mean ..., std ...)".
std::vector<std::string> DescribeSweepMaxima(const std::vector<SweepMaxima>& columns);

}  // namespace cablefilm
