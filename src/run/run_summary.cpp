#include "run/run_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/snap_monitor.h"

namespace cablefilm {

void RunSummary::AddRow(double t, const Eigen::VectorXd& tension,
                        const Eigen::VectorXd& breaking_load) {
  ++rows;
  int u_link = -1;
  const double u = MaxUtilisation(tension, breaking_load, &u_link);
  if (u_link >= 0 && !(u <= utilisation)) {  // the first row, or a larger one
    utilisation = u;
    utilisation_t = t;
    utilisation_link = u_link;
    utilisation_tension = tension[u_link];
    utilisation_mbl = breaking_load[u_link];
  }
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

void RunSummary::AddEndLoads(double t, const Vec& start, const Vec& end) {
  const double f0 = start.norm(), f1 = end.norm();
  if (!std::isnan(f0) && !(f0 <= start_load_max)) {
    start_load_max = f0;
    start_load_t = t;
  }
  if (!std::isnan(f1) && !(f1 <= end_load_max)) {
    end_load_max = f1;
    end_load_t = t;
  }
}

namespace {

// A statistic of end e's tension (RunSummary::ends).
template <int e, double TensionStatistics::*statistic>
double EndValue(const RunSummary& s) {
  return s.ends[e].*statistic;
}
template <int e>
double EndUpcrossings(const RunSummary& s) {
  return static_cast<double>(s.ends[e].upcrossings);
}

}  // namespace

const SummaryColumn kSummaryColumns[20] = {
    {SummaryColumn::Kind::kNumber, "peak_tension", [](const RunSummary& s) { return s.peak; }},
    {SummaryColumn::Kind::kNumber, "peak_time", [](const RunSummary& s) { return s.peak_t; }},
    {SummaryColumn::Kind::kWhole, "peak_link",
     [](const RunSummary& s) { return static_cast<double>(s.peak_link); }},
    {SummaryColumn::Kind::kNumber, "min_tension",
     [](const RunSummary& s) { return s.min_tension; }},
    {SummaryColumn::Kind::kNumber, "min_tension_time",
     [](const RunSummary& s) { return s.min_tension_t; }},
    {SummaryColumn::Kind::kWhole, "min_tension_link",
     [](const RunSummary& s) { return static_cast<double>(s.min_tension_link); }},
    {SummaryColumn::Kind::kWhole, "snaps",
     [](const RunSummary& s) { return static_cast<double>(s.stats.record.snaps); }},
    {SummaryColumn::Kind::kFlag, "peak_converged",
     [](const RunSummary& s) { return s.peak_converged() ? 1.0 : 0.0; }},
    {SummaryColumn::Kind::kNumber, "tension_start_mean", EndValue<0, &TensionStatistics::mean>},
    {SummaryColumn::Kind::kNumber, "tension_start_std", EndValue<0, &TensionStatistics::sigma>},
    {SummaryColumn::Kind::kNumber, "tension_start_min", EndValue<0, &TensionStatistics::min>},
    {SummaryColumn::Kind::kNumber, "tension_start_max", EndValue<0, &TensionStatistics::max>},
    {SummaryColumn::Kind::kWhole, "tension_start_upcrossings", EndUpcrossings<0>},
    {SummaryColumn::Kind::kNumber, "tension_start_mpm", EndValue<0, &TensionStatistics::mpm>},
    {SummaryColumn::Kind::kNumber, "tension_end_mean", EndValue<1, &TensionStatistics::mean>},
    {SummaryColumn::Kind::kNumber, "tension_end_std", EndValue<1, &TensionStatistics::sigma>},
    {SummaryColumn::Kind::kNumber, "tension_end_min", EndValue<1, &TensionStatistics::min>},
    {SummaryColumn::Kind::kNumber, "tension_end_max", EndValue<1, &TensionStatistics::max>},
    {SummaryColumn::Kind::kWhole, "tension_end_upcrossings", EndUpcrossings<1>},
    {SummaryColumn::Kind::kNumber, "tension_end_mpm", EndValue<1, &TensionStatistics::mpm>},
};

std::vector<std::string> SummaryCells(const RunSummary& s) {
  std::vector<std::string> cells;
  for (const SummaryColumn& c : kSummaryColumns) {
    const double v = c.value(s);
    char buf[40];
    if (c.kind == SummaryColumn::Kind::kNumber) std::snprintf(buf, sizeof buf, "%.10g", v);
    if (c.kind == SummaryColumn::Kind::kWhole) std::snprintf(buf, sizeof buf, "%.0f", v);
    if (c.kind == SummaryColumn::Kind::kFlag) std::snprintf(buf, sizeof buf, "%s", v != 0 ? "true" : "false");
    cells.emplace_back(buf);
  }
  return cells;
}

std::vector<std::string> TrustWarnings(const LineModel& m, const StepStats& stats) {
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
       << "where the steps fall. To resolve them: "
       << "integrator = \"explicit\" with time_step <= " << kResolvedSnapFraction * shortest
       << " s"
       << ", or fewer, more compliant links; or avoid the slack (more pretension)";
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
  if (stats.snap_windows > 0)
    os << "; " << stats.explicit_steps << " of the steps explicit, through "
       << stats.snap_windows << (stats.snap_windows == 1 ? " snap" : " snaps");
  return os.str();
}

}  // namespace cablefilm
