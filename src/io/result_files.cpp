#include "io/result_files.h"

#include <filesystem>
#include <vector>

#include "core/error.h"
#include "io/csv_line.h"

namespace cablefilm {

void WriteEquilibriumCsv(const std::string& path, const LineModel& m, const State& state,
                         const Eigen::VectorXd& tension) {
  AtomicFile file(path);
  std::FILE* f = file.stream();
  std::fputs("j,s,x,y,z,tension\n", f);
  for (int j = 0; j <= m.line.links; ++j) {
    // "%d,%.10g,%.12g,%.12g,%.12g,%.10g\n" (written when `line` goes)
    CsvLine line(f);
    line.Int(j).Comma().G(m.line.arc_length[j], 10).Comma();
    for (int c = 0; c < kDim; ++c) line.G(state.x(c, j), 12).Comma();
    if (j < m.line.links) line.G(tension[j], 10);
    line.Char('\n');
  }
  file.Commit();
}

const char kTimeseriesHeader[] =
    "t,x_end,y_end,z_end,tension_start,tension_end,tension_max,link_max,"
    "fx_start,fy_start,fz_start,fx_end,fy_end,fz_end,angle_start,angle_end\n";

const char kUtilisationColumn[] = ",utilisation_max";

namespace {

// A row whose end loads are known.
void WriteRow(std::FILE* f, const LineModel& m, const LineData& d, const EndLoads& ends, bool utilisation) {
  const State& s = d.state;
  const Eigen::VectorXd& tension = d.tension();
  Eigen::Index link_max = 0;
  const double t_max = tension.maxCoeff(&link_max);
  const int end = m.line.links;
  const Vec& f0 = ends.at(0);
  const Vec& f1 = ends.at(1);
  // "%.10g,%.12g,%.12g,%.12g,%.10g,%.10g,%.10g,%d,%.10g x 6,%.8g,%.8g[,%.10g]"
  CsvLine line(f);
  line.G(s.t, 10);
  for (int c = 0; c < kDim; ++c) line.Comma().G(s.x(c, end), 12);
  line.Comma().G(tension[0], 10).Comma().G(tension[end - 1], 10).Comma().G(t_max, 10);
  line.Comma().Int(static_cast<int>(link_max));
  for (int c = 0; c < kDim; ++c) line.Comma().G(f0[c], 10);
  for (int c = 0; c < kDim; ++c) line.Comma().G(f1[c], 10);
  line.Comma().G(ElevationDegrees(f0), 8).Comma().G(ElevationDegrees(f1), 8);
  if (utilisation) line.Comma().G(MaxUtilisation(tension, m.line.breaking_load), 10);
  line.Char('\n');
}

}  // namespace

void WriteTimeseriesRow(std::FILE* f, const LineModel& m, const LineData& d, const Inputs& in,
                        EndLoads& ends, bool utilisation) {
  ends.Compute(m, d, in);
  WriteRow(f, m, d, ends, utilisation);
}

TimeseriesWriter::TimeseriesWriter(const std::string& path, const LineModel& m, int line,
                                   const Inputs& in, const EndLoads* row_ends)
    : file_(path), m_(m), line_(line), in_(in), ends_(m), row_ends_(row_ends),
      utilisation_(m.line.has_breaking_load()) {
  std::string header = kTimeseriesHeader;
  if (utilisation_) header.insert(header.size() - 1, kUtilisationColumn);
  std::fputs(header.c_str(), file_.stream());
}

bool TimeseriesWriter::Row(const Data& data) {
  const LineData& d = data.lines[line_];
  if (row_ends_)
    WriteRow(file_.stream(), m_, d, *row_ends_, utilisation_);
  else
    WriteTimeseriesRow(file_.stream(), m_, d, in_, ends_, utilisation_);
  return true;
}

void TimeseriesWriter::Commit() { file_.Commit(); }
void TimeseriesWriter::CommitPartial(const std::string& path) { file_.CommitAs(path); }

}  // namespace cablefilm
