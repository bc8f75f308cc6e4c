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

namespace {

// The names a run writes in a folder (a line's, in lines/<name>/, has the first eight kinds).
const char* const kResultNames[] = {
    "equilibrium.csv", "equilibrium_inextensible.csv", "timeseries.csv",
    "timeseries.partial.csv", "timeseries_inextensible.csv",
    "timeseries_inextensible.partial.csv", "results.nc", "results.partial.nc",
    "results_inextensible.nc", "results_inextensible.partial.nc", "run_report.toml",
    "run_report_inextensible.toml", "film.mp4", "film.partial.mp4", "max_tension.png",
    "max_tension.partial.png", "points.csv", "points.partial.csv", "points_inextensible.csv",
    "points_inextensible.partial.csv", "body.csv", "body.partial.csv", "body_inextensible.csv",
    "body_inextensible.partial.csv"};

// Removes `dir`'s files of those names (plain files only) and its frames/frame_*.png.
void RemoveResultsIn(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::vector<fs::path> stale;
  for (const char* name : kResultNames) stale.push_back(dir / name);
  std::error_code ec;
  const fs::path frames = dir / "frames";
  if (fs::is_directory(fs::symlink_status(frames, ec)))
    for (const auto& entry : fs::directory_iterator(frames, ec)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("frame_", 0) == 0 && entry.path().extension() == ".png")
        stale.push_back(entry.path());
    }
  for (const fs::path& p : stale) {
    if (!fs::is_regular_file(fs::symlink_status(p, ec))) continue;  // ours are plain files
    fs::remove(p, ec);
    if (ec) throw Error("cannot remove the earlier result " + p.string() + ": " + ec.message());
  }
}

}  // namespace

void RemoveEarlierResults(const std::string& out_dir) {
  namespace fs = std::filesystem;
  RemoveResultsIn(out_dir);
  // A run of several lines has each in lines/<name>/ with a line's own files: those removed,
  // and a folder they leave empty (a user's own files stay, and their folders with them).
  std::error_code ec;
  const fs::path lines = fs::path(out_dir) / "lines";
  if (!fs::is_directory(fs::symlink_status(lines, ec))) return;
  std::vector<fs::path> folders;
  for (const auto& entry : fs::directory_iterator(lines, ec))
    if (fs::is_directory(fs::symlink_status(entry.path(), ec))) folders.push_back(entry.path());
  for (const fs::path& folder : folders) {
    RemoveResultsIn(folder);
    if (fs::is_empty(folder, ec)) fs::remove(folder, ec);
  }
  if (fs::is_empty(lines, ec)) fs::remove(lines, ec);
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
