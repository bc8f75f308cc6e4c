// Case P63 with the explicit scheme (at its automatic, stable step) and the implicit scheme
// (generalized-alpha, automatic step) at 60, 600 and 6000 links: wall time, steps, rejected
// steps, Newton iterations per step, the peak of tension_max and its relative difference from a
// converged reference computed here (explicit, --ref-links links, step halved from the stable
// one until the peak changes by less than 1e-5 relative). Explicit runs of more than --max-steps
// steps are cut short and their wall time for the whole duration is projected (marked).
// Also the static equilibrium's time at 60 links (and at --statics-sizes: issue 23 asks 60 000
// links under 60 ms). Repeated timings are medians of --repeat runs.
//   bench_integrators [--scene FILE] [--duration S] [--max-steps N] [--sizes 60,600,6000]
//                     [--ref-links N] [--repeat N] [--statics-sizes 60,60000] [--statics-only]
// (--statics-only: the statics' figures alone)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "run/driver.h"
#include "run/initial_state.h"
#include "run/time_grid.h"
#include "scene/build_model.h"
#include "scene/scene_loader.h"
#include "../tests/run/scene_line.h"

using namespace cablefilm;

namespace {

using Clock = std::chrono::steady_clock;

std::vector<int> Sizes(const char* list) {
  std::vector<int> sizes;
  std::stringstream ss(list);
  for (std::string s; std::getline(ss, s, ',');) sizes.push_back(std::stoi(s));
  return sizes;
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

SceneDef Resized(const SceneDef& base, int links, double duration) {
  SceneDef scene = base;
  int base_links = 0;
  for (const SectionDef& s : base.lines[0].sections) base_links += s.segments;
  for (SectionDef& s : scene.lines[0].sections) s.segments = s.segments * links / base_links;
  scene.simulation.duration = duration;
  return scene;
}

struct RunResult {
  double wall = 0;         // [s], for the steps run
  double total_steps = 0;  // for the whole duration
  double steps_run = 0;
  bool projected = false;
  double dt = 0;
  double peak = 0;         // of tension_max over the outputs [N]
  StepStats stats;
};

// max_steps <= 0: no cap. dt_override > 0: that step (explicit), else the scene's "auto".
RunResult Run(const SceneDef& scene_in, IntegratorChoice kind, double max_steps,
              double dt_override = 0) {
  SceneDef scene = scene_in;
  scene.simulation.integrator = kind;
  scene.simulation.time_step = dt_override;
  Model model = BuildModel(scene);
  TimeGrid grid = ChooseTimeGrid(model, scene.simulation, scene.output.interval);
  RunResult r;
  r.dt = grid.dt;
  r.total_steps = static_cast<double>(grid.outputs) * grid.steps_per_output;
  if (max_steps > 0 && r.total_steps > max_steps) {
    grid.outputs = std::max<long>(1, static_cast<long>(max_steps / grid.steps_per_output));
    r.projected = true;
  }
  r.steps_run = static_cast<double>(grid.outputs) * grid.steps_per_output;
  const std::vector<State> states = MakeInitialState(scene, model, grid, nullptr, nullptr);
  const Inputs in = SceneInputs(model);
  Data d = MakeData(model, in, grid.options, states);
  RowFunction sink([&](const Data& row) {
    r.peak = std::max(r.peak, row.lines.front().tension().maxCoeff());
    return true;
  });
  const auto t0 = Clock::now();
  Drive(model, d, in, grid, {&sink});
  r.wall = std::chrono::duration<double>(Clock::now() - t0).count();
  r.stats = ModelStepStats(model, d);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene_path = std::string(CABLEFILM_SOURCE_DIR) + "/scenes/polachek1963.toml";
  double duration = 60.0;
  double max_steps = 3e6;
  int ref_links = 600;
  int repeat = 3;
  std::vector<int> sizes = {60, 600, 6000}, statics_sizes = {60};
  bool statics_only = false;
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--statics-only")) statics_only = true;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--statics-only")) --i;  // a flag: no value
    if (!std::strcmp(argv[i], "--scene")) scene_path = argv[i + 1];
    else if (!std::strcmp(argv[i], "--duration")) duration = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--max-steps")) max_steps = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--ref-links")) ref_links = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--repeat")) repeat = std::max(1, std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--sizes")) sizes = Sizes(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--statics-sizes")) statics_sizes = Sizes(argv[i + 1]);
  }
  const SceneDef base = LoadScene(scene_path);
  std::printf("case %s, %.4g s simulated, output every %.4g s\n", scene_path.c_str(), duration,
              base.output.interval);

  // Static equilibrium: median of several solves.
  for (int links : statics_sizes) {
    const SceneDef scene = Resized(base, links, duration);
    const LineModel m = LineOf(scene);
    std::vector<double> ms;
    LineEquilibriumReport rep;
    for (int i = 0; i < std::max(5, repeat); ++i) {
      const auto t0 = Clock::now();
      InitialStateOf(scene, &rep);
      ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    std::printf("static equilibrium, %d links: %.3f ms (median of %zu), %d Newton iterations\n",
                links, Median(ms), ms.size(), rep.iterations);
  }
  if (statics_only) return 0;

  // The reference: explicit at ref_links links, step halved until the peak settles.
  const SceneDef ref_scene = Resized(base, ref_links, duration);
  double dt = Run(ref_scene, IntegratorChoice::kExplicit, 1).dt;  // the stable "auto" step
  double ref_peak = Run(ref_scene, IntegratorChoice::kExplicit, 0, dt).peak;
  std::printf("reference: explicit, %d links: dt %.4g s, peak %.8g N\n", ref_links, dt, ref_peak);
  for (int halving = 1; halving <= 6; ++halving) {
    dt *= 0.5;
    const double peak = Run(ref_scene, IntegratorChoice::kExplicit, 0, dt).peak;
    const double change = std::abs(peak / ref_peak - 1);
    std::printf("reference: explicit, %d links: dt %.4g s, peak %.8g N (change %.2e)\n",
                ref_links, dt, peak, change);
    ref_peak = peak;
    if (change < 1e-5) break;
  }
  std::fflush(stdout);

  std::printf("\n(implicit, auto: adaptive steps up to the output interval, shown as dt)\n");
  std::printf("%-9s %6s %10s %10s %9s %12s %8s %12s %13s %10s %s\n", "scheme", "links", "dt [s]",
              "steps", "rejected", "Newton/step", "wall [s]", "peak T [N]", "vs ref [%]",
              "timings", "");
  for (int links : sizes) {
    const SceneDef scene = Resized(base, links, duration);
    for (IntegratorChoice kind : {IntegratorChoice::kExplicit, IntegratorChoice::kImplicit}) {
      std::vector<double> walls;
      RunResult r;
      // Repeat only runs that take under ~20 s; the long ones once.
      for (int i = 0; i < repeat; ++i) {
        r = Run(scene, kind, kind == IntegratorChoice::kExplicit ? max_steps : 0);
        walls.push_back(r.wall * r.total_steps / r.steps_run);
        if (r.wall > 20) break;
      }
      const bool expl = kind == IntegratorChoice::kExplicit;
      const double newton =
          r.stats.steps ? double(r.stats.newton_iterations) / r.stats.steps : 0.0;
      char peak[32], diff[32];
      if (r.projected) {
        std::snprintf(peak, sizeof peak, "%s", "-");
        std::snprintf(diff, sizeof diff, "%s", "-");
      } else {
        std::snprintf(peak, sizeof peak, "%.2f", r.peak);
        std::snprintf(diff, sizeof diff, "%+.4f", 100 * (r.peak / ref_peak - 1));
      }
      std::printf("%-9s %6d %10.4g %10.4g %9ld %12s %8.3g %12s %13s %10s %s\n",
                  expl ? "explicit" : "implicit", links, r.dt,
                  expl ? r.total_steps : double(r.stats.steps), r.stats.rejected,
                  expl ? "-" : (std::to_string(newton).substr(0, 5)).c_str(), Median(walls), peak,
                  diff, (walls.size() > 1 ? "median/" + std::to_string(walls.size()) : "1 run").c_str(),
                  r.projected ? "PROJECTED wall time (ran only part of the steps)" : "");
      if (r.projected)
        std::printf("%-9s %6s ran %.4g of %.4g steps (%.3g of %.4g s simulated) in %.3g s; the "
                    "full run is projected at %.3g s\n",
                    "", "", r.steps_run, r.total_steps, r.steps_run * r.dt, duration, r.wall,
                    r.wall * r.total_steps / r.steps_run);
      std::fflush(stdout);
    }
  }
  return 0;
}
