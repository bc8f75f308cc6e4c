#include "live/live_options.h"

#include <cerrno>
#include <cstdlib>

#include "live/bind_address.h"
#include "scene/option_values.h"

namespace cablefilm {
namespace {

CLI::Option* Value(CLI::App* app, const std::string& name, const std::string& type,
                   const std::string& help, std::function<void(const std::string&)> apply) {
  return app->add_option_function<std::string>(name, std::move(apply), help)->type_name(type);
}

int ParsePort(const std::string& v) {
  char* end = nullptr;
  errno = 0;
  const long port = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || end == v.c_str() || *end != '\0' || errno == ERANGE || port < 0 ||
      port > 65535)
    Bad("--port: expected a port number 0..65535, got " + Shown(v));
  return static_cast<int>(port);
}

}  // namespace

CLI::App* DeclareLiveCommand(CLI::App& program, std::string* scene, LiveCommandOptions* o) {
  CLI::App* cmd =
      program.add_subcommand("live", "simulate in real time, watch and steer it in a browser");
  cmd->add_option("SCENE", *scene, "the scene file (TOML, or a MoorDyn v2 input file)")
      ->type_name("")
      ->required();
  cmd->allow_extras();  // unknown options and a second scene: reported by main, by name
  Value(cmd, "--port", "N", "port to serve on (default 8080; 0: any free port)",
        [o](const std::string& v) { o->port = ParsePort(v); });
  Value(cmd, "--bind", "ADDR",
        "IPv4 address to listen on (default 127.0.0.1: this machine only; beyond loopback the "
        "printed address carries an access token)",
        [o](const std::string& v) {
          if (const std::string why = BindAddressProblem(v); !why.empty()) Bad(why);
          o->bind = v;
        });
  Value(cmd, "--size", "WxH", "frame size in pixels, even, 16x16 to 7680x4320 (default 1280x720)",
        [o](const std::string& v) { ParseSize("--size", v, &o->width, &o->height); });
  Value(cmd, "--fps", "N", "frames per second, 1 to 120 (default 30)",
        [o](const std::string& v) {
          o->fps = ParseNumber("--fps", v, 1, 120, false, " frames per second");
        });
  Value(cmd, "--speed", "X", "simulated seconds per second, 0.1 to 10 (default 1)",
        [o](const std::string& v) { o->speed = ParseNumber("--speed", v, 0.1, 10, false, ""); });
  Value(cmd, "--colormap", "NAME", "as for run (default: the scene's)",
        [o](const std::string& v) { o->colormap = ParseColormap("--colormap", v); });
  Value(cmd, "--view", "VIEW", "as for run (default: the scene's film.view)",
        [o](const std::string& v) { o->view = ParseView("--view", v); });
  Value(cmd, "--out", "DIR", "where recordings go (default output/<scene name>)",
        [o](const std::string& v) { o->out_dir = v; });
  Value(cmd, "--shaders", "DIR", "as for run",
        [o](const std::string& v) { o->shader_dir = ParseShaderDir("--shaders", v); });
  cmd->footer(
      "Serves the live view until Ctrl-C or SIGTERM (status 0), and prints its address.\n"
      "--bind beyond 127.0.0.1 serves other machines: only with the printed address's token\n"
      "(kept by the page as a cookie); the connection is not encrypted.");
  return cmd;
}

}  // namespace cablefilm
