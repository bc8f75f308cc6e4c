#include "app/commands.h"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>

#include "app/progress.h"
#include "app/run_extent.h"
#include "app/result_files.h"
#include "app/simulation_run.h"
#include "core/forces.h"
#include "scene/build_model.h"
#include "scene/scene_loader.h"

#ifdef CABLEFILM_HAVE_RENDER
#include "app/film_pass.h"
#endif

namespace cablefilm {
namespace {

std::atomic<int> g_signal{0};
extern "C" void OnSignal(int sig) { g_signal = sig; }

void InstallSignalHandlers() {
  std::signal(SIGINT, OnSignal);
  std::signal(SIGTERM, OnSignal);
}

Eigen::VectorXd TensionsOf(const CableModel& m, const CableState& s) {
  ForceWorkspace ws(m.links);
  ComputeGeometry(s.x, ws.geometry);
  ComputeHookeTensions(m, ws.geometry, ws.tension);
  return ws.tension;
}

void PrintSummary(const SceneDef& scene, const CableModel& m, const TimeGrid& grid) {
  const double cable_mass = m.link_mass.sum();
  double weights = 0;
  for (const WeightDef& w : scene.weights) weights += w.mass;
  std::printf("scene %s: \"%s\"\n", scene.path.c_str(), scene.title.c_str());
  std::printf("  %d stations, %d links in %zu section(s), unstretched length %.6g m\n",
              m.stations(), m.links, scene.sections.size(), m.total_length());
  std::printf("  mass %.6g kg (cable %.6g kg, %zu weight(s) %.6g kg), net weight in fluid %.6g N\n",
              cable_mass + weights, cable_mass, scene.weights.size(), weights,
              m.net_weight.sum());
  std::printf("  stable time step (explicit) %.4g s, stiffest at station %d\n",
              grid.limit.time_step, grid.limit.station);
  if (grid.automatic)
    std::printf("  time step %.4g s = %.2f x the stability limit (safety factor %.2f), %ld steps\n",
                grid.dt, grid.dt / grid.limit.time_step, grid.safety_factor,
                grid.outputs * grid.steps_per_output);
  else
    std::printf("  time step %.4g s (given), %.2f x the stability limit, %ld steps\n", grid.dt,
                grid.dt / grid.limit.time_step, grid.outputs * grid.steps_per_output);
  if (!grid.automatic && grid.dt > grid.limit.time_step)
    std::printf("  warning: the time step is above the stability limit; the explicit scheme "
                "will likely blow up\n");
  const Eigen::Vector2d a = m.start.Position(0), b = m.end.Position(0);
  if (m.start.prescribed() && m.end.prescribed() && (b - a).norm() > m.total_length())
    std::printf("  warning: the ends are %.3g %% further apart than the cable is long: it starts "
                "stretched\n",
                100.0 * ((b - a).norm() / m.total_length() - 1.0));
}

}  // namespace

int CheckCommand(const std::string& scene_path) {
  const SceneDef scene = LoadScene(scene_path);
  const CableModel m = BuildModel(scene);
  const TimeGrid grid = ChooseTimeGrid(m, scene.simulation, scene.output.interval);
  PrintSummary(scene, m, grid);
  if (scene.model == CableModelKind::kInextensible)
    throw Error(scene.path + ": cable.model: \"inextensible\" is not available yet");
  std::printf("ok\n");
  return 0;
}

int RunCommand(const std::string& scene_path, const RunOptions& options) {
  const SceneDef scene = LoadScene(scene_path);
  if (scene.model == CableModelKind::kInextensible)
    throw Error(scene.path + ": cable.model: \"inextensible\" is not available yet");
  const CableModel m = BuildModel(scene);
  const TimeGrid grid = ChooseTimeGrid(m, scene.simulation, scene.output.interval);
  PrintSummary(scene, m, grid);

  const std::string out_dir =
      options.out_dir.empty() ? "output/" + scene.name : options.out_dir;
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw Error("cannot create the output folder " + out_dir + ": " + ec.message());

  // Initial state.
  const auto t0 = std::chrono::steady_clock::now();
  EquilibriumReport eq;
  const CableState initial = MakeInitialState(scene, m, &eq);
  const double eq_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const Eigen::VectorXd eq_tension = TensionsOf(m, initial);
  if (scene.initial == InitialStateKind::kEquilibrium)
    std::printf("equilibrium: %d Newton iterations, residual %.3g N (of %.4g N), %.1f ms; "
                "tension %.6g N at the start, %.6g N at the end\n",
                eq.iterations, eq.residual, eq.force_scale, eq_ms, eq_tension[0],
                eq_tension[m.links - 1]);
  WriteEquilibriumCsv(out_dir + "/equilibrium.csv", m, initial, eq_tension);

  // Pass 1: the tension time series (and the ranges the film needs).
  InstallSignalHandlers();
  TimeseriesWriter series(out_dir + "/timeseries.csv");
  auto integrator = MakeIntegrator(m, grid);
  CableState state = initial;
  RunExtent extent(m, initial);
  double peak = -1, peak_t = 0;
  int peak_link = 0;
  ProgressLine progress("simulating", grid.outputs * grid.interval, "s");
  const auto t1 = std::chrono::steady_clock::now();
  bool completed = false;
  try {
    completed = Simulate(m, *integrator, state, grid, [&](const CableState& s, const Eigen::VectorXd& T) {
      series.Append(m, s, T);
      extent.Add(s, T);
      Eigen::Index link = 0;
      const double tmax = T.maxCoeff(&link);
      if (tmax > peak) {
        peak = tmax;
        peak_t = s.t;
        peak_link = static_cast<int>(link);
      }
      progress.Update(s.t);
      return g_signal == 0;
    });
  } catch (const BlowUpError& e) {
    progress.Finish();
    series.CommitPartial(out_dir + "/timeseries.partial.csv");
    throw Error(std::string(e.what()) + " (time step " + std::to_string(grid.dt) +
                " s); the rows up to then are in " + out_dir + "/timeseries.partial.csv");
  }
  progress.Finish();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  if (!completed) {
    series.CommitPartial(out_dir + "/timeseries.partial.csv");
    std::fprintf(stderr, "interrupted at t = %.4g s; rows so far in %s/timeseries.partial.csv\n",
                 state.t, out_dir.c_str());
    return 128 + g_signal;
  }
  series.Commit();
  const double station_steps =
      static_cast<double>(grid.outputs) * grid.steps_per_output * (m.links + 1);
  std::printf("simulated %.6g s in %.3g s of computer time (%.3g station-steps/s)\n", state.t,
              wall, station_steps / wall);
  std::printf("peak tension %.6g N at t = %.4g s in link %d\n", peak, peak_t, peak_link);
  std::printf("wrote %s/equilibrium.csv, %s/timeseries.csv\n", out_dir.c_str(), out_dir.c_str());

  const bool film = options.film >= 0 ? options.film == 1 : scene.output.film;
  if (!film) return 0;
#ifdef CABLEFILM_HAVE_RENDER
  return RenderFilmPass(scene, m, initial, eq_tension, extent, grid, options, out_dir, g_signal);
#else
  std::printf("film: not rendered (this build has no renderer: CABLEFILM_RENDER=OFF)\n");
  return 0;
#endif
}

}  // namespace cablefilm
