#include "app/commands.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "app/material_summary.h"
#include "app/progress.h"
#include "app/run_support.h"
#include "app/system_command.h"
#include "core/version.h"
#include "io/results_nc.h"
#include "io/out_dir_lock.h"
#include "io/result_files.h"
#include "io/run_report_file.h"
#include "run/initial_state.h"
#include "run/run.h"
#include "scene/build_model.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"
#include "scene/text_escape.h"
#include "view/max_tension_figure.h"

namespace cablefilm {
namespace {

const char* ModelName(const LineModel& m) { return LawName(m.line.law); }

// A horizontal direction as a user gives it: "+x", or "<angle> deg from +x towards +z".
std::string HeadingText(const Vec& direction) {
  const double deg = std::atan2(direction.z(), direction.x()) * 180.0 / M_PI;
  if (deg == 0) return "+x";
  char text[64];
  std::snprintf(text, sizeof text, "%.4g deg from +x towards +z", deg);
  return text;
}

void PrintSummary(const SceneDef& scene, const LineModel& m, const TimeGrid& grid) {
  const double cable_mass = m.line.link_mass.sum();
  double weights = 0;
  for (const WeightDef& w : scene.weights) weights += w.mass;
  std::printf("scene %s: %s\n", EscapeText(scene.path).c_str(), QuoteText(scene.title).c_str());
  std::printf("  %s cable: %d stations, %d links in %zu section(s), unstretched length %.6g m\n",
              ModelName(m), m.stations(), m.line.links, scene.sections.size(), m.line.total_length());
  std::printf("  mass %.6g kg (cable %.6g kg, %zu weight(s) %.6g kg), net weight in fluid %.6g N\n",
              cable_mass + weights, cable_mass, scene.weights.size(), weights,
              m.line.net_weight.sum());
  PrintTangentialMaterials(scene);
  if (!m.env.current_profile.empty()) {
    const CurrentProfile& p = m.env.current_profile;
    const auto [lo, hi] = std::minmax_element(p.speed.begin(), p.speed.end());
    std::printf("  current profile: %zu point(s) from y = %.6g to %.6g m, %.4g to %.4g m/s along "
                "%s, linear between them, constant beyond\n",
                p.y.size(), p.y.front(), p.y.back(), m.env.current + *lo, m.env.current + *hi,
                HeadingText(m.env.current_direction).c_str());
  } else if (m.env.current != 0) {
    std::printf("  current: %.4g m/s along %s\n", m.env.current,
                HeadingText(m.env.current_direction).c_str());
  }
  if (m.env.seabed.present) {
    // What a station resting on it sinks: its net weight over its share of the bed's stiffness.
    double sink = 0, damping_lo = 1e300, damping_hi = 0;
    int deepest = 0;
    for (int j = m.first_free(); j <= m.last_free(); ++j) {
      const double share = m.line.seabed_stiffness[j] / m.env.seabed.stiffness;  // [m of line]
      damping_lo = std::min(damping_lo, m.line.seabed_damping[j] / share);
      damping_hi = std::max(damping_hi, m.line.seabed_damping[j] / share);
      if (m.line.net_weight[j] / m.line.seabed_stiffness[j] > sink) {
        sink = m.line.net_weight[j] / m.line.seabed_stiffness[j];
        deepest = j;
      }
    }
    std::printf("  seabed at y = %.6g m: stiffness %.4g N/m per m of line, damping %.4g",
                m.env.seabed.y, m.env.seabed.stiffness, damping_lo);
    if (damping_hi > damping_lo * (1 + 1e-9)) std::printf(" to %.4g", damping_hi);
    std::printf(" N s/m per m (%s), friction %.3g", m.env.seabed.damping < 0 ? "critical" : "given",
                m.env.seabed.friction);
    if (m.env.seabed.friction > 0 && m.env.seabed.friction_model == FrictionModel::kSmoothed)
      std::printf(" (smoothed over %.3g m/s)", m.env.seabed.friction_velocity);
    else if (m.env.seabed.friction > 0)
      std::printf(" (stick-slip, shear stiffness %.4g N/m per m)",
                  m.env.seabed.shear_stiffness());
    std::printf("; a line resting on it sinks at most %.3g mm (station %d)\n", 1e3 * sink,
                deepest);
  }
  if (m.has_waves() && m.env.wave.spec.height == 0) {
    std::printf("  still water with its surface at y = %.6g m (waves.height = 0): no buoyancy, "
                "drag or added mass above it\n",
                m.env.wave.spec.surface_y);
  } else if (m.has_waves()) {
    const Wave& w = m.env.wave;
    const double kh = w.k * w.spec.depth;
    std::printf("  waves (linear Airy, along %s): height %.4g m, period %.4g s, depth %.6g m, "
                "still water level y = %.6g m: length %.6g m, k h = %.4g (%s), steepness H/L = "
                "%.4g (breaks above %.4g), crest speed %.4g m/s, phase %.4g deg, ramp rate %.4g "
                "1/s\n",
                HeadingText(w.direction).c_str(), w.spec.height, w.spec.period, w.spec.depth, w.spec.surface_y, w.length(), kh,
                kh > M_PI ? "deep" : kh < M_PI / 10 ? "shallow" : "intermediate depth",
                w.steepness(), w.breaking_steepness(), w.omega / w.k, scene.waves.phase,
                w.spec.ramp_rate);
    for (const auto& [name, end] : {std::pair<const char*, const EndDef*>{"start", &scene.start},
                                    {"end", &scene.end}})
      if (end->follows_wave)
        std::printf("  ends.%s follows the wave: along x %.4g x [%.4g deg], heave %.4g x "
                    "[%.4g deg], along z %.4g x [%.4g deg] of the wave's amplitude at it\n",
                    name, end->x_rao[0], end->x_rao[1], end->y_rao[0], end->y_rao[1],
                    end->z_rao[0], end->z_rao[1]);
  }
  const long steps = grid.outputs * grid.steps_per_output;
  if (m.line.law == LinkLaw::kElastic)
    std::printf("  stable time step of the explicit scheme %.4g s (stiffest at station %d)\n",
                grid.limit.time_step, grid.limit.station);
  switch (grid.options.scheme) {
    case Scheme::kExplicit:
      std::printf("  integrator explicit, time step %.4g s = %.2f x the stability limit%s, %ld steps\n",
                  grid.dt, grid.dt / grid.limit.time_step,
                  grid.automatic ? " (auto: safety factor)" : " (given)", steps);
      if (!grid.automatic && grid.dt > grid.limit.time_step)
        std::printf("  warning: the time step is above the stability limit; the explicit scheme "
                    "will blow up (use integrator = \"implicit\" or time_step = \"auto\")\n");
      break;
    case Scheme::kImplicit:
      if (grid.automatic)
        std::printf("  integrator implicit (generalized-alpha, rho_inf %.2f), adaptive step up to "
                    "%.4g s (%.0f x the explicit limit), tolerance %.3g m: each step's local "
                    "position error estimate kept below it (the error a step adds, not the "
                    "run's total)\n",
                    grid.options.rho_inf, grid.dt, grid.dt / grid.limit.time_step, grid.options.tolerance);
      if (grid.automatic && grid.options.start_end > 0)
        std::printf("  while the motion starts, until t = %.4g s: tolerance %.3g m (the start's "
                    "free oscillations carry their phase error on)\n",
                    grid.options.start_end, grid.options.start_tolerance);
      else
        std::printf("  integrator implicit (generalized-alpha, rho_inf %.2f), time step %.4g s "
                    "(given) = %.0f x the explicit limit, %ld steps\n",
                    grid.options.rho_inf, grid.dt, grid.dt / grid.limit.time_step, steps);
      break;
    case Scheme::kInextensible:
      if (grid.options.tolerance > 0)
        std::printf("  integrator inextensible (constraint tensions), output every %.4g s, "
                    "substeps below the transverse wave limit and error-controlled: tolerance "
                    "%.3g m, each step's local position error estimate kept below it\n",
                    grid.interval, grid.options.tolerance);
      else
        std::printf("  integrator inextensible (constraint tensions), output every %.4g s, "
                    "substeps from the transverse wave limit\n",
                    grid.interval);
      break;
  }
  std::vector<std::string> notes, warnings;
  DescribeTables(scene, &notes, &warnings);
  for (const std::string& n : notes) std::printf("  %s\n", n.c_str());
  for (const std::string& w : warnings) std::printf("  warning: %s\n", w.c_str());
  const Vec a = m.ends.start.Position(0), b = m.ends.end.Position(0);
  if (m.line.law == LinkLaw::kElastic && m.ends.start.prescribed() && m.ends.end.prescribed() &&
      (b - a).norm() > m.line.total_length())
    std::printf("  warning: the ends are %.3g %% further apart than the cable is long: it starts "
                "stretched\n",
                100.0 * ((b - a).norm() / m.line.total_length() - 1.0));
}

// The progress line of a run, and its stop at a signal (seen between rows; within a step, the
// inputs' stop flag).
class ProgressSink : public RowSink {
 public:
  ProgressSink(const std::string& label, double end) : line_(label, end, "s") {}
  bool Row(const LineData& d) override {
    line_.Update(d.state.t);
    return g_signal == 0;
  }
  void Finish() { line_.Finish(); }

 private:
  ProgressLine line_;
};

// The snap check of a line's run (RefineStepControl): sets summary's refinement, refined_peak,
// refined_peak_change.
void CheckPeakUnderRefinement(const SceneDef& scene, const LineModel& m, RunSummary* s) {
  SceneDef refined = scene;
  const std::string how =
      RefineStepControl(refined.simulation, s->tolerance, s->stats.snap_windows);
  RunSummary rs;
  try {  // the run's own files are written: a failure here is reported, not thrown
    Run r = PrepareRun(refined, m, "refined", &g_signal);
    ProgressSink progress("checking the peak under refinement (" + how + ")", r.grid.end());
    ExecuteRun(r, {&progress});
    progress.Finish();
    rs = r.summary;
  } catch (const Error& e) {
    rs.completed = false;
    rs.failure = e.what();
  }
  ReportRefinement(how, rs, s);
}

// One model of a scene simulated into result files: the equilibrium, the time series (with
// `suffix` before .csv), every station and link (results<suffix>.nc), the run's report; the
// run keeps the largest tension of every row (for the pictures) and what the film needs. A run
// cut short (summary.completed false) has committed its rows under the .partial names;
// summary.failure then holds a blow-up's message (empty: stopped by a signal).
Run SimulateToFiles(const SceneDef& scene, const LineModel& m, const std::string& out_dir,
                    const std::string& suffix) {
  PrintSummary(scene, m, ChooseTimeGrid(m, scene.simulation, scene.output.interval));
  Run run = PrepareRun(scene, m, LawName(m.line.law), &g_signal);
  const LineEquilibriumReport& eq = run.equilibrium;
  const Eigen::VectorXd& T0 = run.initial.tension();
  if (scene.initial == InitialStateKind::kEquilibrium)
    std::printf("equilibrium: %d Newton iterations%s, residual %.3g N (of %.4g N), %.2f ms; "
                "tension %.6g N at the start, %.6g N at the end\n",
                eq.iterations,
                eq.fallback ? (" (" + std::to_string(eq.fallback_iterations) +
                               " pseudo-transient after Newton stalled)").c_str()
                            : "",
                eq.residual, eq.force_scale, run.equilibrium_ms, T0[0], T0[m.line.links - 1]);
  else
    std::printf("initial state: the straight chord at rest (not an equilibrium), written to "
                "equilibrium%s.csv; tension %.6g N at the start, %.6g N at the end\n",
                suffix.c_str(), T0[0], T0[m.line.links - 1]);
  WriteEquilibriumCsv(out_dir + "/equilibrium" + suffix + ".csv", m, run.initial.state, T0);

  const std::string series_path = out_dir + "/timeseries" + suffix + ".csv";
  const std::string partial_path = out_dir + "/timeseries" + suffix + ".partial.csv";
  TimeseriesWriter series(series_path, m, run.inputs, &run.row_ends);
  const std::string nc_path = out_dir + "/results" + suffix + ".nc";
  const std::string nc_partial_path = out_dir + "/results" + suffix + ".partial.nc";
  const std::unique_ptr<LineResultsNc> links =
      OpenLineResultsNc(nc_path, MakeNetcdfInfo(scene, ModelName(m), run.grid.outputs + 1), m,
                        run.initial.state, T0);
  ProgressSink progress(std::string("simulating (") + run.label + ")", run.grid.end());
  ExecuteRun(run, {&series, links.get(), &progress});
  progress.Finish();
  RunSummary& s = run.summary;
  if (!s.completed) {
    series.CommitPartial(partial_path);
    links->CommitPartial(nc_partial_path);
    if (!s.failure.empty())
      s.failure += "; the rows up to then are in " + EscapeText(partial_path) + " and " +
                   EscapeText(nc_partial_path);
    else
      std::fprintf(stderr, "interrupted at t = %.4g s; rows so far in %s and %s\n", s.duration,
                   EscapeText(partial_path).c_str(), EscapeText(nc_partial_path).c_str());
    return run;
  }
  series.Commit();
  links->Commit();
  std::printf("simulated %.6g s in %.3g s of computer time: %s, %.3g station-steps/s\n",
              s.duration, s.wall, DescribeSteps(s.stats).c_str(),
              static_cast<double>(s.stats.steps) * m.stations() / s.wall);
  // Sampled as the CSV is: at the output rows (every `interval`), not at every step.
  std::printf("peak tension %.6g N at t = %.4g s in link %d (the largest tension_max of the "
              "%ld rows, one every %.4g s)\n",
              s.peak, s.peak_t, s.peak_link, s.rows, run.grid.interval);
  if (s.utilisation_link >= 0)
    std::printf("peak utilisation %.4g %% (tension / minimum_breaking_load: %.6g N of %.6g N) at "
                "t = %.4g s in link %d, material %s\n",
                100 * s.utilisation, s.utilisation_tension, s.utilisation_mbl, s.utilisation_t,
                s.utilisation_link, QuoteText(s.utilisation_material).c_str());
  std::printf("largest end loads %.6g N at the start (t = %.4g s), %.6g N at the end (t = %.4g s)"
              " (fx..fz_start, fx..fz_end of the time series)\n",
              s.start_load_max, s.start_load_t, s.end_load_max, s.end_load_t);
  std::printf("wrote %s\n", EscapeText(series_path).c_str());
  std::printf("wrote %s\n", EscapeText(nc_path).c_str());
  for (const std::string& w : s.warnings) std::printf("warning: %s\n", w.c_str());
  if (s.stats.record.unresolved_snaps > 0) CheckPeakUnderRefinement(scene, m, &s);
  const std::string report_path = out_dir + "/run_report" + suffix + ".toml";
  WriteRunReport(report_path, s);
  std::printf("wrote %s\n", EscapeText(report_path).c_str());
  return run;
}

// The runs so far, the last cut short: max_tension.partial.png beside timeseries.partial.csv
// (a failure to draw it is reported, not thrown: the run's own message comes next). Then a
// blow-up's message is thrown; a signal gives its exit status.
int EndCutShort(const SceneDef& scene, const std::vector<const Run*>& runs,
                const std::string& failure, const std::string& out_dir,
                RunReport* report) {
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
  return 128 + g_signal;
}

}  // namespace

int CheckCommand(const std::string& scene_path) {
  const SceneDef scene = LoadScene(scene_path);
  if (scene.is_system()) return CheckSystem(scene);
  const LineModel m = BuildModel(scene);
  CheckModelLimits(scene, m);
  PrintSummary(scene, m, ChooseTimeGrid(m, scene.simulation, scene.output.interval));
  if (scene.initial == InitialStateKind::kEquilibrium) {
    // The initial state is part of the scene: a cable with no steady state is caught here,
    // not after `run` has set up its outputs.
    InstallSignalHandlers();
    LineEquilibriumReport eq;
    MakeInitialState(scene, m, &eq, &g_signal);
    std::printf("  static equilibrium found: %d Newton iterations%s, residual %.3g N\n",
                eq.iterations, eq.fallback ? " (with the pseudo-transient fallback)" : "",
                eq.residual);
  }
  std::printf("ok\n");
  return 0;
}

int RunCommand(const std::string& scene_path, const RunOptions& options, RunReport* report) {
  const SceneDef scene = LoadScene(scene_path);
  if (scene.is_system()) return RunSystem(scene, options, report);
  const bool film = options.film >= 0 ? options.film == 1 : scene.output.film;
  const FilmSettings look = film ? ResolveFilm(scene, options, kCommandLineNames) : FilmSettings{};
  const LineModel model = BuildModel(scene);
  CheckModelLimits(scene, model);
  OutDirLock lock;
  const std::string out_dir = PrepareOutDir(scene, options, lock);
  InstallSignalHandlers();
  const Run run = SimulateToFiles(scene, model, out_dir, "");
  if (report) report->summary = run.summary;
  const std::vector<const Run*> runs{&run};
  if (!run.summary.completed)
    return EndCutShort(scene, runs, run.summary.failure, out_dir, report);
  // Figure 1 from every row, film or not (a film cut short leaves it whole: it has every row).
  const PictureReport figure =
      WriteMaxTensionFigure(scene, runs, out_dir, true);
  if (report) report->figure = figure;
  if (!film) return 0;
  PictureReport shown;
  const bool finished =
      RenderFilm(scene, runs, MakeFilmRequest(look, out_dir, options.shader_dir), g_signal, &shown);
  if (report) report->film = shown;
  return finished ? 0 : 128 + g_signal;
}

int CompareCommand(const std::string& scene_path, const RunOptions& options) {
  SceneDef scene = LoadScene(scene_path);
  const bool film = options.film >= 0 ? options.film == 1 : scene.output.film;
  const FilmSettings look = film ? ResolveFilm(scene, options, kCommandLineNames) : FilmSettings{};
  for (const CableModelKind kind : {CableModelKind::kElastic, CableModelKind::kInextensible}) {
    scene.model = kind;
    CheckModelLimits(scene, BuildModel(scene));
  }
  OutDirLock lock;
  const std::string out_dir = PrepareOutDir(scene, options, lock);
  InstallSignalHandlers();
  scene.model = CableModelKind::kElastic;
  const Run elastic = SimulateToFiles(scene, BuildModel(scene), out_dir, "");
  std::vector<const Run*> runs{&elastic};
  if (!elastic.summary.completed)
    return EndCutShort(scene, runs, elastic.summary.failure, out_dir, nullptr);
  scene.model = CableModelKind::kInextensible;
  const Run rigid = SimulateToFiles(scene, BuildModel(scene), out_dir, "_inextensible");
  runs.push_back(&rigid);
  if (!rigid.summary.completed)
    return EndCutShort(scene, runs, rigid.summary.failure, out_dir, nullptr);
  const RunSummary &e = elastic.summary, &r = rigid.summary;
  std::printf("peak tension: elastic %.6g N (t = %.4g s), inextensible %.6g N (t = %.4g s), "
              "ratio inextensible/elastic %.4g\n",
              e.peak, e.peak_t, r.peak, r.peak_t, r.peak / e.peak);
  WriteMaxTensionFigure(scene, runs, out_dir, true);
  if (!film) return 0;
  const bool finished =
      RenderFilm(scene, runs, MakeFilmRequest(look, out_dir, options.shader_dir), g_signal);
  return finished ? 0 : 128 + g_signal;
}

}  // namespace cablefilm
