#pragma once
// The files a run writes into its output folder as its rows come, laid out as its model has
// lines: a model of one line its equilibrium.csv, timeseries.csv and results.nc in the folder;
// of several, each line's in lines/<name>/ and the points' points.csv and the model's
// results.nc (points, lines' ends, bodies) in the folder; body.csv when it has bodies; a
// complete run's tension_spectrum.csv beside each line's timeseries.csv. A
// `suffix` goes before each name's extension (compare's second run: "_inextensible"). Every
// file is written whole or not at all: Commit gives them their names, CommitPartial their
// .partial names (a run cut short).
#include <memory>
#include <string>
#include <vector>

#include "io/bodies_file.h"
#include "io/points_file.h"
#include "io/result_files.h"
#include "io/results_nc.h"
#include "run/run.h"

namespace cablefilm {

class RunFiles : public RowSink {
 public:
  // Creates the folders, writes each line's equilibrium.csv (of run.initial) and opens the
  // rest. `info`: results.nc's attributes. Throws Error. Keeps references to `run`.
  RunFiles(const std::string& out_dir, const std::string& suffix, const Run& run,
           const NetcdfResultsInfo& info);
  bool Row(const Data& d) override;
  // The complete files, with the end tensions' statistics (results.nc) and spectra
  // (tension_spectrum.csv, when the run had rows enough) of the run's record.
  void Commit();
  void CommitPartial();
  // Where a cut-short run's rows are, for its message ("DIR/timeseries.partial.csv and ...").
  std::string PartialWhere() const;
  // The folder of line i's files (the output folder itself for a model of one line).
  const std::string& line_dir(int i) const { return lines_[i].dir; }
  // The file written under `name` (e.g. "run_report.toml") in line i's folder, suffixed.
  std::string LineFile(int i, const std::string& name) const;
  // The same in the output folder.
  std::string File(const std::string& name) const;
  bool several() const { return lines_.size() > 1; }

 private:
  struct LineFiles {
    std::string dir;
    std::unique_ptr<TimeseriesWriter> series;
    std::unique_ptr<LineResultsNc> results;
  };
  const Run& run_;
  std::string out_dir_, suffix_;
  std::vector<LineFiles> lines_;
  std::unique_ptr<PointsWriter> points_;
  std::unique_ptr<BodiesWriter> bodies_;
  std::unique_ptr<ModelResultsNc> model_results_;
  std::vector<RowSink*> sinks_;
};

// Writes the run's reports: each line's run_report.toml in its folder, and the run's in the
// output folder (a model of one line: the one, its line's).
void WriteRunReports(const RunFiles& files, const Run& run);

// "name" with `suffix` before its extension: "timeseries.csv" + "_inextensible".
std::string Suffixed(const std::string& name, const std::string& suffix);

}  // namespace cablefilm
