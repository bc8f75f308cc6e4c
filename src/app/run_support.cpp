#include "app/run_support.h"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/version.h"
#include "io/result_files.h"
#include "scene/film_view.h"
#include "scene/text_escape.h"

namespace cablefilm {

std::atomic<int> g_signal{0};

namespace {
// The first signal asks the work to stop cleanly (partial results kept); a second stops at once.
extern "C" void OnSignal(int sig) {
  if (g_signal != 0) std::_Exit(128 + sig);
  g_signal = sig;
}
}  // namespace

void InstallSignalHandlers() {
  std::signal(SIGINT, OnSignal);
  std::signal(SIGTERM, OnSignal);
}

int InterruptedExitStatus() { return 128 + (g_signal != 0 ? g_signal.load() : SIGINT); }

// results.nc's attributes: the scene (its path and text) and the program's version.
NetcdfResultsInfo MakeNetcdfInfo(const SceneDef& scene, const char* model, long rows) {
  NetcdfResultsInfo info;
  info.title = scene.title;
  info.scene_file = EscapeText(scene.path);
  std::ifstream in(scene.path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  info.scene = std::make_shared<const std::string>(text.str());
  info.version = kVersion;
  if (*kGitDescribe) info.version += std::string(" (git ") + kGitDescribe + ")";
  info.model = model;
  info.initial_state = scene.initial == InitialStateKind::kEquilibrium ? "equilibrium" : "straight";
  info.rows = rows;
  info.planar = SceneIsPlanar(scene);
  return info;
}

std::string PrepareOutDir(const SceneDef& scene, const RunOptions& options, OutDirLock& lock) {
  const std::string out_dir = options.out_dir.empty() ? "output/" + scene.name : options.out_dir;
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec)
    throw Error("cannot create the output folder " + EscapeText(out_dir) + ": " + ec.message());
  lock.Lock(out_dir, "output folder");  // and removes what the earlier run there wrote
  return out_dir;
}


std::string RefineStepControl(SimulationDef& sim, double tolerance, long snap_windows) {
  if (sim.time_step > 0) {
    sim.time_step /= 4;
    return "time_step / 4";
  }
  if (tolerance > 0) {
    sim.tolerance = tolerance / 10;
    if (snap_windows == 0) return "tolerance / 10";
    sim.safety_factor /= 4;  // and its explicit steps through snaps
    return "tolerance / 10, safety_factor / 4";
  }
  sim.safety_factor /= 4;
  return "safety_factor / 4";
}

void ReportRefinement(const std::string& how, const RunSummary& refined, RunSummary* s) {
  s->refinement = how;
  if (!refined.completed) {
    s->refinement += refined.failure.empty() ? " (interrupted)" : " (failed: " + refined.failure + ")";
    std::printf("snap check: the refined run (%s) did not finish\n", s->refinement.c_str());
    return;
  }
  s->refined_peak = refined.peak;
  s->refined_peak_change = (refined.peak - s->peak) / s->peak;
  std::printf("snap check: refined (%s: %ld steps against %ld), the peak is %.6g N at t = %.4g s, "
              "%+.3g %% from %.6g N\n",
              how.c_str(), refined.stats.steps, s->stats.steps, refined.peak, refined.peak_t,
              100 * s->refined_peak_change, s->peak);
}

}  // namespace cablefilm
