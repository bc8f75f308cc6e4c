#pragma once
// What a run says about itself: the steps it took, its peak and least tension over the rows,
// how it ended, and whether its peak can be trusted. One struct with one writer each: printed
// after the run, written beside its results as run_report.toml (io/run_report_file.h), a row
// of sweep.csv (SummaryCells), a Python dict (python/module.cpp).
#include <limits>
#include <string>
#include <vector>

#include "core/line_data.h"
#include "core/line_model.h"
#include "run/tension_statistics.h"

namespace cablefilm {

struct RunSummary {
  std::string scheme;             // the scheme's name (core/line_data.h, SchemeName)
  double tolerance = 0;           // local position error per step [m]; 0: fixed steps
  double start_tolerance = 0;     // the stricter one while the motion starts [m]; 0: none
  double start_end = 0;           // until then [s]
  double duration = 0;            // simulated: the time reached [s]
  double wall = 0;                // computer time of the stepping: wall time [s]
  double cpu = 0;                 // its CPU time, the stepping thread's (steady under load) [s]
  StepStats stats;
  long rows = 0;                  // output rows handed out (t = 0 included)
  // Over the rows, as timeseries.csv has them: the largest tension_max (the first row holding
  // it) and the smallest tension of any link (the first), their times and links.
  double peak = std::numeric_limits<double>::quiet_NaN();            // [N]
  double peak_t = std::numeric_limits<double>::quiet_NaN();          // [s]
  int peak_link = -1;
  double min_tension = std::numeric_limits<double>::quiet_NaN();     // [N]
  double min_tension_t = std::numeric_limits<double>::quiet_NaN();   // [s]
  int min_tension_link = -1;
  // The largest end load over the rows (|force| the line exerts on what holds its start,
  // station 0, and its end, station s; core/end_loads.h) [N], and the first time of each [s].
  // NaN where the rows held none (the summary of a run of several lines).
  double start_load_max = std::numeric_limits<double>::quiet_NaN();
  double start_load_t = std::numeric_limits<double>::quiet_NaN();
  double end_load_max = std::numeric_limits<double>::quiet_NaN();
  double end_load_t = std::numeric_limits<double>::quiet_NaN();
  // The statistics of the end links' tensions over the rows (tension_start and tension_end of
  // timeseries.csv; run/end_tension_pass.h): [0] at station 0, [1] at station s. A run of
  // several lines: those of the line holding the peak (`ends_line`).
  TensionStatistics ends[2];
  std::string ends_line;
  // A run of several lines: the lines holding the peak and the least tension (their links are
  // the line's); empty for a line alone.
  std::string peak_line, min_tension_line;
  // The largest utilisation T / MBL over the rows and the links whose material has a
  // minimum_breaking_load (NaN: none has), the first row holding it: its time [s], link,
  // tension [N], that link's MBL [N] and material's name (set by the run, which knows the
  // scene); a system's also its line. Not at the peak tension when the materials differ.
  double utilisation = std::numeric_limits<double>::quiet_NaN();          // [1]
  double utilisation_t = std::numeric_limits<double>::quiet_NaN();        // [s]
  double utilisation_tension = std::numeric_limits<double>::quiet_NaN();  // [N]
  double utilisation_mbl = std::numeric_limits<double>::quiet_NaN();      // [N]
  int utilisation_link = -1;
  std::string utilisation_material, utilisation_line;
  // Snaps unresolved in time (stats.record.unresolved_snaps): the same run made again with a
  // stricter step control (`refinement`, e.g. "tolerance / 10"), its peak [N] and the relative
  // change of the peak it gives [1]; NaN and empty when not made (nothing unresolved).
  std::string refinement;
  double refined_peak = std::numeric_limits<double>::quiet_NaN();
  double refined_peak_change = std::numeric_limits<double>::quiet_NaN();
  bool completed = false;         // every row; false: stopped, or a blow-up (`failure`)
  std::string failure;            // a blow-up's message
  std::vector<std::string> warnings;  // why the peak cannot be trusted (TrustWarnings)
  bool peak_converged() const { return warnings.empty(); }

  // One output row's tensions [N] at time t [s], taken into the peak and the least tension.
  // With the links' breaking loads [N] (Line::breaking_load), the utilisation too.
  void AddRow(double t, const Eigen::VectorXd& tension,
              const Eigen::VectorXd& breaking_load = Eigen::VectorXd());
  // One output row's end loads [N] at time t [s], taken into their largest.
  void AddEndLoads(double t, const Vec& start, const Vec& end);
};

// Reasons the peak tension cannot be trusted (empty: none found): snaps within steps too long to
// resolve them (see core/snap_monitor.h), with what would resolve them (explicit steps short
// enough).
std::vector<std::string> TrustWarnings(const LineModel& m, const StepStats& stats);

// "N steps (M rejected) from a to b s[, k Newton iterations per step]".
std::string DescribeSteps(const StepStats& stats);

// The columns of a sweep's row from a run's summary (after the case's status and message): each
// its name, its kind and its value; the one place they are spelled (sweep.csv, the Python
// module's sweep rows). The peak's and the least tension's, then each end tension's statistics
// (tension_start_mean, ..., tension_end_mpm).
struct SummaryColumn {
  enum class Kind { kNumber, kWhole, kFlag } kind;
  const char* name;
  double (*value)(const RunSummary&);
};
extern const SummaryColumn kSummaryColumns[20];
// The cells of the columns: numbers with 10 significant digits (as run_report.toml has them),
// whole numbers, true or false.
std::vector<std::string> SummaryCells(const RunSummary& s);

}  // namespace cablefilm
