#include "app/run_options.h"

#include "scene/option_values.h"
#include "scene/scene_limits.h"

namespace cablefilm {

void AddRunOptions(CLI::App* cmd, RunOptions* o, const std::string& out_help) {
  Value(cmd, "--out", "DIR", out_help, [o](const std::string& v) { o->out_dir = v; });
  Flag(cmd, "--no-film", "result files only, no rendering", [o] { o->film = 0; });
  Flag(cmd, "--film", "make the film even if the scene says film = false", [o] { o->film = 1; });
  Flag(cmd, "--frames", "also keep every frame as PNG in DIR/frames/ (and make the film)", [o] {
    o->frames = 1;
    if (o->film < 0) o->film = 1;
  });
  Value(cmd, "--size", "WxH", "film size in pixels, even, 16x16 to 7680x4320 (default 1920x1080)",
        [o](const std::string& v) { ParseSize("--size", v, &o->width, &o->height); });
  Value(cmd, "--fps", "N", "film frames per second, 1 to 240 (default 30)",
        [o](const std::string& v) {
          o->fps = ParseNumber("--fps", v, kMinFps, kMaxFps, false, " frames per second");
        });
  // The film's frame count (1 to kMaxFilmFrames) depends on the scene: checked with it.
  Value(cmd, "--speed", "X", "simulated seconds per second of film (default 1: real time)",
        [o](const std::string& v) {
          o->speed = ParseNumber("--speed", v, 0, kMaxTime, true,
                                 " simulated seconds per second of film");
        });
  Value(cmd, "--colormap", "NAME", "viridis (default), cividis, magma, inferno, plasma",
        [o](const std::string& v) { o->colormap = ParseColormap("--colormap", v); });
  Value(cmd, "--tension-range", "MIN,MAX", "colour and plot range in N (default: the run's)",
        [o](const std::string& v) {
          ParseTensionRange("--tension-range", v, &o->tension_min, &o->tension_max);
        });
  Value(cmd, "--view", "VIEW",
        "auto (default: 3D unless the scene stays in the plane z = 0), 2d, 3d",
        [o](const std::string& v) { o->view = ParseView("--view", v); });
  Value(cmd, "--film-window", "WINDOW",
        "film only part of the run: peak:SECONDS (around its peak), T0,T1 or whole (default: "
        "the scene's film.window, else whole)",
        [o](const std::string& v) {
          const std::string problem = FilmWindowProblem(v, &o->window);
          if (!problem.empty()) Bad("--film-window: " + problem);
          o->window_given = true;
          if (o->film < 0) o->film = 1;
        });
  Value(cmd, "--shaders", "DIR", "GLSL shader folder (default: $CABLEFILM_SHADERS, else built in)",
        [o](const std::string& v) { o->shader_dir = ParseShaderDir("--shaders", v); });
}

}  // namespace cablefilm
