// cablefilm: the command line (CLI11); the work is in commands.cpp and live_command.cpp.
// Every bad option is answered on stderr with a message that names it (input text escaped)
// and exit status 2, before anything is read or simulated; --help and --version exit 0.
#include <CLI/CLI.hpp>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/body_commands.h"
#include "app/commands.h"
#include "app/sweep_command.h"
#include "core/version.h"
#ifdef CABLEFILM_LIVE
#include "live/bind_address.h"
#include "live/live_command.h"
#endif
#include "core/cancel.h"
#include "core/error.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"
#include "scene/text_escape.h"

namespace {

// A bad option or argument; the message names it and quotes what the user typed through
// Shown(), so it is printed as it is.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

[[noreturn]] void Bad(const std::string& message) { throw UsageError(message); }

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
double ParseNumber(const std::string& option, const std::string& text, double lo, double hi,
                   bool lo_open, const std::string& unit) {
  double v = 0;
  const bool ok = ParseDouble(text, &v) && (lo_open ? v > lo : v >= lo) && v <= hi;
  if (!ok)
    Bad(option + ": expected a number " + (lo_open ? "above " : "from ") +
        cablefilm::FormatNumber(lo) + " to " + cablefilm::FormatNumber(hi) + unit + ", got " +
        Shown(text));
  return v;
}

// WxH: even whole numbers within the stated pixel limits (checked before anything is drawn).
void ParseSize(const std::string& s, int* width, int* height) {
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
    Bad("--size: expected WxH with even numbers of pixels, " +
        std::to_string(cablefilm::kMinFilmSize) + "x" + std::to_string(cablefilm::kMinFilmSize) +
        " to " + std::to_string(cablefilm::kMaxFilmWidth) + "x" +
        std::to_string(cablefilm::kMaxFilmHeight) + ", got " + Shown(s));
}

std::string ParseColormap(const std::string& text) {
  std::string list;
  for (const std::string& name : cablefilm::ColormapNames()) {
    if (name == text) return name;
    list += (list.empty() ? "" : ", ") + name;
  }
  Bad("--colormap: expected one of " + list + ", got " + Shown(text));
}

std::string ParseView(const std::string& text) {
  if (cablefilm::ViewProblem(text).empty()) return text;
  Bad("--view: " + cablefilm::ViewProblem(text));
}

// A folder, checked now rather than after the simulation, when the film needs it.
std::string ShaderDir(const std::string& text) {
  std::error_code ec;
  if (!std::filesystem::is_directory(text, ec))
    Bad("--shaders: expected a folder of GLSL shaders, got " + Shown(text));
  return text;
}

void ParseTensionRange(const std::string& v, double* lo, double* hi) {
  const std::size_t comma = v.find(',');
  if (comma == std::string::npos || !ParseDouble(v.substr(0, comma), lo) ||
      !ParseDouble(v.substr(comma + 1), hi) || !(*lo >= 0) || !(*hi > *lo) ||
      !(*hi <= cablefilm::kMaxTension))
    Bad("--tension-range: expected MIN,MAX in N with " +
        cablefilm::FormatNumber(cablefilm::kMaxTension) + " >= MAX > MIN >= 0, got " + Shown(v));
}

#ifdef CABLEFILM_LIVE
int ParsePort(const std::string& v) {
  char* end = nullptr;
  errno = 0;
  const long port = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || end == v.c_str() || *end != '\0' || errno == ERANGE || port < 0 ||
      port > 65535)
    Bad("--port: expected a port number 0..65535, got " + Shown(v));
  return static_cast<int>(port);
}
#endif

// An option taking one value, checked and converted by `apply` (which throws UsageError).
CLI::Option* Value(CLI::App* app, const std::string& name, const std::string& type,
                   const std::string& help, std::function<void(const std::string&)> apply) {
  return app->add_option_function<std::string>(name, std::move(apply), help)->type_name(type);
}

// A flag whose effect depends on its place among the others (the last one given wins).
CLI::Option* Flag(CLI::App* app, const std::string& name, const std::string& help,
                  std::function<void()> apply) {
  return app->add_flag_callback(name, std::move(apply), help)->trigger_on_parse();
}

// An error of a command: a scene's file named first (the loader's already start with it).
int ReportError(const std::string& scene, const cablefilm::Error& e) {
  std::fflush(stdout);
  const std::string message = cablefilm::SceneErrorMessage(scene, e.what());
  std::fprintf(stderr, "cablefilm: error: %s\n", message.c_str());
  return 1;
}

// The film options of run and compare (and sweep, for each case) into `o`.
void AddRunOptions(CLI::App* cmd, cablefilm::RunOptions* o,
                   const std::string& out_help = "output folder (default output/<scene name>)") {
  Value(cmd, "--out", "DIR", out_help, [o](const std::string& v) { o->out_dir = v; });
  Flag(cmd, "--no-film", "result files only, no rendering", [o] { o->film = 0; });
  Flag(cmd, "--film", "make the film even if the scene says film = false", [o] { o->film = 1; });
  Flag(cmd, "--frames", "also keep every frame as PNG in DIR/frames/ (and make the film)", [o] {
    o->frames = 1;
    if (o->film < 0) o->film = 1;
  });
  Value(cmd, "--size", "WxH", "film size in pixels, even, 16x16 to 7680x4320 (default 1920x1080)",
        [o](const std::string& v) { ParseSize(v, &o->width, &o->height); });
  Value(cmd, "--fps", "N", "film frames per second, 1 to 240 (default 30)",
        [o](const std::string& v) {
          o->fps = ParseNumber("--fps", v, cablefilm::kMinFps, cablefilm::kMaxFps, false,
                               " frames per second");
        });
  // The film's frame count (1 to kMaxFilmFrames) depends on the scene: checked with it.
  Value(cmd, "--speed", "X", "simulated seconds per second of film (default 1: real time)",
        [o](const std::string& v) {
          o->speed = ParseNumber("--speed", v, 0, cablefilm::kMaxTime, true,
                                 " simulated seconds per second of film");
        });
  Value(cmd, "--colormap", "NAME", "viridis (default), cividis, magma, inferno, plasma",
        [o](const std::string& v) { o->colormap = ParseColormap(v); });
  Value(cmd, "--tension-range", "MIN,MAX", "colour and plot range in N (default: the run's)",
        [o](const std::string& v) { ParseTensionRange(v, &o->tension_min, &o->tension_max); });
  Value(cmd, "--view", "VIEW",
        "auto (default: 3D unless the scene stays in the plane z = 0), 2d, 3d",
        [o](const std::string& v) { o->view = ParseView(v); });
  Value(cmd, "--shaders", "DIR", "GLSL shader folder (default: $CABLEFILM_SHADERS, else built in)",
        [o](const std::string& v) { o->shader_dir = ShaderDir(v); });
}

// sweep's own options; the run options come from AddRunOptions.
void AddSweepOptions(CLI::App* cmd, cablefilm::SweepOptions* o) {
  Value(cmd, "--set", "KEY=V1,V2,...",
        "a scene key (e.g. environment.current, ends.end.period, material[0].youngs_modulus) "
        "and its values (TOML: 0.5, \"explicit\" or explicit, [1, 2]); repeat for more keys: "
        "the cases are their cross product",
        [o](const std::string& v) {
          try {
            o->sets.push_back(cablefilm::ParseSetOption(v));
          } catch (const cablefilm::Error& e) {
            Bad(std::string("--set: ") + e.what());
          }
        })
      ->trigger_on_parse();
  Value(cmd, "--cases", "CASES.csv",
        "a CSV of cases: a header naming the keys, a row of values per case (times the --set "
        "values)",
        [o](const std::string& v) { o->cases_csv = v; });
  Value(cmd, "--jobs", "N", "cases at a time (default: one per core)", [o](const std::string& v) {
    const double jobs = ParseNumber("--jobs", v, 1, 1024, false, " cases at a time");
    if (jobs != std::floor(jobs))
      Bad("--jobs: expected a whole number from 1 to 1024, got " + Shown(v));
    o->jobs = static_cast<int>(jobs);
  });
  Flag(cmd, "--prepare", "write the case folders (scene.toml) and sweep.csv, run nothing",
       [o] { o->prepare = true; });
  Flag(cmd, "--summary-only",
       "run the cases in this process and write sweep.csv alone: no case folders, no per-case "
       "files (the fastest for many short cases)",
       [o] { o->summary_only = true; });
  AddRunOptions(cmd, &o->run, "sweep folder (default output/<scene name>_sweep)");
}

#ifdef CABLEFILM_LIVE
void AddLiveOptions(CLI::App* cmd, cablefilm::LiveCommandOptions* o) {
  Value(cmd, "--port", "N", "port to serve on (default 8080; 0: any free port)",
        [o](const std::string& v) { o->port = ParsePort(v); });
  Value(cmd, "--bind", "ADDR",
        "IPv4 address to listen on (default 127.0.0.1: this machine only; beyond loopback the "
        "printed address carries an access token)",
        [o](const std::string& v) {
          if (const std::string why = cablefilm::BindAddressProblem(v); !why.empty()) Bad(why);
          o->bind = v;
        });
  Value(cmd, "--size", "WxH", "frame size in pixels, even, 16x16 to 7680x4320 (default 1280x720)",
        [o](const std::string& v) { ParseSize(v, &o->width, &o->height); });
  Value(cmd, "--fps", "N", "frames per second, 1 to 120 (default 30)",
        [o](const std::string& v) {
          o->fps = ParseNumber("--fps", v, 1, 120, false, " frames per second");
        });
  Value(cmd, "--speed", "X", "simulated seconds per second, 0.1 to 10 (default 1)",
        [o](const std::string& v) { o->speed = ParseNumber("--speed", v, 0.1, 10, false, ""); });
  Value(cmd, "--colormap", "NAME", "as for run (default: the scene's)",
        [o](const std::string& v) { o->colormap = ParseColormap(v); });
  Value(cmd, "--view", "VIEW", "as for run (default: the scene's film.view)",
        [o](const std::string& v) { o->view = ParseView(v); });
  Value(cmd, "--out", "DIR", "where recordings go (default output/<scene name>)",
        [o](const std::string& v) { o->out_dir = v; });
  Value(cmd, "--shaders", "DIR", "as for run",
        [o](const std::string& v) { o->shader_dir = ShaderDir(v); });
}
#endif

std::string VersionText() {
  std::string text = std::string("cablefilm ") + cablefilm::kVersion;
  if (*cablefilm::kGitDescribe) text += std::string(" (git ") + cablefilm::kGitDescribe + ")";
  return text;
}

// A usage error: the message, then where to read the options; status 2.
int UsageFailure(const std::string& message, const std::string& command) {
  std::fflush(stdout);
  std::fprintf(stderr, "cablefilm: %s\nrun 'cablefilm%s --help' for the options\n",
               message.c_str(), command.empty() ? "" : (" " + command).c_str());
  return 2;
}

// CLI11's own message, escaped (it may quote what was typed); a missing value said plainly.
std::string ParserMessage(const CLI::ParseError& e) {
  std::string message = e.what();
  static const std::regex missing("^(-[^:]*): 1 required (.*) missing$");
  std::smatch m;
  if (std::regex_match(message, m, missing))
    message = m[1].str() + ": missing value (expected " + m[2].str() + ")";
  return cablefilm::EscapeText(message);
}

// What stood before the command other than --help and --version, said; "" when nothing did.
std::string BeforeTheCommand(const CLI::App& app) {
  const std::vector<std::string> extras = app.remaining();
  if (extras.empty()) return "";
  const std::string& what = extras.front();
  if (!what.empty() && what[0] == '-')
    return "unknown option " + Shown(what) + " (options go after the command)";
  return "unknown command " + Shown(what);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("cablefilm " + std::string(cablefilm::kVersion) +
                   ": a lumped-mass cable in a fluid (Polachek et al. 1963), simulated and "
                   "filmed with its tension",
               "cablefilm");
  app.set_version_flag("--version", VersionText(), "print the version and exit");
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.allow_extras();
  app.get_formatter()->column_width(27);

  std::string scene;
  auto add_command = [&](const std::string& name, const std::string& help,
                         const std::string& what = "the scene file (TOML, or a MoorDyn v2 input "
                                                   "file)") {
    CLI::App* cmd = app.add_subcommand(name, help);
    cmd->add_option("SCENE", scene, what)->type_name("")->required();
    cmd->allow_extras();  // unknown options and a second scene: reported below, by name
    return cmd;
  };
  cablefilm::RunOptions run_options;
  CLI::App* run = add_command("run", "simulate, write the results and the film");
  AddRunOptions(run, &run_options);
  CLI::App* compare = add_command("compare", "elastic and inextensible runs: the paper's Figure 1");
  AddRunOptions(compare, &run_options);
  CLI::App* check = add_command("check", "validate a scene, print stations, mass, time step");
  std::string convert_out;
  CLI::App* convert =
      add_command("convert", "write a MoorDyn v2 input file as the equivalent scene (TOML)",
                  "the MoorDyn v2 input file");
  convert->add_option("-o,--out", convert_out, "the scene file to write (default: standard output)")
      ->type_name("FILE");
  convert->footer(
      "'run' and 'check' read a MoorDyn file as it is, through this scene; MoorDyn's\n"
      "z-up axes become cablefilm's y-up ones: (x, y, z) -> (x, z, -y). See docs/moordyn.md.");
  std::string stiffness_body;
  CLI::App* stiffness = add_command(
      "stiffness", "print the moorings' 6x6 stiffness matrix of a body at equilibrium");
  stiffness->add_option("--body", stiffness_body, "the body (default: the scene's only one)")
      ->type_name("NAME");
  cablefilm::OffsetOptions offset_options;
  CLI::App* offset =
      add_command("offset", "the offset-restoring curve of a body along a heading (CSV)");
  offset->add_option("--body", offset_options.body, "the body (default: the scene's only one)")
      ->type_name("NAME");
  Value(offset, "--heading", "DEG", "direction of the offset from +x towards +z (default 0)",
        [&](const std::string& v) {
          offset_options.heading = ParseNumber("--heading", v, -360, 360, false, " degrees");
        });
  Value(offset, "--max", "M",
        "largest offset in m (default: a twentieth of the shortest line on the body)",
        [&](const std::string& v) {
          offset_options.max_offset =
              ParseNumber("--max", v, 0, cablefilm::kMaxLength, false, " m");
        });
  Value(offset, "--points", "N", "offsets from 0 to --max, 1 to 10000 (default 11)",
        [&](const std::string& v) {
          offset_options.points =
              static_cast<int>(ParseNumber("--points", v, 1, 10000, false, " points"));
          if (offset_options.points != std::stod(v)) Bad("--points: expected a whole number");
        });
  offset->add_option("-o,--out", offset_options.out, "the CSV file (default: standard output)")
      ->type_name("FILE");
  offset->footer(
      "Columns: offset [m], restoring (the moorings' horizontal force against the heading)\n"
      "[N], fx, fy, fz [N], mx, my, mz [N m] (the moorings' load on the body), then the load\n"
      "at each line's end on the body, tension_<line> [N]. The body moves from its\n"
      "equilibrium; its other degrees of freedom are held. See docs/systems.md.");
  cablefilm::SweepOptions sweep_options;
  CLI::App* sweep = add_command("sweep", "run a scene over the cross product of values of its keys");
  AddSweepOptions(sweep, &sweep_options);
#ifdef CABLEFILM_LIVE
  cablefilm::LiveCommandOptions live_options;
  CLI::App* live =
      add_command("live", "simulate in real time, watch and steer it in a browser");
  AddLiveOptions(live, &live_options);
  live->footer(
      "Serves the live view until Ctrl-C or SIGTERM (status 0), and prints its address.\n"
      "--bind beyond 127.0.0.1 serves other machines: only with the printed address's token\n"
      "(kept by the page as a cookie); the connection is not encrypted.");
#endif
  const std::string outputs =
      "The results go to the output folder: equilibrium.csv, timeseries.csv, max_tension.png\n"
      "and film.mp4 (with the film: duration x fps / speed must be 1 to 1e6 frames).";
  run->footer(outputs);
  compare->footer(outputs + "\nAlso equilibrium_inextensible.csv and timeseries_inextensible.csv.");
  check->footer("Refuses whatever run would, before anything is simulated.");
  sweep->footer(
      "Each case is 'cablefilm run' in a process of its own (the film off unless --film), in\n"
      "DIR/case_NNN/ with its scene.toml; every case's scene is checked as 'check' would before\n"
      "any runs. The summary: DIR/sweep.csv (case, folder, the values, status, message, peak\n"
      "tension, its time and link, minimum tension, its time and link, snaps, peak_converged).\n"
      "Ctrl-C stops the running cases and leaves the finished ones.");
  app.footer("'cablefilm COMMAND --help' shows the options of a command; 'cablefilm --version'\n"
             "the version.");

  if (argc < 2) return UsageFailure("missing command", "");
  const std::string first = argv[1];
  if (first == "help") {  // `cablefilm help [COMMAND]`
    const CLI::App* about = &app;
    if (argc > 2) {
      try {
        about = app.get_subcommand(argv[2]);
      } catch (const CLI::OptionNotFound&) {
        return UsageFailure("unknown command " + Shown(argv[2]), "");
      }
    }
    std::printf("%s", about == &app ? app.help().c_str() : about->help("cablefilm").c_str());
    return 0;
  }
#ifndef CABLEFILM_LIVE
  if (first == "live") {
    std::fprintf(stderr,
                 "cablefilm: this build has no live view (configured with CABLEFILM_RENDER=OFF)\n");
    return 2;
  }
#endif

  CLI::App* command = nullptr;
  try {
    app.parse(argc, argv);
    if (const std::string bad = BeforeTheCommand(app); !bad.empty())
      return UsageFailure(bad, "");
    for (CLI::App* c : app.get_subcommands()) command = c;
    if (!command) return UsageFailure("missing command", "");
    for (const std::string& extra : command->remaining())
      Bad(!extra.empty() && extra[0] == '-'
              ? "unknown option " + Shown(extra) + " for " + command->get_name()
              : "more than one scene given");
    if (command == sweep && sweep_options.sets.empty() && sweep_options.cases_csv.empty())
      Bad("nothing to sweep: give --set KEY=V1,V2,... or --cases CASES.csv");
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (const std::string bad = BeforeTheCommand(app); !bad.empty())
      return UsageFailure(bad, "");
    for (CLI::App* c : app.get_subcommands()) command = c;
    return UsageFailure(ParserMessage(e), command ? command->get_name() : "");
  } catch (const UsageError& e) {
    if (!command)
      for (CLI::App* c : app.get_subcommands()) command = c;
    return UsageFailure(e.what(), command ? command->get_name() : "");
  }

  try {
#ifdef CABLEFILM_LIVE
    if (command == live) return cablefilm::LiveCommand(scene, live_options);
#endif
    if (command == run) return cablefilm::RunCommand(scene, run_options);
    if (command == compare) return cablefilm::CompareCommand(scene, run_options);
    if (command == check) return cablefilm::CheckCommand(scene);
    if (command == convert) return cablefilm::ConvertCommand(scene, convert_out);
    if (command == stiffness) return cablefilm::StiffnessCommand(scene, stiffness_body);
    if (command == offset) return cablefilm::OffsetCommand(scene, offset_options);
    if (command == sweep) return cablefilm::SweepCommand(scene, sweep_options);
    return UsageFailure("unknown command " + Shown(command->get_name()), "");
  } catch (const cablefilm::CancelledError& e) {  // a signal seen inside the work
    std::fflush(stdout);
    std::fprintf(stderr, "cablefilm: %s\n", e.what());
    return cablefilm::InterruptedExitStatus();
  } catch (const cablefilm::Error& e) {
    return ReportError(scene, e);
  }
}
