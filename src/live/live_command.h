#pragma once
// cablefilm live: the scene simulated in real time and shown in a browser (src/live).
#include <string>

namespace cablefilm {

struct LiveCommandOptions {
  std::string bind = "127.0.0.1";
  int port = 8080;                  // 0: any free port
  int width = 1280, height = 720;
  double fps = 30, speed = 1;
  std::string colormap;             // empty: the scene's
  std::string view;                 // "auto", "2d", "3d"; empty: the scene's film.view
  std::string out_dir;              // recordings; empty: output/<scene name>
  std::string shader_dir;
};

// Serves until SIGINT or SIGTERM, then stops cleanly (a recording closed and playable): 0.
int LiveCommand(const std::string& scene_path, const LiveCommandOptions& options);

}  // namespace cablefilm
