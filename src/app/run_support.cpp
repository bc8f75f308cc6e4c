#include "app/run_support.h"

#include <cmath>
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
    // Without the scheme's numerical damping: it takes the ringing a snap leaves at the line's
    // highest axial frequencies, by a factor that shorter steps alone barely change (a 556 Hz
    // ring of a model-basin chain at steps of 0.2 ms: the refined peak 57.15 N, as the run's,
    // against the explicit scheme's 61.5 N, 62.4 N at a quarter of its step).
    const bool damped = sim.rho_infinity < 1;
    sim.rho_infinity = 1;
    const std::string undamped = damped ? ", rho_infinity 1" : "";
    if (snap_windows == 0) return "tolerance / 10" + undamped;
    sim.safety_factor /= 4;  // and its explicit steps through snaps
    return "tolerance / 10, safety_factor / 4" + undamped;
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

std::string RingingWarning(const RunSummary& s) {
  // 2 %: snap peaks are chaotic in the rounding; two explicit runs of a model-basin chain at
  // 0.8 and 0.1 of the stability limit peak 1.7 % apart.
  const bool finished = std::isfinite(s.refined_peak);
  if (finished && std::abs(s.refined_peak_change) <= kRingingTolerance) return "";
  std::ostringstream os;
  os.precision(3);
  os << "the peak tension is not converged: its " << s.stats.snap_windows
     << " snaps were stepped explicitly, but the implicit steps after them damp the ringing "
        "they leave (the line's highest axial frequencies): ";
  if (finished)
    os << "the run without that damping (" << s.refinement << ") peaks at " << s.refined_peak
       << " N, " << std::showpos << 100 * s.refined_peak_change << std::noshowpos << " %";
  else
    os << "the run without that damping did not finish (" << s.refinement << ")";
  os << ". To resolve it: integrator = \"explicit\", or the material's axial_damping_ratio "
        "(a real line's internal damping takes that ringing too)";
  return os.str();
}

}  // namespace cablefilm
