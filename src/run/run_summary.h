#pragma once
// What a finished run says about itself: the steps it took and whether its peak tension can be
// trusted. Printed after the run and written beside its results as run_report.toml (suffix
// before .toml for compare's second model), so a script or a later reader sees the same.
#include <string>
#include <vector>

#include "core/cable_model.h"
#include "core/integrator.h"

namespace cablefilm {

struct RunFacts {
  std::string scheme;             // the integrator's name
  double tolerance = 0;           // local position error per step [m]; 0: fixed steps
  double duration = 0;            // simulated [s]
  double wall = 0;                // computer time [s]
  IntegratorStats stats;
  double peak = 0, peak_t = 0;    // largest tension_max of the rows [N], when [s]
  int peak_link = 0;
  long rows = 0;
  double min_tension = 0, min_tension_t = 0;  // smallest tension of the rows [N], when [s]
  int min_tension_link = 0;
};

// Reasons the peak tension cannot be trusted (empty: none found): snaps within steps too long to
// resolve them (see core/snap_monitor.h), with what would resolve them.
std::vector<std::string> TrustWarnings(const CableModel& m, const IntegratorStats& stats);

// "N steps (M rejected) from a to b s[, k Newton iterations per step]".
std::string DescribeSteps(const IntegratorStats& stats);

}  // namespace cablefilm
