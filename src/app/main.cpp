// cablefilm: argument parsing only; the work is in commands.cpp.
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "app/commands.h"
#ifdef CABLEFILM_LIVE
#include "app/live_command.h"
#endif
#include "core/cancel.h"
#include "core/error.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"

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
    "  --size WxH             film size in pixels, even numbers, 16x16 to 7680x4320\n"
    "                         (default 1920x1080)\n"
    "  --fps N                film frames per second, 1 to 240 (default 30)\n"
    "  --speed X              simulated seconds per second of film (default 1: real time);\n"
    "                         the film must have 1 to 1e6 frames\n"
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

// `message` quotes what the user typed through Shown().
[[noreturn]] void UsageError(const std::string& message) {
  std::fprintf(stderr, "cablefilm: %s\n%s", message.c_str(), kUsage);
  std::exit(2);
}

std::string Shown(const std::string& text) { return cablefilm::QuoteText(text); }

// A finite decimal number, nothing before or after it.
bool ParseDouble(const std::string& text, double* v) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
  char* end = nullptr;
  errno = 0;
  *v = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0' && errno != ERANGE && std::isfinite(*v);
}

// A finite number within [lo, hi] (lo itself excluded when lo_open).
double ParseNumber(const std::string& option, const char* text, double lo, double hi,
                   bool lo_open, const std::string& unit) {
  double v = 0;
  const bool ok = ParseDouble(text, &v) && (lo_open ? v > lo : v >= lo) && v <= hi;
  if (!ok)
    UsageError(option + ": expected a number " + (lo_open ? "above " : "from ") +
               cablefilm::FormatNumber(lo) + " to " + cablefilm::FormatNumber(hi) + unit +
               ", got " + Shown(text));
  return v;
}

// WxH: even whole numbers within the stated pixel limits (checked before anything is drawn).
void ParseSize(const char* text, int* width, int* height) {
  const std::string s = text;
  const std::size_t x = s.find('x');
  auto whole = [](const std::string& part, long max, int* out) {
    if (part.empty() || part.size() > 6 ||
        part.find_first_not_of("0123456789") != std::string::npos)
      return false;
    const long v = std::stol(part);
    if (v < cablefilm::kMinFilmSize || v > max || v % 2) return false;
    *out = static_cast<int>(v);
    return true;
  };
  if (x == std::string::npos || !whole(s.substr(0, x), cablefilm::kMaxFilmWidth, width) ||
      !whole(s.substr(x + 1), cablefilm::kMaxFilmHeight, height))
    UsageError("--size: expected WxH with even numbers of pixels, " +
               std::to_string(cablefilm::kMinFilmSize) + "x" +
               std::to_string(cablefilm::kMinFilmSize) + " to " +
               std::to_string(cablefilm::kMaxFilmWidth) + "x" +
               std::to_string(cablefilm::kMaxFilmHeight) + ", got " + Shown(text));
}

std::string ParseColormap(const char* text) {
  std::string list;
  for (const std::string& name : cablefilm::ColormapNames()) {
    if (name == text) return name;
    list += (list.empty() ? "" : ", ") + name;
  }
  UsageError("--colormap: expected one of " + list + ", got " + Shown(text));
}

// A folder, checked now rather than after the simulation, when the film needs it.
std::string ShaderDir(const char* text) {
  std::error_code ec;
  if (!std::filesystem::is_directory(text, ec))
    UsageError("--shaders: expected a folder of GLSL shaders, got " + Shown(text));
  return text;
}

// An error of a command: a scene's file named first (the loader's already start with it).
int ReportError(const std::string& scene, const cablefilm::Error& e) {
  std::fflush(stdout);
  std::string message = e.what();
  const std::string prefix = cablefilm::EscapeText(scene) + ":";
  if (message.compare(0, prefix.size(), prefix) != 0) message = prefix + " " + message;
  std::fprintf(stderr, "cablefilm: error: %s\n", message.c_str());
  return 1;
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
        UsageError("--port: expected a port number 0..65535, got " + Shown(v));
      options.port = static_cast<int>(port);
    } else if (arg == "--bind") {
      options.bind = value();
    } else if (arg == "--size") {
      ParseSize(value(), &options.width, &options.height);
    } else if (arg == "--fps") {
      options.fps = ParseNumber(arg, value(), 1, 120, false, " frames per second");
    } else if (arg == "--speed") {
      options.speed = ParseNumber(arg, value(), 0.1, 10, false, "");
    } else if (arg == "--colormap") {
      options.colormap = ParseColormap(value());
    } else if (arg == "--out") {
      options.out_dir = value();
    } else if (arg == "--shaders") {
      options.shader_dir = ShaderDir(value());
    } else if (!arg.empty() && arg[0] == '-') {
      UsageError("unknown option " + Shown(arg) + " for live");
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
    return ReportError(scene, e);
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
  if (!runs && command != "check") UsageError("unknown command " + Shown(command));
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
      ParseSize(value(), &options.width, &options.height);
    } else if (runs && arg == "--fps") {
      options.fps = ParseNumber(arg, value(), cablefilm::kMinFps, cablefilm::kMaxFps, false,
                                " frames per second");
    } else if (runs && arg == "--speed") {
      // The film's frame count (1 to kMaxFilmFrames) depends on the scene: checked with it.
      options.speed = ParseNumber(arg, value(), 0, cablefilm::kMaxTime, true,
                                  " simulated seconds per second of film");
    } else if (runs && arg == "--colormap") {
      options.colormap = ParseColormap(value());
    } else if (runs && arg == "--tension-range") {
      const std::string v = value();
      const std::size_t comma = v.find(',');
      double lo = 0, hi = 0;
      if (comma == std::string::npos || !ParseDouble(v.substr(0, comma), &lo) ||
          !ParseDouble(v.substr(comma + 1), &hi) || !(lo >= 0) || !(hi > lo) ||
          !(hi <= cablefilm::kMaxTension))
        UsageError("--tension-range: expected MIN,MAX in N with " +
                   cablefilm::FormatNumber(cablefilm::kMaxTension) + " >= MAX > MIN >= 0, got " +
                   Shown(v));
      options.tension_min = lo;
      options.tension_max = hi;
    } else if (runs && arg == "--shaders") {
      options.shader_dir = ShaderDir(value());
    } else if (!arg.empty() && arg[0] == '-') {
      UsageError("unknown option " + Shown(arg) + " for " + command);
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
  } catch (const cablefilm::CancelledError& e) {  // a signal seen inside the work
    std::fflush(stdout);
    std::fprintf(stderr, "cablefilm: %s\n", e.what());
    return cablefilm::InterruptedExitStatus();
  } catch (const cablefilm::Error& e) {
    return ReportError(scene, e);
  }
}
