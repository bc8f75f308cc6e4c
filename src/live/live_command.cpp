#include "live/live_command.h"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <memory>
#include <thread>

#include "live/http_server.h"
#include "live/live_session.h"
#include "core/cancel.h"
#include "core/error.h"
#include "scene/scene_loader.h"

namespace cablefilm {
namespace {

std::atomic<int> g_live_signal{0};
extern "C" void OnLiveSignal(int sig) {
  if (g_live_signal != 0) std::_Exit(128 + sig);  // a second Ctrl-C: at once
  g_live_signal = sig;
}

}  // namespace

int LiveCommand(const std::string& scene_path, const LiveCommandOptions& o) {
  // A bad address is refused before the scene is loaded and simulated to equilibrium.
  if (const std::string why = BindAddressProblem(o.bind); !why.empty()) throw Error("live: " + why);
  const bool loopback = IsLoopbackAddress(o.bind);
  const SceneDef scene = LoadScene(scene_path);
  LiveOptions lo;
  lo.width = o.width;
  lo.height = o.height;
  lo.fps = o.fps;
  lo.speed = o.speed;
  lo.colormap = o.colormap;
  lo.view = o.view;
  lo.out_dir = o.out_dir.empty() ? "output/" + scene.name : o.out_dir;
  lo.shader_dir = o.shader_dir;
  std::signal(SIGINT, OnLiveSignal);
  std::signal(SIGTERM, OnLiveSignal);
  std::signal(SIGPIPE, SIG_IGN);  // a viewer that hangs up is an error of its write, not a kill
  // Ctrl-C while the statics run (a system's can take seconds) stops them at once.
  lo.stop = &g_live_signal;
  std::unique_ptr<LiveSession> started;
  try {
    started = std::make_unique<LiveSession>(scene, lo);
  } catch (const CancelledError& e) {
    std::fprintf(stderr, "cablefilm: %s\n", e.what());
    return 128 + g_live_signal.load();
  }
  LiveSession& session = *started;
  ServerOptions so;
  so.bind = o.bind;
  so.port = o.port;
  // Beyond loopback other machines can connect: each request needs the printed URL's token.
  if (!loopback) so.token = MakeToken();
  LiveServer server(session, so);
  if (!loopback)
    std::fprintf(stderr,
                 "cablefilm: warning: serving on %s: anyone with the printed address (its "
                 "token) can watch and steer the simulation; the connection is not encrypted\n",
                 o.bind.c_str());
  std::printf("live view at %s\n", server.url().c_str());
  std::fflush(stdout);
  while (g_live_signal == 0 && !session.stopped())
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::fprintf(stderr, "cablefilm: stopping the live view\n");
  session.Stop();  // first: viewers' streams end when the session says it stopped
  return 0;        // the server closes as it goes out of scope
}

}  // namespace cablefilm
