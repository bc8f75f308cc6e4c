#pragma once
// The statistics of a line's two end tensions (tension_start and tension_end of timeseries.csv:
// the tensions of the links at station 0 and station s) over a run's rows, in two passes of
// bounded memory. The first, as the rows come: their moments (RunningMoments, per row O(1)).
// The second, after the run, over the rows the run kept on disk (MaxTensionLog): the
// up-crossings of the exact mean (of the whole record, not a running estimate that drifts
// while the run starts) and the Welch spectrum of the tension less that mean.
#include <vector>

#include "run/max_tension_log.h"
#include "run/running_moments.h"
#include "run/tension_statistics.h"

namespace cablefilm {

// The one-sided spectral density of each end tension, tension_spectrum.csv's columns.
struct EndTensionSpectrum {
  std::vector<double> frequency;   // [Hz]
  std::vector<double> density[2];  // of tension_start and tension_end [N^2/Hz]
  int segment = 0;                 // samples per Welch segment (0: no spectrum, too few rows)
  int segments = 0;                // segments averaged
  bool empty() const { return frequency.empty(); }
};

// The statistics of ends 0 (tension_start) and 1 (tension_end) of a line whose rows, every
// `interval` [s], are in `rows` and whose moments the first pass took in `moments`; its spectrum
// into `spectrum`. Throws Error when the kept rows cannot be read.
void EndTensionPass(const MaxTensionLog& rows, const RunningMoments moments[2], double interval,
                    TensionStatistics stats[2], EndTensionSpectrum* spectrum);

}  // namespace cablefilm
