#include "io/run_report_file.h"

#include <cstdio>

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
