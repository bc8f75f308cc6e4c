#include "app/run_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/snap_monitor.h"
#include "io/atomic_file.h"

namespace cablefilm {
namespace {

// A TOML basic string: quotes and backslashes escaped, control characters dropped.
std::string TomlString(const std::string& text) {
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) quoted += c;
  }
  return quoted + "\"";
}

}  // namespace

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

void WriteRunReport(const std::string& path, const RunFacts& f,
                    const std::vector<std::string>& warnings) {
  AtomicFile file(path);
  std::FILE* out = file.stream();
  // TOML, like the scene: a reader of the scene reads this too.
  std::fprintf(out, "# cablefilm run report\n");
  std::fprintf(out, "scheme = %s\n", TomlString(f.scheme).c_str());
  std::fprintf(out, "tolerance = %.17g            # local position error per step [m]; 0: fixed steps\n",
               f.tolerance);
  std::fprintf(out, "duration = %.17g             # simulated [s]\n", f.duration);
  std::fprintf(out, "computer_time = %.6g        # [s]\n", f.wall);
  std::fprintf(out, "steps = %ld\nrejected_steps = %ld\nnewton_iterations = %ld\n", f.stats.steps,
               f.stats.rejected, f.stats.newton_iterations);
  std::fprintf(out, "smallest_step = %.17g        # [s]\nlargest_step = %.17g         # [s]\n",
               f.stats.record.smallest_step, f.stats.record.largest_step);
  std::fprintf(out, "snaps = %ld                  # links going from slack to taut\n",
               f.stats.record.snaps);
  std::fprintf(out, "unresolved_snaps = %ld       # ... within a step > %.2g of their rise time\n",
               f.stats.record.unresolved_snaps, kResolvedSnapFraction);
  std::fprintf(out, "peak_tension = %.10g         # [N], the largest tension_max of the %ld rows\n",
               f.peak, f.rows);
  std::fprintf(out, "peak_time = %.10g            # [s]\npeak_link = %d\n", f.peak_t, f.peak_link);
  std::fprintf(out, "min_tension = %.10g          # [N], the smallest tension of any link in the rows\n",
               f.min_tension);
  std::fprintf(out, "min_tension_time = %.10g     # [s]\nmin_tension_link = %d\n", f.min_tension_t,
               f.min_tension_link);
  std::fprintf(out, "peak_converged = %s\n", warnings.empty() ? "true" : "false");
  std::fprintf(out, "warnings = [");
  for (size_t i = 0; i < warnings.size(); ++i)
    std::fprintf(out, "%s\n  %s", i ? "," : "", TomlString(warnings[i]).c_str());
  std::fprintf(out, "%s]\n", warnings.empty() ? "" : "\n");
  file.Commit();
}

}  // namespace cablefilm
