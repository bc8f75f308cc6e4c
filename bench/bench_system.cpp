// A mooring system's cost (issue 20: "a 3-leg system of 3 x 200 links for 600 s in under 5 s
// of CPU"): scenes/spread_mooring.toml (three chain legs, one with a clump weight where its two
// lines meet, a ship's fairleads in eq. (3)'s orbit, a sheared current) with each leg's links
// scaled to --links (200), run for --duration (600 s) with the default step control, no files
// written. Prints the machine's load, the statics' time, the steps and the CPU seconds of the
// stepping, the median of --repeats runs.
//   bench_system [--scene FILE] [--links N] [--duration S] [--repeats K]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "run/run.h"
#include "scene/build_model.h"
#include "scene/scene_loader.h"

using namespace cablefilm;

namespace {

std::string LoadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string one;
  in >> one;
  return one.empty() ? "?" : one;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene_path = std::string(CABLEFILM_SOURCE_DIR) + "/scenes/spread_mooring.toml";
  int links = 200, repeats = 3;
  double duration = 600;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--scene")) scene_path = argv[i + 1];
    else if (!std::strcmp(argv[i], "--links")) links = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--duration")) duration = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--repeats")) repeats = std::max(1, std::atoi(argv[i + 1]));
  }
  SceneDef scene = LoadScene(scene_path);
  scene.simulation.duration = duration;
  // Each leg (the lines between an anchor and a fairlead) gets `links` links in all, shared
  // by its lines in proportion to their links.
  int scene_links = 0;
  for (const LineDef& l : scene.lines)
    for (const SectionDef& s : l.sections) scene_links += s.segments;
  const double legs = 3.0, scale = legs * links / scene_links;
  int total = 0;
  for (LineDef& l : scene.lines)
    for (SectionDef& s : l.sections) total += s.segments = std::max(1, int(s.segments * scale + 0.5));
  std::printf("system %s: %zu lines, %d links in all, %.4g s simulated; load average %s\n",
              scene_path.c_str(), scene.lines.size(), total, duration, LoadAverage().c_str());
  std::vector<double> cpu;
  long steps = 0;
  for (int k = 0; k < repeats; ++k) {
    Run run = PrepareRun(scene, BuildModel(scene), "elastic", nullptr);
    const std::clock_t c0 = std::clock();
    ExecuteRun(run, {});
    cpu.push_back(double(std::clock() - c0) / CLOCKS_PER_SEC);
    const RunSummary& s = run.summary;
    steps = s.stats.steps;
    std::printf("run %d: statics %.1f ms, %ld steps (%ld rejected), %.3g Newton iterations per "
                "step, stepping %.3f s CPU, peak %.6g N%s\n",
                k + 1, run.equilibrium_ms, s.stats.steps, s.stats.rejected,
                double(s.stats.newton_iterations) / std::max(1L, s.stats.steps), cpu.back(),
                s.peak, s.completed ? "" : " (not completed)");
  }
  std::sort(cpu.begin(), cpu.end());
  std::printf("median stepping CPU %.3f s (min %.3f, max %.3f) for %d links over %.4g s: "
              "%.3g station-steps per CPU second; load average now %s\n",
              cpu[cpu.size() / 2], cpu.front(), cpu.back(), total, duration,
              double(steps) * (total + int(scene.lines.size())) / cpu[cpu.size() / 2],
              LoadAverage().c_str());
  return 0;
}
