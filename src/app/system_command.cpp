#include "app/system_command.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/material_summary.h"
#include "app/progress.h"
#include "app/run_support.h"
#include "core/error.h"
#include "io/bodies_file.h"
#include "io/results_nc.h"
#include "io/points_file.h"
#include "io/result_files.h"
#include "io/run_report_file.h"
#include "run/system_run.h"
#include "io/atomic_file.h"
#include "scene/build_model.h"
#include "scene/film_settings.h"
#include "scene/scene_loader.h"
#include "scene/text_escape.h"
#include "view/max_tension_figure.h"
#include "view/system_film.h"

namespace cablefilm {
namespace {

// The system's statics as `run` finds them, a progress line shown while the relaxation's
// motion goes on (it can take seconds: core/relaxation.h).
SystemRun PrepareWithProgress(const SceneDef& scene, const Model& sys) {
  StaticsProgress progress;
  return PrepareSystemRun(scene, sys, &g_signal, progress.relaxing(), progress.solving());
}

const char* KindName(PointKind kind) {
  switch (kind) {
    case PointKind::kFixed:
      return "fixed";
    case PointKind::kMoved:
      return "moved";
    case PointKind::kFree:
      return "free";
    case PointKind::kBody:
      return "on a free body";
  }
  return "";
}

void PrintSystem(const SceneDef& scene, const Model& sys) {
  std::printf("scene %s: %s\n", EscapeText(scene.path).c_str(), QuoteText(scene.title).c_str());
  std::printf("  a system of %zu line(s) and %zu point(s)\n", sys.lines.size(),
              sys.points.size());
  for (size_t i = 0; i < sys.lines.size(); ++i) {
    const LineModel& m = sys.lines[i];
    std::printf("  line %s: %d links, unstretched length %.6g m, mass %.6g kg, from point %s "
                "to point %s\n",
                QuoteText(sys.line_names[i]).c_str(), m.line.links, m.line.total_length(),
                m.line.link_mass.sum(), QuoteText(sys.points[sys.line_points[i][0]].name).c_str(),
                QuoteText(sys.points[sys.line_points[i][1]].name).c_str());
  }
  PrintTangentialMaterials(scene);
  for (const Point& p : sys.points)
    std::printf("  point %s: %s, %zu line end(s)%s\n", QuoteText(p.name).c_str(),
                KindName(p.kind), p.ends.size(),
                p.shared >= 0 ? ", where lines meet (solved with them)" : "");
  for (const BodySpec& b : sys.bodies) {
    const bool turns = b.kind == BodyKind::kDriven && b.turn.moves();
    const char* kind = b.kind == BodyKind::kFree     ? "free"
                       : turns                       ? "driven, turning"
                       : b.kind == BodyKind::kDriven ? "driven"
                                                     : "held";
    std::printf("  body %s: %s, reference point at (%.6g, %.6g, %.6g) m\n",
                QuoteText(b.name).c_str(), kind, b.motion.rest()[0], b.motion.rest()[1],
                b.motion.rest()[2]);
  }
  std::vector<std::string> notes, warnings;
  DescribeTables(scene, &notes, &warnings);
  for (const std::string& n : notes) std::printf("  %s\n", n.c_str());
  for (const std::string& w : scene.warnings) std::printf("  warning: %s\n", w.c_str());
  for (const std::string& w : warnings) std::printf("  warning: %s\n", w.c_str());
}

void PrintEquilibrium(const Model& sys, const EquilibriumReport& eq, double ms) {
  std::printf("equilibrium: %d Newton iteration(s) on the shared points and free bodies, "
              "out-of-balance %.3g N (of %.4g N), %.2f ms\n",
              eq.iterations, eq.residual, eq.force_scale, ms);
  if (eq.chains > 0)
    std::printf("  first guess: %d chain(s) of lines through their joints solved as one line\n",
                eq.chains);
  if (eq.relaxed > 0)
    std::printf("  not reached from the scene's positions: found from where %.3g s of the "
                "system's own motion, damped by its fluid, brought it\n",
                eq.relaxed);
  for (int b : sys.free_bodies) {
    const Vec6& q = eq.body_poses[b];
    std::printf("  body %s at (%.6g, %.6g, %.6g) m, turned (%.6g, %.6g, %.6g) deg about x, y, "
                "z\n",
                QuoteText(sys.bodies[b].name).c_str(), q[0], q[1], q[2], q[3] * 180 / M_PI,
                q[4] * 180 / M_PI, q[5] * 180 / M_PI);
  }
}

// The system's rows on a progress line, stopped by a signal.
class SystemProgress : public SystemRowSink {
 public:
  explicit SystemProgress(double end, const std::string& what = "simulating (system)")
      : line_(what, end, "s") {}
  bool Row(const Data& sd) override {
    line_.Update(sd.t);
    return g_signal == 0;
  }
  void Finish() { line_.Finish(); }

 private:
  ProgressLine line_;
};

// The snap check of a system's run (RefineStepControl): the run again from its initial state,
// in memory; sets its summary's refinement, refined_peak, refined_peak_change.
void CheckPeakUnderRefinement(const SceneDef& scene, SystemRun& run) {
  RunSummary& s = run.summary;
  SceneDef refined = scene;
  const std::string how = RefineStepControl(refined.simulation, s.tolerance, s.stats.snap_windows);
  RunSummary rs;
  try {  // the run's own files are written: a failure here is reported, not thrown
    SystemRun again = RestartSystemRun(refined, run);
    SystemProgress progress(again.grid.end(), "checking the peak under refinement (" + how + ")");
    ExecuteSystemRun(again, std::vector<std::vector<RowSink*>>(again.sys.lines.size()),
                     {&progress});
    progress.Finish();
    rs = again.summary;
  } catch (const Error& e) {
    rs.completed = false;
    rs.failure = e.what();
  }
  ReportRefinement(how, rs, &s);
}

// One line's files in its folder.
struct LineFiles {
  std::string dir;
  std::unique_ptr<TimeseriesWriter> series;
  std::unique_ptr<LineResultsNc> results;
};

}  // namespace

int ConvertCommand(const std::string& path, const std::string& out_path) {
  std::vector<std::string> warnings;
  const std::string text = MoorDynSceneText(path, &warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  if (out_path.empty() || out_path == "-") {
    std::fputs(text.c_str(), stdout);
    return 0;
  }
  AtomicFile file(out_path);
  std::fputs(text.c_str(), file.stream());
  file.Commit();
  std::fprintf(stderr, "wrote %s\n", EscapeText(out_path).c_str());
  return 0;
}

int CheckSystem(const SceneDef& scene) {
  const Model sys = BuildSystem(scene);
  PrintSystem(scene, sys);
  InstallSignalHandlers();
  const SystemRun run = PrepareWithProgress(scene, sys);
  PrintEquilibrium(run.sys, run.equilibrium, run.equilibrium_ms);
  std::printf("ok\n");
  return 0;
}

int RunSystem(const SceneDef& scene, const RunOptions& options, RunReport* report) {
  namespace fs = std::filesystem;
  // The film's settings checked before anything runs, as a line's are.
  const bool film = options.film >= 0 ? options.film == 1 : scene.output.film;
  const FilmSettings look = film ? ResolveFilm(scene, options, kCommandLineNames) : FilmSettings{};
  const Model built = BuildSystem(scene);
  PrintSystem(scene, built);
  OutDirLock lock;
  const std::string out_dir = PrepareOutDir(scene, options, lock);
  InstallSignalHandlers();
  SystemRun run = PrepareWithProgress(scene, built);
  PrintEquilibrium(run.sys, run.equilibrium, run.equilibrium_ms);
  const Model& sys = run.sys;
  const int nl = static_cast<int>(sys.lines.size());
  std::vector<LineFiles> files(nl);
  const long rows = run.grid.outputs + 1;  // of a complete run
  std::vector<std::vector<RowSink*>> line_sinks(nl);
  for (int i = 0; i < nl; ++i) {
    const LineModel& m = sys.lines[i];
    const LineData& d = run.initial.lines[i];
    LineFiles& f = files[i];
    f.dir = out_dir + "/lines/" + sys.line_names[i];
    std::error_code ec;
    fs::create_directories(f.dir, ec);
    if (ec) throw Error("cannot create the folder " + EscapeText(f.dir) + ": " + ec.message());
    WriteEquilibriumCsv(f.dir + "/equilibrium.csv", m, d.state, d.tension());
    f.series = std::make_unique<TimeseriesWriter>(f.dir + "/timeseries.csv", m, run.inputs);
    f.results = OpenLineResultsNc(f.dir + "/results.nc", MakeNetcdfInfo(scene, "elastic", rows),
                                  m, d.state, d.tension());
    line_sinks[i] = {f.series.get(), f.results.get()};
  }
  PointsWriter points(out_dir + "/points.csv", sys, run.inputs);
  std::unique_ptr<BodiesWriter> bodies;
  if (!sys.bodies.empty())
    bodies = std::make_unique<BodiesWriter>(out_dir + "/body.csv", sys, run.inputs);
  const std::unique_ptr<SystemResultsNc> results =
      OpenSystemResultsNc(out_dir + "/results.nc", MakeNetcdfInfo(scene, "elastic", rows), sys,
                          run.inputs);
  SystemProgress progress(run.grid.end());
  std::vector<SystemRowSink*> sinks = {&points, results.get(), &progress};
  if (bodies) sinks.push_back(bodies.get());
  ExecuteSystemRun(run, line_sinks, sinks);
  progress.Finish();
  const RunSummary& s = run.summary;
  if (report) report->summary = s;
  if (!s.completed) {
    for (LineFiles& f : files) {
      f.series->CommitPartial(f.dir + "/timeseries.partial.csv");
      f.results->CommitPartial(f.dir + "/results.partial.nc");
    }
    points.CommitPartial(out_dir + "/points.partial.csv");
    results->CommitPartial(out_dir + "/results.partial.nc");
    if (bodies) bodies->CommitPartial(out_dir + "/body.partial.csv");
    const std::string where = "the rows up to then are in " + EscapeText(out_dir) +
                              "/points.partial.csv and lines/*/timeseries.partial.csv";
    // Those rows drawn (a failure to draw them is reported: the run's own message comes next).
    bool drawn = false;
    try {
      const PictureReport figure =
          WriteSystemMaxTensionFigure(scene, run, out_dir, false);
      drawn = !std::isnan(figure.peak);
      if (report) report->figure = figure;
    } catch (const Error& e) {
      std::fprintf(stderr, "%s\n", e.what());
    }
    if (!s.failure.empty())
      throw Error(s.failure + "; " + where + (drawn ? " (drawn in max_tension.partial.png)" : ""));
    std::fprintf(stderr, "interrupted at t = %.4g s; %s\n", s.duration, where.c_str());
    return InterruptedExitStatus();
  }
  for (LineFiles& f : files) {
    f.series->Commit();
    f.results->Commit();
  }
  points.Commit();
  results->Commit();
  if (bodies) bodies->Commit();
  std::printf("simulated %.6g s in %.3g s of computer time: %s\n", s.duration, s.wall,
              DescribeSteps(s.stats).c_str());
  if (run.peak_line >= 0)
    std::printf("peak tension %.6g N at t = %.4g s in line %s, link %d (over the %ld rows, one "
                "every %.4g s)\n",
                s.peak, s.peak_t, QuoteText(sys.line_names[run.peak_line]).c_str(), s.peak_link,
                s.rows, run.grid.interval);
  if (s.utilisation_link >= 0)
    std::printf("peak utilisation %.4g %% (tension / minimum_breaking_load: %.6g N of %.6g N) at "
                "t = %.4g s in line %s, link %d, material %s\n",
                100 * s.utilisation, s.utilisation_tension, s.utilisation_mbl, s.utilisation_t,
                QuoteText(s.utilisation_line).c_str(), s.utilisation_link,
                QuoteText(s.utilisation_material).c_str());
  for (const std::string& w : s.warnings) std::printf("warning: %s\n", w.c_str());
  bool unresolved = false;  // snaps the steps did not resolve, in any line
  for (const RunSummary& l : run.lines) unresolved |= l.stats.record.unresolved_snaps > 0;
  if (unresolved) CheckPeakUnderRefinement(scene, run);
  if (report) report->summary = s;
  for (int i = 0; i < nl; ++i) WriteRunReport(files[i].dir + "/run_report.toml", run.lines[i]);
  WriteRunReport(out_dir + "/run_report.toml", s);
  std::printf("wrote %s/points.csv,%s results.nc, run_report.toml and lines/<name>/ for %d "
              "line(s)\n",
              EscapeText(out_dir).c_str(), bodies ? " body.csv," : "", nl);
  // Figure 1 from every row, film or not (a film cut short leaves it whole: it has every row).
  const PictureReport figure =
      WriteSystemMaxTensionFigure(scene, run, out_dir, true);
  if (report) report->figure = figure;
  if (!film) return 0;
  PictureReport shown;
  const bool finished = RenderSystemFilm(
      scene, run, MakeFilmRequest(look, out_dir, options.shader_dir), g_signal, &shown);
  if (report) report->film = shown;
  return finished ? 0 : InterruptedExitStatus();
}

}  // namespace cablefilm
