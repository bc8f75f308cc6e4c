#include "io/run_report_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <toml++/toml.h>

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

void WriteRunReport(const std::string& path, const RunSummary& f) {
  const std::vector<std::string>& warnings = f.warnings;
  AtomicFile file(path);
  std::FILE* out = file.stream();
  // TOML, like the scene: a reader of the scene reads this too.
  std::fprintf(out, "# cablefilm run report\n");
  std::fprintf(out, "scheme = %s\n", TomlString(f.scheme).c_str());
  std::fprintf(out, "tolerance = %.17g            # local position error per step [m]; 0: fixed steps\n",
               f.tolerance);
  std::fprintf(out, "start_tolerance = %.17g      # the same while the motion starts [m]; 0: none\n",
               f.start_tolerance);
  std::fprintf(out, "start_end = %.17g            # the start's end [s]\n", f.start_end);
  std::fprintf(out, "duration = %.17g             # simulated [s]\n", f.duration);
  std::fprintf(out, "computer_time = %.6g        # [s] wall time of the simulation\n", f.wall);
  std::fprintf(out, "cpu_time = %.6g             # [s] its CPU time (the stepping thread's)\n",
               f.cpu);
  std::fprintf(out, "steps = %ld\nrejected_steps = %ld\nnewton_iterations = %ld\n", f.stats.steps,
               f.stats.rejected, f.stats.newton_iterations);
  std::fprintf(out, "snap_windows = %ld           # times the implicit steps left a snap to explicit ones\n",
               f.stats.snap_windows);
  std::fprintf(out, "explicit_steps = %ld         # ... the explicit steps among `steps`\n",
               f.stats.explicit_steps);
  std::fprintf(out, "smallest_step = %.17g        # [s]\nlargest_step = %.17g         # [s]\n",
               f.stats.record.smallest_step, f.stats.record.largest_step);
  std::fprintf(out, "snaps = %ld                  # links going from slack to taut\n",
               f.stats.record.snaps);
  std::fprintf(out, "unresolved_snaps = %ld       # ... within a step > %.2g of their rise time\n",
               f.stats.record.unresolved_snaps, kResolvedSnapFraction);
  std::fprintf(out, "peak_tension = %.10g         # [N], the largest tension_max of the %ld rows\n",
               f.peak, f.rows);
  std::fprintf(out, "peak_time = %.10g            # [s]\npeak_link = %d\n", f.peak_t, f.peak_link);
  if (!f.peak_line.empty())  // a system's: the line of peak_link
    std::fprintf(out, "peak_line = %s\n", TomlString(f.peak_line).c_str());
  std::fprintf(out, "min_tension = %.10g          # [N], the smallest tension of any link in the rows\n",
               f.min_tension);
  std::fprintf(out, "min_tension_time = %.10g     # [s]\nmin_tension_link = %d\n", f.min_tension_t,
               f.min_tension_link);
  if (!f.min_tension_line.empty())
    std::fprintf(out, "min_tension_line = %s\n", TomlString(f.min_tension_line).c_str());
  if (!std::isnan(f.start_load_max))  // a line's: the loads on what holds its ends
    std::fprintf(out,
                 "start_load_max = %.10g       # [N], the largest |force| of the line on its start"
                 " (fx_start, fy_start, fz_start)\nstart_load_time = %.10g      # [s]\n"
                 "end_load_max = %.10g         # [N], on its end (fx_end, fy_end, fz_end)\n"
                 "end_load_time = %.10g        # [s]\n",
                 f.start_load_max, f.start_load_t, f.end_load_max, f.end_load_t);
  if (f.ends[0].known()) {  // the end tensions' statistics (run/end_tension_pass.h)
    if (!f.ends_line.empty())  // a system's: the line holding the peak
      std::fprintf(out, "statistics_line = %s\n", TomlString(f.ends_line).c_str());
    std::fprintf(out, "statistics_rows = %ld        # the rows the end tensions' statistics are over (every row, t = 0 included)\n",
                 f.ends[0].samples);
    const char* names[2] = {"start", "end"};
    const char* where[2] = {"station 0", "station s"};
    for (int e = 0; e < 2; ++e) {
      const TensionStatistics& t = f.ends[e];
      const char* n = names[e];
      std::fprintf(out, "tension_%s_mean = %.10g     # [N], tension_%s (the link at %s) over the rows\n",
                   n, t.mean, n, where[e]);
      std::fprintf(out, "tension_%s_std = %.10g      # [N], its standard deviation\n", n, t.sigma);
      std::fprintf(out, "tension_%s_min = %.10g      # [N]\ntension_%s_max = %.10g      # [N]\n", n,
                   t.min, n, t.max);
      std::fprintf(out, "tension_%s_upcrossings = %ld  # upward crossings of its mean\n", n,
                   t.upcrossings);
      std::fprintf(out, "tension_%s_mpm = %.10g      # [N], most probable maximum: mean + std sqrt(2 ln upcrossings)\n",
                   n, t.mpm);
      std::fprintf(out, "tension_%s_psd_m0 = %.10g   # [N^2], the integral of its spectrum (tension_spectrum.csv), about std^2\n",
                   n, t.psd_m0);
    }
  }
  if (f.utilisation_link >= 0) {  // some material has a minimum_breaking_load
    std::fprintf(out, "utilisation_max = %.10g      # [1], the largest tension / minimum_breaking_load of the rows\n",
                 f.utilisation);
    std::fprintf(out, "utilisation_time = %.10g     # [s]\nutilisation_link = %d\n", f.utilisation_t,
                 f.utilisation_link);
    if (!f.utilisation_line.empty())
      std::fprintf(out, "utilisation_line = %s\n", TomlString(f.utilisation_line).c_str());
    std::fprintf(out, "utilisation_tension = %.10g  # [N], that link's tension then\n",
                 f.utilisation_tension);
    std::fprintf(out, "utilisation_breaking_load = %.10g  # [N], its material's MBL\n",
                 f.utilisation_mbl);
    std::fprintf(out, "utilisation_material = %s\n", TomlString(f.utilisation_material).c_str());
  }
  if (!f.refinement.empty()) {  // snaps unresolved: how far the peak moves when refined
    std::fprintf(out, "refinement = %s\n", TomlString(f.refinement).c_str());
    std::fprintf(out, "peak_refined = %.10g         # [N], the peak of the same run so refined\n",
                 f.refined_peak);
    std::fprintf(out, "peak_refined_change = %.6g   # [1], (peak_refined - peak_tension) / peak_tension\n",
                 f.refined_peak_change);
  }
  std::fprintf(out, "peak_converged = %s\n", f.peak_converged() ? "true" : "false");
  std::fprintf(out, "warnings = [");
  for (size_t i = 0; i < warnings.size(); ++i)
    std::fprintf(out, "%s\n  %s", i ? "," : "", TomlString(warnings[i]).c_str());
  std::fprintf(out, "%s]\n", warnings.empty() ? "" : "\n");
  file.Commit();
}

bool ReadRunReport(const std::string& path, RunSummary* s) {
  toml::table r;
  try {
    r = toml::parse_file(path);
  } catch (const std::exception&) {
    return false;
  }
  auto number = [&](const char* key, double fallback) {
    return r[key].value<double>().value_or(fallback);
  };
  auto whole = [&](const char* key) { return r[key].value<long>().value_or(-1); };
  s->scheme = r["scheme"].value<std::string>().value_or("");
  s->tolerance = number("tolerance", 0);
  s->start_tolerance = number("start_tolerance", 0);
  s->start_end = number("start_end", 0);
  s->duration = number("duration", 0);
  s->wall = number("computer_time", 0);
  s->cpu = number("cpu_time", 0);
  s->stats.steps = whole("steps");
  s->stats.rejected = whole("rejected_steps");
  s->stats.newton_iterations = whole("newton_iterations");
  s->stats.snap_windows = std::max(0L, whole("snap_windows"));  // (absent before they were)
  s->stats.explicit_steps = std::max(0L, whole("explicit_steps"));
  s->stats.record.smallest_step = number("smallest_step", 0);
  s->stats.record.largest_step = number("largest_step", 0);
  s->stats.record.snaps = whole("snaps");
  s->stats.record.unresolved_snaps = whole("unresolved_snaps");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  s->peak = number("peak_tension", nan);
  s->peak_t = number("peak_time", nan);
  s->peak_link = static_cast<int>(whole("peak_link"));
  s->min_tension = number("min_tension", nan);
  s->min_tension_t = number("min_tension_time", nan);
  s->min_tension_link = static_cast<int>(whole("min_tension_link"));
  s->peak_line = r["peak_line"].value<std::string>().value_or("");
  s->min_tension_line = r["min_tension_line"].value<std::string>().value_or("");
  s->start_load_max = number("start_load_max", nan);
  s->start_load_t = number("start_load_time", nan);
  s->end_load_max = number("end_load_max", nan);
  s->end_load_t = number("end_load_time", nan);
  s->utilisation = number("utilisation_max", nan);
  s->utilisation_t = number("utilisation_time", nan);
  s->utilisation_link = r.contains("utilisation_max") ? static_cast<int>(whole("utilisation_link")) : -1;
  s->utilisation_tension = number("utilisation_tension", nan);
  s->utilisation_mbl = number("utilisation_breaking_load", nan);
  s->utilisation_material = r["utilisation_material"].value<std::string>().value_or("");
  s->utilisation_line = r["utilisation_line"].value<std::string>().value_or("");
  s->refinement = r["refinement"].value<std::string>().value_or("");
  s->refined_peak = number("peak_refined", nan);
  s->refined_peak_change = number("peak_refined_change", nan);
  const char* names[2] = {"start", "end"};
  for (int e = 0; e < 2; ++e) {
    TensionStatistics& t = s->ends[e];
    const std::string n = std::string("tension_") + names[e] + "_";
    t = TensionStatistics();
    if (!r.contains(n + "mean")) continue;
    t.samples = whole("statistics_rows");
    t.mean = number((n + "mean").c_str(), nan);
    t.sigma = number((n + "std").c_str(), nan);
    t.min = number((n + "min").c_str(), nan);
    t.max = number((n + "max").c_str(), nan);
    t.upcrossings = std::max(0L, whole((n + "upcrossings").c_str()));
    t.mpm = number((n + "mpm").c_str(), nan);
    t.psd_m0 = number((n + "psd_m0").c_str(), nan);
  }
  s->ends_line = r["statistics_line"].value<std::string>().value_or("");
  s->warnings.clear();
  if (const toml::array* w = r["warnings"].as_array())
    for (const toml::node& n : *w) s->warnings.push_back(n.value<std::string>().value_or(""));
  s->completed = true;  // a report is written for a complete run only
  return r.contains("peak_tension");
}

}  // namespace cablefilm
