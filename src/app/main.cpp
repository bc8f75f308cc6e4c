// cablefilm: argument parsing only; the work is in commands.cpp.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "app/commands.h"
#ifdef CABLEFILM_LIVE
#include "app/live_command.h"
#endif
#include "core/error.h"

namespace {

const char* kUsage =
    "usage: cablefilm run SCENE [options]   simulate, write the results and the film\n"
    "       cablefilm compare SCENE [options]  elastic and inextensible runs, Figure 1\n"
    "       cablefilm check SCENE           validate a scene and print its summary\n"
    "       cablefilm live SCENE [options]  simulate in real time, watch and steer it in a browser\n"
    "\n"
    "run and compare options:\n"
    "  --out DIR              output folder (default output/<scene name>)\n"
    "  --no-film              result files only, no rendering\n"
    "  --frames               also keep every frame as PNG under DIR/frames/\n"
    "  --size WxH             film size in pixels, even numbers (default 1920x1080)\n"
    "  --fps N                film frames per second (default 30)\n"
    "  --speed X              simulated seconds per second of film (default 1: real time)\n"
    "  --colormap NAME        viridis (default), cividis, magma, inferno or plasma\n"
    "  --tension-range A,B    colour and plot range in N (default: the run's range)\n"
    "  --shaders DIR          GLSL shader folder (default: $CABLEFILM_SHADERS or built-in)\n"
    "\n"
    "live options:\n"
    "  --port N               port to serve on (default 8080; 0: any free port)\n"
    "  --bind ADDR            address to listen on (default 127.0.0.1: this machine only)\n"
    "  --size WxH             frame size in pixels, even numbers (default 1280x720)\n"
    "  --fps N                frames per second, 1 to 120 (default 30)\n"
    "  --speed X              simulated seconds per second, 0.1 to 10 (default 1)\n"
    "  --colormap NAME        as for run (default: the scene's)\n"
    "  --out DIR              where recordings go (default output/<scene name>)\n"
    "  --shaders DIR          as for run\n";

[[noreturn]] void UsageError(const std::string& message) {
  std::fprintf(stderr, "cablefilm: %s\n%s", message.c_str(), kUsage);
  std::exit(2);
}

double ParseNumber(const std::string& option, const char* text) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(v > 0))
    UsageError(option + ": expected a positive number, got \"" + text + "\"");
  return v;
}

#ifdef CABLEFILM_LIVE
int LiveMain(int argc, char** argv) {
  std::string scene;
  cablefilm::LiveCommandOptions options;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) UsageError(arg + ": missing value");
      return argv[++i];
    };
    if (arg == "--help" || arg == "-h") {
      std::printf("%s", kUsage);
      return 0;
    } else if (arg == "--port") {
      const char* v = value();
      char* end = nullptr;
      const long port = std::strtol(v, &end, 10);
      if (end == v || *end != '\0' || port < 0 || port > 65535)
        UsageError("--port: expected a port number 0..65535, got \"" + std::string(v) + "\"");
      options.port = static_cast<int>(port);
    } else if (arg == "--bind") {
      options.bind = value();
    } else if (arg == "--size") {
      const char* v = value();
      char tail = 0;
      if (std::sscanf(v, "%dx%d%c", &options.width, &options.height, &tail) != 2 ||
          options.width < 16 || options.height < 16 || options.width > 7680 ||
          options.height > 4320 || options.width % 2 || options.height % 2)
        UsageError("--size: expected WxH with even numbers of pixels, 16x16 to 7680x4320, got \"" +
                   std::string(v) + "\"");
    } else if (arg == "--fps") {
      options.fps = ParseNumber(arg, value());
      if (options.fps < 1 || options.fps > 120) UsageError("--fps: expected 1 to 120");
    } else if (arg == "--speed") {
      options.speed = ParseNumber(arg, value());
      if (options.speed < 0.1 || options.speed > 10) UsageError("--speed: expected 0.1 to 10");
    } else if (arg == "--colormap") {
      options.colormap = value();
    } else if (arg == "--out") {
      options.out_dir = value();
    } else if (arg == "--shaders") {
      options.shader_dir = value();
    } else if (!arg.empty() && arg[0] == '-') {
      UsageError("unknown option \"" + arg + "\" for live");
    } else if (scene.empty()) {
      scene = arg;
    } else {
      UsageError("more than one scene given");
    }
  }
  if (scene.empty()) UsageError("missing SCENE");
  try {
    return cablefilm::LiveCommand(scene, options);
  } catch (const cablefilm::Error& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "cablefilm: error: %s\n", e.what());
    return 1;
  }
}
#endif

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) UsageError("missing command");
  const std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    std::printf("%s", kUsage);
    return 0;
  }
  if (command == "live") {
#ifdef CABLEFILM_LIVE
    return LiveMain(argc, argv);
#else
    std::fprintf(stderr, "cablefilm: this build has no live view (configured with CABLEFILM_RENDER=OFF)\n");
    return 2;
#endif
  }
  const bool runs = command == "run" || command == "compare";
  if (!runs && command != "check") UsageError("unknown command \"" + command + "\"");
  std::string scene;
  cablefilm::RunOptions options;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) UsageError(arg + ": missing value");
      return argv[++i];
    };
    if (runs && arg == "--out") {
      options.out_dir = value();
    } else if (runs && arg == "--no-film") {
      options.film = 0;
    } else if (runs && arg == "--film") {
      options.film = 1;
    } else if (runs && arg == "--frames") {
      options.frames = 1;
      if (options.film < 0) options.film = 1;
    } else if (runs && arg == "--size") {
      const char* v = value();
      if (std::sscanf(v, "%dx%d", &options.width, &options.height) != 2 || options.width < 16 ||
          options.height < 16 || options.width % 2 || options.height % 2)
        UsageError("--size: expected WxH with even numbers of pixels, got \"" + std::string(v) + "\"");
    } else if (runs && arg == "--fps") {
      options.fps = ParseNumber(arg, value());
    } else if (runs && arg == "--speed") {
      options.speed = ParseNumber(arg, value());
    } else if (runs && arg == "--colormap") {
      options.colormap = value();
    } else if (runs && arg == "--tension-range") {
      const char* v = value();
      if (std::sscanf(v, "%lf,%lf", &options.tension_min, &options.tension_max) != 2 ||
          !(options.tension_min >= 0) || !(options.tension_max > options.tension_min))
        UsageError("--tension-range: expected MIN,MAX in N with MAX > MIN >= 0, got \"" +
                   std::string(v) + "\"");
    } else if (runs && arg == "--shaders") {
      options.shader_dir = value();
    } else if (!arg.empty() && arg[0] == '-') {
      UsageError("unknown option \"" + arg + "\" for " + command);
    } else if (scene.empty()) {
      scene = arg;
    } else {
      UsageError("more than one scene given");
    }
  }
  if (scene.empty()) UsageError("missing SCENE");
  try {
    if (command == "run") return cablefilm::RunCommand(scene, options);
    if (command == "compare") return cablefilm::CompareCommand(scene, options);
    return cablefilm::CheckCommand(scene);
  } catch (const cablefilm::Error& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "cablefilm: error: %s\n", e.what());
    return 1;
  }
}
