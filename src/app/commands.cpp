#include "app/commands.h"

#include <memory>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "app/open_files.h"
#include "app/progress.h"
#include "app/run_support.h"
#include "app/scene_summary.h"
#include "io/out_dir_lock.h"
#include "app/run_files.h"
#include "run/film_checkpoint.h"
#include "run/peak_windows.h"
#include "run/run.h"
#include "scene/build_model.h"
#include "scene/film_settings.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"
#include "scene/text_escape.h"
#include "view/max_tension_figure.h"

namespace cablefilm {
namespace {

// The progress line of a run, and its stop at a signal (seen between rows; within a step, the
// inputs' stop flag).
class ProgressSink : public RowSink {
 public:
  ProgressSink(const std::string& label, double end) : line_(label, end, "s") {}
  bool Row(const Data& d) override {
    line_.Update(d.t);
    return g_signal == 0;
  }
  void Finish() { line_.Finish(); }

 private:
  ProgressLine line_;
};

// The snap check of a run (RefineStepControl): the run again, in memory, its step control
// stricter, from its initial state, or from the checkpoints of `windows` over them alone; sets
// its summary's refinement, refined_peak, refined_peak_change.
void CheckPeakUnderRefinement(const SceneDef& scene, Run& run, const PeakWindows* windows) {
  RunSummary& s = run.summary;
  SceneDef refined = scene;
  std::string how = RefineStepControl(refined.simulation, s.tolerance, s.stats.snap_windows);
  RunSummary rs;
  try {  // the run's own files are written: a failure here is reported, not thrown
    if (!windows) {
      Run again = RestartRun(refined, run);
      ProgressSink progress("checking the peak under refinement (" + how + ")", again.grid.end());
      ExecuteRun(again, {&progress});
      progress.Finish();
      rs = again.summary;
    } else {
      const std::vector<PeakWindow> list = windows->Windows();
      std::string spans;
      rs.completed = true;
      rs.peak = 0;
      for (std::size_t k = 0; k < list.size() && rs.completed; ++k) {
        const PeakWindow& w = list[k];
        Run again = WindowRun(refined, run, w.states, w.anchors, w.first_row, w.last_row);
        char label[160];
        std::snprintf(label, sizeof label,
                      "checking the peak under refinement (%s), window %zu of %zu: %.6g to %.6g s",
                      how.c_str(), k + 1, list.size(), w.first_row * run.grid.interval,
                      again.grid.end());
        ProgressSink progress(label, again.grid.end());
        ExecuteRun(again, {&progress});
        progress.Finish();
        const RunSummary& ws = again.summary;
        rs.completed = ws.completed;
        rs.failure = ws.failure;
        rs.stats.steps += ws.stats.steps;
        if (ws.peak > rs.peak) {
          rs.peak = ws.peak;
          rs.peak_t = ws.peak_t;
        }
        char span[64];
        std::snprintf(span, sizeof span, "%s%.6g-%.6g s", spans.empty() ? "" : ", ",
                      w.first_row * run.grid.interval, again.grid.end());
        spans += span;
      }
      how += "; over the " + std::to_string(list.size()) + " windows of the highest peaks, " +
             spans + ", from the run's states";
    }
  } catch (const Error& e) {
    rs.completed = false;
    rs.failure = e.what();
  }
  ReportRefinement(how, rs, &s);
}

// What a finished run prints: its steps, peak, utilisation and end loads.
void PrintRunEnd(const Run& run) {
  const RunSummary& s = run.summary;
  const Model& model = run.model;
  const bool alone = model.lines.size() == 1;
  long stations = 0;
  for (const LineModel& m : model.lines) stations += m.stations();
  std::printf("simulated %.6g s in %.3g s of computer time (%.3g s of CPU): %s", s.duration,
              s.wall, s.cpu, DescribeSteps(s.stats).c_str());
  if (alone)
    std::printf(", %.3g station-steps/s", static_cast<double>(s.stats.steps) * stations / s.wall);
  std::printf("\n");
  // Sampled as the CSV is: at the output rows (every `interval`), not at every step.
  if (alone)
    std::printf("peak tension %.6g N at t = %.4g s in link %d (the largest tension_max of the "
                "%ld rows, one every %.4g s)\n",
                s.peak, s.peak_t, s.peak_link, s.rows, run.grid.interval);
  else if (run.peak_line >= 0)
    std::printf("peak tension %.6g N at t = %.4g s in line %s, link %d (over the %ld rows, one "
                "every %.4g s)\n",
                s.peak, s.peak_t, QuoteText(model.line_names[run.peak_line]).c_str(),
                s.peak_link, s.rows, run.grid.interval);
  if (s.utilisation_link >= 0)
    std::printf("peak utilisation %.4g %% (tension / minimum_breaking_load: %.6g N of %.6g N) at "
                "t = %.4g s in %slink %d, material %s\n",
                100 * s.utilisation, s.utilisation_tension, s.utilisation_mbl, s.utilisation_t,
                alone ? "" : ("line " + QuoteText(s.utilisation_line) + ", ").c_str(),
                s.utilisation_link, QuoteText(s.utilisation_material).c_str());
  for (std::size_t i = 0; i < run.lines.size(); ++i) {
    const RunSummary& l = run.lines[i].summary;
    std::printf("%slargest end loads %.6g N at the start (t = %.4g s), %.6g N at the end (t = "
                "%.4g s) (fx..fz_start, fx..fz_end of the time series)\n",
                alone ? "" : ("line " + QuoteText(model.line_names[i]) + ": ").c_str(),
                l.start_load_max, l.start_load_t, l.end_load_max, l.end_load_t);
    const char* names[2] = {"start", "end"};
    for (int e = 0; e < 2; ++e) {
      const TensionStatistics& t = l.ends[e];
      if (!t.known()) continue;
      std::printf("%stension_%s over the rows: mean %.6g N, std %.4g N, max %.6g N, most probable "
                  "maximum %.6g N (%ld up-crossings of the mean)\n",
                  alone ? "" : ("line " + QuoteText(model.line_names[i]) + ": ").c_str(), names[e],
                  t.mean, t.sigma, t.max, t.mpm, t.upcrossings);
    }
  }
}

// One model of a scene simulated into result files (io/run_files.h: the equilibrium, the time
// series, every station and link, the points and bodies of several lines, the reports), with
// `suffix` before each name's extension; the run keeps the largest tension of every row (for
// the pictures) and what the film needs. A run cut short (summary.completed false) has
// committed its rows under the .partial names; summary.failure then holds a blow-up's message
// (empty: stopped by a signal). `film_window` (null: no film): the film's window, whose start
// the run keeps in *checkpoint (null for the whole run).
Run SimulateToFiles(const SceneDef& scene, const Model& model, const std::string& out_dir,
                    const std::string& suffix, const std::string& label,
                    const FilmWindow* film_window = nullptr,
                    std::unique_ptr<FilmCheckpoint>* checkpoint = nullptr) {
  const TimeGrid grid = ChooseTimeGrid(model, scene.simulation, scene.output.interval);
  PrintScene(scene, model, grid);
  StaticsProgress statics;
  Run run = PrepareRun(scene, model, label, &g_signal, {statics.relaxing(), statics.solving()});
  PrintInitialState(scene, run, suffix);
  RunFiles files(out_dir, suffix, run, MakeNetcdfInfo(scene, label.c_str(), run.grid.outputs + 1));
  ProgressSink progress(std::string("simulating (") + run.label + ")", run.grid.end());
  const std::unique_ptr<PeakWindows> windows = SnapCheckWindows(run);
  std::vector<RowSink*> sinks{&files, &progress};
  if (windows) sinks.push_back(windows.get());
  if (film_window && checkpoint) {
    *checkpoint = FilmCheckpoint::For(*film_window, run.grid);
    if (*checkpoint) sinks.push_back(checkpoint->get());
  }
  ExecuteRun(run, sinks);
  progress.Finish();
  RunSummary& s = run.summary;
  if (!s.completed) {
    files.CommitPartial();
    const std::string where = files.PartialWhere();
    if (!s.failure.empty())
      s.failure += "; the rows up to then are in " + where;
    else
      std::fprintf(stderr, "interrupted at t = %.4g s; rows so far in %s\n", s.duration,
                   where.c_str());
    return run;
  }
  files.Commit();
  PrintRunEnd(run);
  if (!files.several()) {
    std::printf("wrote %s\n", EscapeText(files.File("timeseries.csv")).c_str());
    std::printf("wrote %s\n", EscapeText(files.File("results.nc")).c_str());
    if (!run.lines.front().spectrum.empty())
      std::printf("wrote %s\n", EscapeText(files.File("tension_spectrum.csv")).c_str());
  }
  for (const std::string& w : s.warnings) std::printf("warning: %s\n", w.c_str());
  if (s.stats.record.unresolved_snaps > 0) {
    CheckPeakUnderRefinement(scene, run, windows.get());
  } else if (s.stats.snap_windows > 0) {
    CheckPeakUnderRefinement(scene, run, windows.get());
    const std::string damped = RingingWarning(s);
    if (!damped.empty()) {
      s.warnings.push_back(damped);
      std::printf("warning: %s\n", damped.c_str());
    }
  }
  WriteRunReports(files, run);
  if (!files.several())
    std::printf("wrote %s\n", EscapeText(files.File("run_report.toml")).c_str());
  else
    std::printf("wrote %s, %s%s, %s and lines/<name>/ for %zu lines\n",
                EscapeText(files.File("points.csv")).c_str(),
                model.bodies.empty() ? "" : (EscapeText(files.File("body.csv")) + ", ").c_str(),
                EscapeText(files.File("results.nc")).c_str(),
                EscapeText(files.File("run_report.toml")).c_str(), model.lines.size());
  return run;
}

// The runs so far, the last cut short: max_tension.partial.png beside timeseries.partial.csv
// (a failure to draw it is reported, not thrown: the run's own message comes next). Then a
// blow-up's message is thrown; a signal gives its exit status.
int EndCutShort(const SceneDef& scene, const std::vector<const Run*>& runs,
                const std::string& failure, const std::string& out_dir, RunReport* report) {
  bool drawn = false;
  try {
    const PictureReport figure = WriteMaxTensionFigure(scene, runs, out_dir, false);
    drawn = !std::isnan(figure.peak);
    if (report) report->figure = figure;
  } catch (const Error& e) {
    std::fprintf(stderr, "%s\n", e.what());
  }
  if (!failure.empty())
    throw Error(failure + (drawn ? " (drawn in max_tension.partial.png)" : ""));
  return InterruptedExitStatus();
}

// The pictures of finished runs: Figure 1 from every row, film or not (a film cut short leaves
// it whole: it has every row); the film when asked, of its window from the runs' checkpoints.
int DrawPictures(const SceneDef& scene, const std::vector<const Run*>& runs, bool film,
                 const FilmSettings& look, const RunOptions& options, const std::string& out_dir,
                 RunReport* report, std::vector<const FilmCheckpoint*> starts = {}) {
  const PictureReport figure = WriteMaxTensionFigure(scene, runs, out_dir, true);
  if (report) report->figure = figure;
  if (!film) return 0;
  PictureReport shown;
  FilmRequest request = MakeFilmRequest(look, out_dir, options.shader_dir);
  request.starts = std::move(starts);
  const bool finished = RenderFilm(scene, runs, request, g_signal, &shown);
  if (report) report->film = shown;
  return finished ? 0 : InterruptedExitStatus();
}

// The scene with every line of `model` (its elastic model) that can be inextensible made so:
// a line of a coupled island cannot (the coupled step is the elastic lines'), and is said.
// Throws Error when no line can.
SceneDef InextensibleScene(const SceneDef& scene, const Model& model) {
  SceneDef rigid = scene;
  int made = 0;
  for (std::size_t i = 0; i < rigid.lines.size() && i < model.lines.size(); ++i) {
    if (model.islands[model.line_island[i]].coupled()) {
      std::printf("compare: line %s is joined to other lines or to a free body: the inextensible "
                  "model cannot run there (the coupled step is the elastic lines'); it stays "
                  "elastic in the inextensible run\n",
                  QuoteText(model.line_names[i]).c_str());
      continue;
    }
    rigid.lines[i].model = CableModelKind::kInextensible;
    ++made;
  }
  if (made == 0)
    throw Error(scene.path + ": compare: every line is joined to others or to a free body: the "
                "inextensible model can run none of them (the coupled step is the elastic lines')");
  return rigid;
}

}  // namespace

int RunCommand(const std::string& scene_path, const RunOptions& options, RunReport* report) {
  const SceneDef scene = LoadScene(scene_path);
  const bool film = options.film >= 0 ? options.film == 1 : scene.output.film;
  const FilmSettings look = film ? ResolveFilm(scene, options, kCommandLineNames) : FilmSettings{};
  const Model model = BuildModel(scene);
  CheckModelLimits(scene, model);
  CheckOpenFiles(scene, model);
  OutDirLock lock;
  const std::string out_dir = PrepareOutDir(scene, options, lock);
  InstallSignalHandlers();
  std::unique_ptr<FilmCheckpoint> start;
  const Run run = SimulateToFiles(scene, model, out_dir, "", ModelLawName(model),
                                  film ? &look.look.window : nullptr, &start);
  if (report) report->summary = run.summary;
  const std::vector<const Run*> runs{&run};
  if (!run.summary.completed)
    return EndCutShort(scene, runs, run.summary.failure, out_dir, report);
  return DrawPictures(scene, runs, film, look, options, out_dir, report, {start.get()});
}

int CompareCommand(const std::string& scene_path, const RunOptions& options) {
  SceneDef scene = LoadScene(scene_path);
  const bool film = options.film >= 0 ? options.film == 1 : scene.output.film;
  const FilmSettings look = film ? ResolveFilm(scene, options, kCommandLineNames) : FilmSettings{};
  for (LineDef& line : scene.lines) line.model = CableModelKind::kElastic;
  const Model elastic_model = BuildModel(scene);
  CheckModelLimits(scene, elastic_model);
  const SceneDef rigid_scene = InextensibleScene(scene, elastic_model);
  const Model rigid_model = BuildModel(rigid_scene);
  CheckModelLimits(rigid_scene, rigid_model);
  CheckOpenFiles(rigid_scene, rigid_model, 2);  // the elastic run's row maxima kept
  OutDirLock lock;
  const std::string out_dir = PrepareOutDir(scene, options, lock);
  InstallSignalHandlers();
  std::unique_ptr<FilmCheckpoint> elastic_start, rigid_start;
  const Run elastic = SimulateToFiles(scene, elastic_model, out_dir, "", "elastic",
                                      film ? &look.look.window : nullptr, &elastic_start);
  std::vector<const Run*> runs{&elastic};
  if (!elastic.summary.completed)
    return EndCutShort(scene, runs, elastic.summary.failure, out_dir, nullptr);
  // The film's window is the first run's (about its peak): the second keeps the same rows' start.
  FilmWindow rows = look.look.window;
  if (!rows.whole()) {
    const RowSpan span = WindowRows(rows, elastic.grid, elastic.summary.peak_t);
    rows = FilmWindow{0, span.first * elastic.grid.interval, span.last * elastic.grid.interval};
  }
  const Run rigid = SimulateToFiles(rigid_scene, rigid_model, out_dir, "_inextensible",
                                    "inextensible", film ? &rows : nullptr, &rigid_start);
  runs.push_back(&rigid);
  if (!rigid.summary.completed)
    return EndCutShort(scene, runs, rigid.summary.failure, out_dir, nullptr);
  for (std::size_t i = 0; i < elastic.lines.size(); ++i) {
    const RunSummary &e = elastic.lines[i].summary, &r = rigid.lines[i].summary;
    const std::string of_line = elastic.lines.size() > 1
                                    ? " of line " + QuoteText(elastic.model.line_names[i])
                                    : "";
    if (rigid_scene.lines[i].model != CableModelKind::kInextensible) {
      std::printf("peak tension%s: elastic %.6g N (t = %.4g s); elastic in both runs (joined to "
                  "other lines or to a free body)\n",
                  of_line.c_str(), e.peak, e.peak_t);
      continue;
    }
    std::printf("peak tension%s: elastic %.6g N (t = %.4g s), inextensible %.6g N (t = %.4g s), "
                "ratio inextensible/elastic %.4g\n",
                of_line.c_str(), e.peak, e.peak_t, r.peak, r.peak_t, r.peak / e.peak);
  }
  return DrawPictures(scene, runs, film, look, options, out_dir, nullptr,
                      {elastic_start.get(), rigid_start.get()});
}

int CheckCommand(const std::string& scene_path) {
  const SceneDef scene = LoadScene(scene_path);
  if (scene.output.film) ResolveFilm(scene, {}, kCommandLineNames);  // as `run` makes it
  const Model model = BuildModel(scene);
  CheckModelLimits(scene, model);
  CheckOpenFiles(scene, model);
  const TimeGrid grid = ChooseTimeGrid(model, scene.simulation, scene.output.interval);
  PrintScene(scene, model, grid);
  if (scene.initial == InitialStateKind::kEquilibrium) {
    // The initial state is part of the scene: a cable with no steady state is caught here,
    // not after `run` has set up its outputs.
    InstallSignalHandlers();
    StaticsProgress statics;
    const Run run =
        PrepareRun(scene, model, ModelLawName(model), &g_signal, {statics.relaxing(), statics.solving()});
    if (model.lines.size() == 1 && !model.islands.front().coupled()) {
      const LineEquilibriumReport& eq = run.equilibrium.lines.front();
      std::printf("  static equilibrium found: %d Newton iterations%s, residual %.3g N\n",
                  eq.iterations, eq.fallback ? " (with the pseudo-transient fallback)" : "",
                  eq.residual);
    } else {
      PrintInitialState(scene, run, "");
    }
  }
  std::printf("ok\n");
  return 0;
}

namespace {

const char kOutputs[] =
    "The results go to the output folder: a scene of one line its equilibrium.csv,\n"
    "timeseries.csv, results.nc and run_report.toml; of several lines each line's in\n"
    "lines/<name>/ and points.csv, results.nc (body.csv with bodies) and run_report.toml; then\n"
    "max_tension.png and film.mp4 (with the film: duration x fps / speed must be 1 to 1e6\n"
    "frames).";

}  // namespace

Command DeclareRunCommand(CLI::App& program, std::string* scene) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* cmd = AddSceneCommand(program, "run", "simulate, write the results and the film", scene);
  AddRunOptions(cmd, options.get());
  cmd->footer(kOutputs);
  return {cmd, [scene, options] { return RunCommand(*scene, *options); }};
}

Command DeclareCompareCommand(CLI::App& program, std::string* scene) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* cmd = AddSceneCommand(program, "compare",
                                  "elastic and inextensible runs: the paper's Figure 1", scene);
  AddRunOptions(cmd, options.get());
  cmd->footer(std::string(kOutputs) +
              "\nAlso each line's equilibrium_inextensible.csv and timeseries_inextensible.csv.");
  return {cmd, [scene, options] { return CompareCommand(*scene, *options); }};
}

Command DeclareCheckCommand(CLI::App& program, std::string* scene) {
  CLI::App* cmd = AddSceneCommand(program, "check",
                                  "validate a scene, print stations, mass, time step", scene);
  cmd->footer("Refuses whatever run would, before anything is simulated.");
  return {cmd, [scene] { return CheckCommand(*scene); }};
}

}  // namespace cablefilm
