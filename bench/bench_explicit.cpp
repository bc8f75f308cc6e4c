// Case P63 with the explicit scheme at 60, 600 and 6000 links (same sections and weight, finer
// stations): time step, steps, wall seconds, station-steps per second, and the peak of
// tension_max with its time. The explicit step shrinks as 1/N, so the cost grows as N^2: runs
// longer than --max-steps are cut short and their wall time for the whole duration projected.
//   bench_explicit [--scene FILE] [--duration S] [--max-steps N] [--sizes 60,600,6000]
//                  [--implicit DT]   (the implicit scheme at a fixed step DT instead)
#include <chrono>
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

int main(int argc, char** argv) {
  std::string scene_path = std::string(CABLEFILM_SOURCE_DIR) + "/scenes/polachek1963.toml";
  double duration = 60.0;
  double max_steps = 3e6;
  double implicit_dt = -1;
  std::vector<int> sizes = {60, 600, 6000};
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--scene")) scene_path = argv[i + 1];
    else if (!std::strcmp(argv[i], "--duration")) duration = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--implicit")) implicit_dt = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--max-steps")) max_steps = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--sizes")) {
      sizes.clear();
      std::stringstream ss(argv[i + 1]);
      for (std::string s; std::getline(ss, s, ',');) sizes.push_back(std::stoi(s));
    }
  }
  const SceneDef base = LoadScene(scene_path);
  int base_links = 0;
  for (const SectionDef& s : base.lines[0].sections) base_links += s.segments;
  std::printf("case %s, %.4g s simulated, explicit scheme (central differences)\n",
              scene_path.c_str(), duration);
  std::printf("%7s %11s %10s %10s %12s %14s %12s %9s %s\n", "links", "dt [s]", "steps",
              "wall [s]", "equil [ms]", "station-steps/s", "peak T [N]", "at t [s]", "");
  for (int links : sizes) {
    SceneDef scene = base;
    for (SectionDef& s : scene.lines[0].sections) s.segments = s.segments * links / base_links;
    scene.simulation.duration = duration;
    scene.simulation.integrator = IntegratorChoice::kExplicit;
    scene.simulation.time_step = 0;  // auto: the stability limit
    if (implicit_dt >= 0) {
      scene.simulation.integrator = IntegratorChoice::kImplicit;
      scene.simulation.time_step = implicit_dt;
    }
    Model model = BuildModel(scene);
    const LineModel& m = model.lines.front();
    TimeGrid grid = ChooseTimeGrid(model, scene.simulation, scene.output.interval);
    const double total_steps = static_cast<double>(grid.outputs) * grid.steps_per_output;
    bool projected = false;
    if (total_steps > max_steps) {
      grid.outputs = std::max<long>(1, static_cast<long>(max_steps / grid.steps_per_output));
      projected = true;
    }
    const auto t0 = std::chrono::steady_clock::now();
    EquilibriumReport report;
    const std::vector<State> states = MakeInitialState(scene, model, grid, &report, nullptr);
    const auto t1 = std::chrono::steady_clock::now();
    const Inputs in = SceneInputs(model);
    Data d = MakeData(model, in, grid.options, states);
    double peak = 0, peak_t = 0;
    RowFunction sink([&](const Data& row) {
      if (row.lines.front().tension().maxCoeff() > peak) {
        peak = row.lines.front().tension().maxCoeff();
        peak_t = row.t;
      }
      return true;
    });
    Drive(model, d, in, grid, {&sink});
    const auto t2 = std::chrono::steady_clock::now();
    const double wall = std::chrono::duration<double>(t2 - t1).count();
    const double steps = static_cast<double>(grid.outputs) * grid.steps_per_output;
    const double rate = steps * (m.line.links + 1) / wall;
    const double eq_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
    const StepStats st = ModelStepStats(model, d);
    if (st.newton_iterations)
      std::printf("   (%ld steps, %ld rejected, %.2f Newton iterations per step)\n", st.steps,
                  st.rejected, double(st.newton_iterations) / st.steps);
    if (projected)
      std::printf("%7d %11.4g %10.4g %10.4g %12.3g %14.3g %12.6g %9.4g projected: ran %.3g s of %.4g s\n",
                  m.line.links, grid.dt, total_steps, wall * total_steps / steps, eq_ms, rate, peak,
                  peak_t, grid.outputs * grid.interval, duration);
    else
      std::printf("%7d %11.4g %10.4g %10.4g %12.3g %14.3g %12.6g %9.4g\n", m.line.links, grid.dt,
                  total_steps, wall, eq_ms, rate, peak, peak_t);
    std::fflush(stdout);
  }
  return 0;
}
