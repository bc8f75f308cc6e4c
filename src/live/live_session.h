#pragma once
// A live view of a scene: the simulation paced to the wall clock on one thread, the picture
// drawn (MakeFrame of a following History, OSMesa) and encoded once as JPEG on another,
// whatever the number of viewers, but only while someone watches (a stream, a recording) or
// asks for a picture (FreshFrame), and a thread-safe face for the network: the newest frame,
// the state as JSON, the controls. Memory stays bounded however long it runs: viewers share the
// newest frame only, the plots keep a rolling window, and the time series goes to a temporary
// file.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "encode/image.h"
#include "live/control.h"
#include "live/live_recorder.h"
#include "live/live_simulation.h"
#include "live/row_log.h"
#include "scene/scene_def.h"
#include "view/camera.h"
#include "view/history.h"
#include "view/plot_layout.h"
#include "view/scene_view.h"
#include "view/snapshot.h"

namespace cablefilm {

struct LiveOptions {
  int width = 1280, height = 720;  // of the frames [px], even
  double fps = 30;                 // frames per wall-clock second
  double speed = 1;                // simulated seconds per wall-clock second
  std::string colormap;            // empty: the scene's
  std::string view;                // "auto", "2d", "3d" (scene/film_view.h); empty: the scene's
  std::string out_dir;             // where recordings go (created when the first one starts)
  std::string shader_dir;          // empty: the built-in shaders
  int jpeg_quality = 85;
  // Polled by the statics while the session starts (a system's can take seconds): raised,
  // the constructor throws CancelledError. Null: not polled.
  const CancelFlag* stop = nullptr;
};

// One frame as sent: a 24-byte header (frame number uint64, t float64, control sequence number
// uint64, all little-endian) followed by the JPEG. The WebSocket sends `message` as it is.
struct LiveFrame {
  static constexpr std::size_t kHeaderBytes = 24;
  std::uint64_t number = 0;
  double t = 0;             // simulated time [s]
  std::uint64_t seq = 0;    // the last control applied before this frame was drawn
  std::string message;      // header + JPEG
  const char* jpeg() const { return message.data() + kHeaderBytes; }
  std::size_t jpeg_size() const { return message.size() - kHeaderBytes; }
};

class LiveSession {
 public:
  // Builds the simulation (equilibrium) and starts both threads; returns once the renderer is
  // ready and the first frame is drawn. Throws Error (scene, renderer, shaders).
  LiveSession(const SceneDef& scene, const LiveOptions& options);
  ~LiveSession();
  LiveSession(const LiveSession&) = delete;
  LiveSession& operator=(const LiveSession&) = delete;

  // Stops both threads, closing a recording so that it plays. Idempotent.
  void Stop();

  struct Reply {
    int status = 200;  // 200, or 400 with a message naming the field
    std::string json;  // the new state, or {"error": "..."}
  };
  Reply Control(const std::string& body);
  std::string StateJson() const;
  // Changes with what a viewer acts on (controls applied, pause, errors, recordings), not
  // with every frame's numbers.
  std::uint64_t state_version() const { return state_version_; }

  std::shared_ptr<const LiveFrame> NewestFrame() const;
  // The first frame numbered above `after`, waiting up to `timeout`; null on timeout or stop.
  std::shared_ptr<const LiveFrame> WaitFrame(std::uint64_t after,
                                             std::chrono::milliseconds timeout) const;
  // A frame of the state now: with nobody watching, one drawn on demand (waiting up to
  // `timeout`, else the newest there is).
  std::shared_ptr<const LiveFrame> FreshFrame(std::chrono::milliseconds timeout);
  std::string SnapshotPng();  // a fresh frame as PNG
  // The time series so far (timeseries.csv's columns) in pieces.
  void ReadTimeseries(const std::function<bool(const char*, std::size_t)>& sink);
  // The path of a finished recording of this session by its file name; empty if none such.
  std::string RecordingPath(const std::string& name) const;

  // A stream opened (+1) or closed (-1): frames are drawn while there is one.
  void AddViewer(int delta);
  int viewers() const { return viewers_; }
  // Frames drawn so far (each one encoded once as JPEG).
  std::uint64_t frames_drawn() const;
  bool stopped() const { return stop_; }
  const std::string& scene_name() const { return scene_.name; }
  int width() const { return options_.width; }
  int height() const { return options_.height; }

 private:
  void SimulationLoop();

  // The render thread: it starts the renderer, waits for work (a viewer, a control, a still
  // asked for), starts or ends a recording, draws the frame, packs it for the viewers and
  // publishes it.
  struct Painter;
  struct RenderWork;
  void RenderLoop();
  bool StartRenderer(Painter* painter);  // false: it could not (render_error_ says why)
  bool WaitForWork(const Painter& painter, RenderWork* work);  // false: the session stops
  bool UpdateRecording(LiveRecorder* recorder, const RenderWork& work);  // false: no film
  void FinishRecording(LiveRecorder* recorder);
  void DrawFrame(Painter* painter, LiveRecorder* recorder, const RenderWork& work);
  std::shared_ptr<LiveFrame> PackFrame(Painter* painter, double t, std::uint64_t seq) const;
  void PublishFrame(std::shared_ptr<LiveFrame> frame, const Painter& painter,
                    const RenderWork& work, const PixelRect& space_view);
  void PublishStillLocked(const Image& canvas);  // if a still was asked for (lock held)
  // Applies what the controls asked of the simulation; called on its thread, without the lock.
  void ApplyPending();
  // The simulation's state now into the history (and the time series), after a step or a
  // restart (lock held).
  void RecordLocked();
  void PublishLocked();  // the numbers, after a step (lock held)
  std::string StateJsonLocked() const;
  std::string StatusLocked() const;

  const SceneDef scene_;
  const LiveOptions options_;
  std::string start_kind_, end_kind_;  // "fixed", "moving" or "free", as the film names them
  ControlLimits limits_;
  // Owned by the simulation thread once it runs.
  const std::unique_ptr<LiveSimulation> sim_;
  const SceneView view_;  // what the picture shows of the scene: read by both threads

  mutable std::mutex mu_;
  mutable std::condition_variable sim_cv_, render_cv_, frame_cv_;
  std::atomic<bool> stop_{false};
  std::atomic<int> viewers_{0};
  std::atomic<std::uint64_t> state_version_{0};

  // Controls (lock held).
  bool paused_ = false;
  double speed_;
  std::string colormap_;
  OrbitCamera camera_;          // the 3D view's (a scene drawn in space)
  SeaTargets targets_;          // what the sea is ramping to (as answered to the controls)
  std::uint64_t seq_ = 0;       // controls accepted
  std::uint64_t seq_applied_ = 0;  // controls the simulation has taken
  struct Pending {
    std::uint64_t seq = 0;
    bool restart = false, step = false;
    std::optional<double> amplitude_scale, period, current, current_heading, wave_height,
        wave_period, wave_heading, offset_x, offset_z, force_x, force_z;
  };
  std::vector<Pending> pending_;
  std::vector<Pending> deferred_;  // refused while too many ramps ran (simulation thread only)
  int steps_requested_ = 0;
  std::string error_;           // a blow-up (paused until a restart)

  // What the simulation published (lock held).
  History history_;
  Snapshot state_;  // the state now as RecordLocked hands it to the history (storage reused)
  RowLog rows_;
  std::uint64_t input_version_ = 0, view_version_ = 0;
  double t_ = 0, current_now_ = 0, current_heading_now_ = 0, wave_heading_now_ = 0;
  double tension_start_ = 0, tension_end_ = 0, tension_max_ = 0;
  int link_max_ = 0;
  struct LineNumbers {  // a line now [N], its most loaded link
    double start = 0, end = 0, max = 0;
    int link_max = 0;
  };
  std::vector<LineNumbers> lines_now_;
  double offset_x_now_ = 0, offset_z_now_ = 0;  // the vessel's offset acting now [m]
  double force_x_now_ = 0, force_z_now_ = 0;    // the free bodies' extra force now [N]
  std::deque<std::pair<double, double>> progress_;  // (wall [s], simulated [s]) for real time

  // Frames (lock held).
  std::shared_ptr<const LiveFrame> frame_;
  std::shared_ptr<const Image> image_;  // the still last asked for (SnapshotPng)
  std::uint64_t still_wanted_ = 0, still_done_ = 0;  // stills asked for, published
  std::deque<double> frame_times_;  // wall [s] of the frames of the last second
  std::string render_error_;
  PixelRect space_view_;        // where the last frame drew its 3D view [px] (none: empty)
  std::uint64_t frame_input_ = 0, frame_view_ = 0;  // the versions frame_ was drawn from
  std::uint64_t fresh_wanted_ = 0, fresh_done_ = 0;  // frames asked by FreshFrame, drawn

  // Recording (lock held).
  bool record_wanted_ = false, recording_ = false;
  // Simulation steps taken: each is speed/fps of simulated time and one frame of a film. A film
  // ends at the step (and time) at which it was asked to stop, whatever the render thread drew.
  std::uint64_t steps_ = 0, record_end_step_ = 0;
  double record_end_t_ = 0;
  std::vector<LiveRecorder::Film> recordings_;
  std::string record_error_;

  std::chrono::steady_clock::time_point start_;
  std::thread sim_thread_, render_thread_;
};

}  // namespace cablefilm
