#pragma once
// The program's commands. Each returns the process exit status; errors are thrown as Error.
#include <string>

namespace cablefilm {

struct RunOptions {
  std::string out_dir;          // empty: output/<scene name>
  int film = -1;                // -1: as the scene says, 0: no film, 1: film
  int frames = -1;              // -1: as the scene says, 0/1: keep PNG frames or not
  int width = 0, height = 0;    // 0: as the scene says
  double fps = 0, speed = 0;    // 0: as the scene says
  std::string colormap;         // empty: as the scene says
  double tension_min = -1, tension_max = -1;  // colour range [N]; negative: as the scene says
  std::string shader_dir;       // empty: CABLEFILM_SHADERS or the built-in path
};

int RunCommand(const std::string& scene_path, const RunOptions& options);
// The exit status after a signal stopped the work (128 + its number).
int InterruptedExitStatus();
int CheckCommand(const std::string& scene_path);
// Runs the scene with the elastic and the inextensible model: timeseries.csv and
// timeseries_inextensible.csv, max_tension.png with both (the paper's Figure 1), the film.
int CompareCommand(const std::string& scene_path, const RunOptions& options);

}  // namespace cablefilm
