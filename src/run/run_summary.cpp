#include "run/run_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/snap_monitor.h"

namespace cablefilm {

std::vector<std::string> TrustWarnings(const CableModel& m, const IntegratorStats& stats) {
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

std::string DescribeSteps(const IntegratorStats& stats) {
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
