#include "run/run_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/snap_monitor.h"

namespace cablefilm {

void RunSummary::AddRow(double t, const Eigen::VectorXd& tension) {
  ++rows;
  Eigen::Index link = 0;
  const double tmax = tension.maxCoeff(&link);  // the row's tension_max and link_max
  // The first row, or a larger tension (NaN peak: none yet); the first of equal ones stays.
  if (!std::isnan(tmax) && !(tmax <= peak)) {
    peak = tmax;
    peak_t = t;
    peak_link = static_cast<int>(link);
  }
  const double tmin = tension.minCoeff(&link);
  if (std::isnan(min_tension) || tmin < min_tension) {
    min_tension = tmin;
    min_tension_t = t;
    min_tension_link = static_cast<int>(link);
  }
}

const char* const kSummaryColumns[] = {"peak_tension",     "peak_time",        "peak_link",
                                       "min_tension",      "min_tension_time", "min_tension_link",
                                       "snaps",            "peak_converged",   nullptr};

std::vector<std::string> SummaryCells(const RunSummary& s) {
  auto number = [](double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return std::string(buf);
  };
  return {number(s.peak),
          number(s.peak_t),
          std::to_string(s.peak_link),
          number(s.min_tension),
          number(s.min_tension_t),
          std::to_string(s.min_tension_link),
          std::to_string(s.stats.record.snaps),
          s.peak_converged() ? "true" : "false"};
}

std::vector<std::string> TrustWarnings(const Model& m, const StepStats& stats) {
  std::vector<std::string> warnings;
  const StepRecord& r = stats.record;
  if (r.unresolved_snaps > 0) {
    const SnapMonitor monitor(m);
    const double tau = monitor.snap_times()[r.first_unresolved_link];  // [s]
    const double shortest = monitor.snap_times().minCoeff();
    std::ostringstream os;
    os.precision(3);
    os << "the peak tension is not converged: " << r.unresolved_snaps << " of " << r.snaps
       << " snaps (a link going from slack to taut) fell within a step longer than "
       << kResolvedSnapFraction << " of the time a snap load takes to rise (tau = pi / the "
       << "link's axial frequency: " << tau << " s for link " << r.first_unresolved_link
       << ", first at t = " << r.first_unresolved_time << " s; steps up to "
       << r.worst_snap_ratio << " tau). Snap loads and the ringing after them then depend on "
       << "where the steps fall. To resolve them: integrator = \"explicit\" with time_step <= "
       << kResolvedSnapFraction * shortest << " s, or fewer, more compliant links; or "
       << "avoid the slack (more pretension)";
    warnings.push_back(os.str());
  }
  return warnings;
}

std::string DescribeSteps(const StepStats& stats) {
  std::ostringstream os;
  os.precision(4);
  os << stats.steps << " steps";
  if (stats.rejected > 0 || stats.newton_iterations > 0) os << " (" << stats.rejected << " rejected)";
  os << " from " << stats.record.smallest_step << " to " << stats.record.largest_step << " s";
  if (stats.newton_iterations > 0) {
    os.precision(3);
    os << ", " << static_cast<double>(stats.newton_iterations) / std::max(1L, stats.steps)
       << " Newton iterations per step";
  }
  return os.str();
}

}  // namespace cablefilm
