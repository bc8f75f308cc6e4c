#pragma once
// The result files of scene-format.md, each written whole or not at all.
#include <Eigen/Core>
#include <cstdio>
#include <memory>
#include <string>

#include "core/line_model.h"
#include "core/data.h"
#include "core/end_loads.h"
#include "io/atomic_file.h"
#include "run/driver.h"

namespace cablefilm {

// equilibrium.csv: j,s,x,y,z,tension (tension of link j+1/2; empty on the last row).
void WriteEquilibriumCsv(const std::string& path, const LineModel& m, const State& state,
                         const Eigen::VectorXd& tension);

// One row of timeseries.csv, and its header line (shared with the live view's /timeseries.csv).
// `ends` holds the end loads of the row's LineData (core/end_loads.h), computed here. With
// `utilisation` (a line some of whose materials have a minimum_breaking_load) the row ends
// with utilisation_max, the largest T / MBL of those links, and the header with
// kUtilisationColumn; the live view's rows never have it.
extern const char kTimeseriesHeader[];  // with its newline
extern const char kUtilisationColumn[];  // ",utilisation_max", no newline
void WriteTimeseriesRow(std::FILE* f, const LineModel& m, const LineData& d, const Inputs& in,
                        EndLoads& ends, bool utilisation = false);

// timeseries.csv of line `line` of the rows' Data (`m` its model): t,x_end,y_end,z_end,
// tension_start,tension_end,tension_max,link_max, then the end loads fx_start,fy_start,
// fz_start,fx_end,fy_end,fz_end,angle_start,angle_end, and utilisation_max when the line has
// a breaking load; a run's rows as they come. With `row_ends`, each row's end loads as a sink
// before this one computed them (LineRecord::row_ends): they cost as much as a tenth of the
// simulation, and are not computed twice.
class TimeseriesWriter : public RowSink {
 public:
  TimeseriesWriter(const std::string& path, const LineModel& m, int line, const Inputs& in,
                   const EndLoads* row_ends = nullptr);
  bool Row(const Data& d) override;
  void Commit();                                  // the complete file, under its name
  void CommitPartial(const std::string& path);    // an incomplete run, under another name

 private:
  AtomicFile file_;
  const LineModel& m_;
  int line_;
  const Inputs& in_;
  EndLoads ends_;                       // computed here, without row_ends
  const EndLoads* row_ends_ = nullptr;  // else these
  bool utilisation_ = false;  // the utilisation_max column
};

}  // namespace cablefilm
