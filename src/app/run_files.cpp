#include "app/run_files.h"

#include <filesystem>

#include "core/error.h"
#include "io/output_ledger.h"
#include "io/run_report_file.h"
#include "io/tension_spectrum_file.h"
#include "scene/text_escape.h"

namespace cablefilm {

std::string Suffixed(const std::string& name, const std::string& suffix) {
  const std::size_t dot = name.find('.');
  return dot == std::string::npos ? name + suffix : name.substr(0, dot) + suffix + name.substr(dot);
}

RunFiles::RunFiles(const std::string& out_dir, const std::string& suffix, const Run& run,
                   const NetcdfResultsInfo& info)
    : run_(run), out_dir_(out_dir), suffix_(suffix) {
  const Model& model = run.model;
  const int nl = static_cast<int>(model.lines.size());
  lines_.resize(nl);
  for (int i = 0; i < nl; ++i) {
    const LineModel& m = model.lines[i];
    const LineData& d = run.initial.lines[i];
    LineFiles& f = lines_[i];
    f.dir = nl == 1 ? out_dir : out_dir + "/lines/" + model.line_names[i];
    CreateOutputFolder(f.dir);
    WriteEquilibriumCsv(LineFile(i, "equilibrium.csv"), m, d.state, d.tension());
    f.series = std::make_unique<TimeseriesWriter>(LineFile(i, "timeseries.csv"), m, i, run.inputs,
                                                  &run.lines[i].row_ends);
    f.results = OpenLineResultsNc(LineFile(i, "results.nc"), info, m, d.state, d.tension(), i);
    sinks_.push_back(f.series.get());
    sinks_.push_back(f.results.get());
  }
  if (nl > 1) {
    points_ = std::make_unique<PointsWriter>(File("points.csv"), model, run.inputs);
    model_results_ = OpenModelResultsNc(File("results.nc"), info, model, run.inputs);
    sinks_.push_back(points_.get());
    sinks_.push_back(model_results_.get());
  }
  if (!model.bodies.empty()) {
    bodies_ = std::make_unique<BodiesWriter>(File("body.csv"), model, run.inputs);
    sinks_.push_back(bodies_.get());
  }
}

std::string RunFiles::LineFile(int i, const std::string& name) const {
  return lines_[i].dir + "/" + Suffixed(name, suffix_);
}

std::string RunFiles::File(const std::string& name) const {
  return out_dir_ + "/" + Suffixed(name, suffix_);
}

bool RunFiles::Row(const Data& d) {
  for (RowSink* s : sinks_) s->Row(d);
  return true;
}

void RunFiles::Commit() {
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    LineFiles& f = lines_[i];
    const LineRecord& r = run_.lines[i];
    f.series->Commit();
    f.results->SetEndStatistics(r.summary.ends);
    f.results->Commit();
    if (!r.spectrum.empty())
      WriteTensionSpectrumCsv(LineFile(static_cast<int>(i), "tension_spectrum.csv"), r.spectrum);
  }
  if (points_) points_->Commit();
  if (model_results_) model_results_->Commit();
  if (bodies_) bodies_->Commit();
}

void RunFiles::CommitPartial() {
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    lines_[i].series->CommitPartial(LineFile(static_cast<int>(i), "timeseries.partial.csv"));
    lines_[i].results->CommitPartial(LineFile(static_cast<int>(i), "results.partial.nc"));
  }
  if (points_) points_->CommitPartial(File("points.partial.csv"));
  if (model_results_) model_results_->CommitPartial(File("results.partial.nc"));
  if (bodies_) bodies_->CommitPartial(File("body.partial.csv"));
}

std::string RunFiles::PartialWhere() const {
  if (lines_.size() == 1)
    return EscapeText(LineFile(0, "timeseries.partial.csv")) + " and " +
           EscapeText(LineFile(0, "results.partial.nc"));
  return EscapeText(File("points.partial.csv")) + " and " + EscapeText(out_dir_) + "/lines/*/" +
         Suffixed("timeseries.partial.csv", suffix_);
}

void WriteRunReports(const RunFiles& files, const Run& run) {
  if (files.several())
    for (std::size_t i = 0; i < run.lines.size(); ++i)
      WriteRunReport(files.LineFile(static_cast<int>(i), "run_report.toml"), run.lines[i].summary);
  WriteRunReport(files.File("run_report.toml"), run.summary);
}

}  // namespace cablefilm
