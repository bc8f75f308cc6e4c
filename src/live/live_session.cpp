#include "live/live_session.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <future>

#include "core/line_data.h"
#include "core/error.h"
#include "live/live_recorder.h"
#include "encode/png_writer.h"
#include "encode/tiled_jpeg.h"
#include "view/colormap.h"
#include "view/frame_builder.h"
#include "view/renderer.h"
#include "scene/film_view.h"
#include "view/scene_view_builder.h"

namespace cablefilm {
namespace {

using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;

// The live view's lines as the film would draw them (a line alone with no name, a system's
// named, its points marked), in space or in the plane as `view` says (empty: the scene's
// film.view).
SceneView MakeLiveScene(const SceneDef& scene, const LiveSimulation& sim, const std::string& view) {
  return sim.MakeView(scene, view.empty() ? scene.film.view : view);
}

ControlLimits MakeLimits(const LiveSimulation& sim) {
  ControlLimits l;
  l.has_driven_end = sim.has_driven_end();
  l.has_vessel = sim.has_vessel();
  l.offset_max = sim.offset_max();
  l.has_free_body = sim.has_free_body();
  l.force_max = sim.force_max();
  const SeaTargets& sea = sim.scene_sea();
  if (l.has_driven_end) {  // the clock of the motion between a tenth and ten times the scene's
    l.period_min = sea.period / 10;
    l.period_max = sea.period * 10;
  }
  l.current_max = std::max(3.0, 2 * std::abs(sea.current));
  l.current_history = sim.model().lines.front().env.current_history != nullptr;
  if (sim.has_waves()) {  // up to the breaking height (Miche's, as the scene's check)
    const Wave& w = sim.model().lines.front().env.wave;
    l.has_waves = true;
    l.irregular_sea = w.irregular();
    l.wave_height_max = w.breaking_height();
    // A third to three times the scene's period, within 1 s to 60 s (a shorter period lowers
    // the breaking height: a higher wave is held at it, live_simulation.h).
    l.wave_period_min = std::clamp(w.spec.period / 3, 1.0, w.spec.period);
    l.wave_period_max = std::clamp(w.spec.period * 3, w.spec.period, 60.0);
  }
  l.colormaps = Colormap::Names();
  return l;
}

std::string Fixed(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

double Seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// A number JSON can carry: the state never says NaN.
double Finite(double v) { return std::isfinite(v) ? v : 0; }

// An end as the film's legend names it.
const char* EndKindName(const EndMotion& m) {
  return m.moves() ? "moving" : m.kind() == EndKind::kFree ? "free" : "fixed";
}

}  // namespace

LiveSession::LiveSession(const SceneDef& scene, const LiveOptions& options)
    : scene_(scene),
      options_(options),
      sim_(std::make_unique<LiveSimulation>(scene, options.stop)),
      view_(MakeLiveScene(scene, *sim_, options.view)),
      speed_(options.speed),
      colormap_(options.colormap.empty() ? scene.film.colormap : options.colormap),
      history_(view_, FollowingPolicy{scene.simulation.duration, sim_->wave()}),
      rows_(sim_->timeseries_header()),
      start_(Clock::now()) {
  if (options_.width < 16 || options_.height < 16 || options_.width % 2 || options_.height % 2)
    throw Error("live: frame size must be even and at least 16x16, got " +
                std::to_string(options_.width) + "x" + std::to_string(options_.height));
  if (!(options_.fps >= 1 && options_.fps <= 120))
    throw Error("live: --fps must be in [1, 120], got " + std::to_string(options_.fps));
  limits_ = MakeLimits(*sim_);
  limits_.space = view_.space;
  camera_ = DefaultCamera(view_);
  if (!(speed_ >= limits_.speed_min && speed_ <= limits_.speed_max))
    throw Error("live: --speed must be in [0.1, 10], got " + std::to_string(speed_));
  Colormap check(colormap_);  // an unknown name fails here, naming the known ones
  targets_ = sim_->scene_sea();  // as a restart sets them (the simulation is at its start)
  if (sim_->line_count() == 1) {  // several lines' ends are their points, named in the picture
    const LineModel& line = sim_->model().lines.front();
    start_kind_ = EndKindName(line.end_motion(0));
    end_kind_ = EndKindName(line.end_motion(line.line.links));
  }
  {
    std::lock_guard<std::mutex> lock(mu_);
    RecordLocked();
    PublishLocked();
  }
  // The renderer's context lives on its thread: start it and wait for the first frame (or the
  // reason there is none), so that a bad shader folder fails here, not in a viewer's face.
  render_thread_ = std::thread([this] { RenderLoop(); });
  {
    std::unique_lock<std::mutex> lock(mu_);
    frame_cv_.wait(lock, [&] { return frame_ != nullptr || !render_error_.empty(); });
    if (!frame_) {
      const std::string why = render_error_;
      stop_ = true;
      lock.unlock();
      render_cv_.notify_all();
      render_thread_.join();
      throw Error(why);
    }
  }
  sim_thread_ = std::thread([this] { SimulationLoop(); });
}

LiveSession::~LiveSession() { Stop(); }

void LiveSession::Stop() {
  {
    std::lock_guard<std::mutex> lock(mu_);
    if (stop_ && !sim_thread_.joinable() && !render_thread_.joinable()) return;
    stop_ = true;
    if (record_wanted_) {  // a film under way ends at the state of now
      record_end_step_ = steps_;
      record_end_t_ = t_;
    }
  }
  sim_cv_.notify_all();
  render_cv_.notify_all();
  frame_cv_.notify_all();
  if (sim_thread_.joinable()) sim_thread_.join();
  if (render_thread_.joinable()) render_thread_.join();
}

// ---- The simulation thread -----------------------------------------------------------------

void LiveSession::ApplyPending() {
  std::vector<Pending> todo;
  todo.swap(deferred_);
  {
    std::lock_guard<std::mutex> lock(mu_);
    todo.insert(todo.end(), pending_.begin(), pending_.end());
    pending_.clear();
  }
  if (todo.empty()) return;
  // Only the newest target of each quantity matters (a slider dragged sends many): an older
  // one still waiting is dropped rather than ramped to and away from.
  for (std::size_t i = 0; i < todo.size(); ++i)
    for (std::size_t k = i + 1; k < todo.size() && !todo[k].restart; ++k) {
      if (todo[k].amplitude_scale) todo[i].amplitude_scale.reset();
      if (todo[k].period) todo[i].period.reset();
      if (todo[k].current) todo[i].current.reset();
      if (todo[k].current_heading) todo[i].current_heading.reset();
      if (todo[k].wave_height) todo[i].wave_height.reset();
      if (todo[k].wave_period) todo[i].wave_period.reset();
      if (todo[k].wave_heading) todo[i].wave_heading.reset();
      if (todo[k].offset_x) todo[i].offset_x.reset();
      if (todo[k].offset_z) todo[i].offset_z.reset();
      if (todo[k].force_x) todo[i].force_x.reset();
      if (todo[k].force_z) todo[i].force_z.reset();
    }
  std::vector<TimeMarker> markers;
  std::uint64_t applied = 0;
  bool restarted = false;
  for (const Pending& p : todo) {
    if (p.restart) {
      sim_->Restart();
      restarted = true;
      deferred_.clear();
      markers.clear();
    }
    const double t = sim_->t();
    Pending left;  // what the ramps could not take yet
    left.seq = p.seq;
    // A change the ramps take is marked on the time plot; one they refuse waits in `left`.
    auto apply = [&](const std::optional<double>& wanted, bool (LiveSimulation::*set)(double),
                     std::optional<double>& refused, const char* label, const char* format,
                     const char* unit) {
      if (!wanted) return;
      if (((*sim_).*set)(*wanted))
        markers.push_back({t, label + Fixed(format, *wanted) + unit});
      else
        refused = wanted;
    };
    apply(p.amplitude_scale, &LiveSimulation::SetAmplitudeScale, left.amplitude_scale,
          "amplitude \u00d7", "%.2f", "");
    apply(p.period, &LiveSimulation::SetPeriod, left.period, "period ", "%.3g", " s");
    apply(p.current, &LiveSimulation::SetCurrent, left.current, "current ", "%.2f", " m/s");
    apply(p.current_heading, &LiveSimulation::SetCurrentHeading, left.current_heading,
          "current heading ", "%.4g", "\u00b0");
    apply(p.wave_height, &LiveSimulation::SetWaveHeight, left.wave_height, "wave height ", "%.2f",
          " m");
    apply(p.wave_period, &LiveSimulation::SetWavePeriod, left.wave_period, "wave period ", "%.3g",
          " s");
    apply(p.wave_heading, &LiveSimulation::SetWaveHeading, left.wave_heading, "wave heading ",
          "%.4g", "\u00b0");
    apply(p.offset_x, &LiveSimulation::SetOffsetX, left.offset_x, "offset x ", "%.3g", " m");
    apply(p.offset_z, &LiveSimulation::SetOffsetZ, left.offset_z, "offset z ", "%.3g", " m");
    apply(p.force_x, &LiveSimulation::SetForceX, left.force_x, "force x ", "%.3g", " N");
    apply(p.force_z, &LiveSimulation::SetForceZ, left.force_z, "force z ", "%.3g", " N");
    if (left.amplitude_scale || left.period || left.current || left.current_heading ||
        left.wave_height || left.wave_period || left.wave_heading || left.offset_x ||
        left.offset_z || left.force_x || left.force_z)
      deferred_.push_back(left);
    else if (deferred_.empty())  // in order: a control counts once those before it are in
      applied = std::max(applied, p.seq);
  }
  std::lock_guard<std::mutex> lock(mu_);
  if (restarted) {
    history_.Reset();
    rows_.Clear();
    error_.clear();
    progress_.clear();
    RecordLocked();
  }
  for (TimeMarker& m : markers) history_.AddMarker(m.t, std::move(m.label));
  if (applied > seq_applied_) seq_applied_ = applied;
  ++state_version_;  // viewers hear of an applied control at once
  PublishLocked();
}

void LiveSession::SimulationLoop() {
  Clock::time_point next = Clock::now();
  while (!stop_) {
    bool advance = false;
    double chunk = 0;
    {
      std::unique_lock<std::mutex> lock(mu_);
      const double frame = 1.0 / options_.fps;
      // Sleep until the next frame is due; a control wakes the loop early so that it shows at
      // once (without advancing the clock ahead of the wall).
      sim_cv_.wait_until(lock, next, [&] { return stop_ || !pending_.empty(); });
      if (stop_) break;
      const bool due = Clock::now() >= next;
      if (!pending_.empty() || (due && !deferred_.empty())) {
        lock.unlock();
        ApplyPending();
        lock.lock();
      }
      const bool can_run = error_.empty();
      if (steps_requested_ > 0 && can_run) {
        --steps_requested_;
        advance = true;
      } else if (due && !paused_ && can_run) {
        advance = true;
      }
      if (due) {
        next += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(frame));
        // Behind by more than a few frames (a slow machine, a huge scene): drop the backlog
        // rather than race to catch up; the real-time factor in the state says so.
        if (Clock::now() - next > std::chrono::milliseconds(200)) next = Clock::now();
      }
      chunk = speed_ * frame;
    }
    if (!advance) continue;
    std::string blow_up;
    try {
      sim_->Advance(chunk);
    } catch (const BlowUpError& e) {
      blow_up = e.what();
    }
    std::lock_guard<std::mutex> lock(mu_);
    if (!blow_up.empty()) {
      error_ = blow_up + "; paused: restart to go on";
      paused_ = true;
      ++state_version_;
      continue;
    }
    ++steps_;  // one more frame of a film (live_session.h)
    RecordLocked();
    progress_.emplace_back(Seconds(start_, Clock::now()), sim_->t());
    while (progress_.size() > 2 && progress_.back().first - progress_.front().first > 2.0)
      progress_.pop_front();
    PublishLocked();
  }
}

void LiveSession::RecordLocked() {
  history_.SetWave(sim_->wave());
  sim_->TakeSnapshot(&state_);
  history_.Add(state_);
  rows_.Append([this](std::FILE* f) { sim_->WriteTimeseriesRow(f); });
}

void LiveSession::PublishLocked() {
  t_ = sim_->t();
  current_now_ = sim_->current_now();
  current_heading_now_ = sim_->current_heading_now();
  wave_heading_now_ = sim_->wave_heading_now();
  lines_now_.resize(sim_->line_count());
  for (int i = 0; i < sim_->line_count(); ++i) {
    const Eigen::VectorXd& T = sim_->line_tensions(i);
    Eigen::Index link = 0;
    LineNumbers& n = lines_now_[i];
    n.start = T[0];
    n.end = T[T.size() - 1];
    n.max = T.maxCoeff(&link);
    n.link_max = static_cast<int>(link);
  }
  // A line's numbers; a system's largest tension of any line (its start and end the first's).
  const LineNumbers* top = &lines_now_.front();
  for (const LineNumbers& n : lines_now_)
    if (n.max > top->max) top = &n;
  tension_start_ = lines_now_.front().start;
  tension_end_ = lines_now_.front().end;
  tension_max_ = top->max;
  link_max_ = top->link_max;
  const Vec offset = sim_->offset_now();
  offset_x_now_ = offset.x();
  offset_z_now_ = offset.z();
  const Vec force = sim_->force_now();
  force_x_now_ = force.x();
  force_z_now_ = force.z();
  ++input_version_;  // the state's numbers change every frame: they go out at its pace, not each
  render_cv_.notify_one();
}

std::string LiveSession::StatusLocked() const {
  if (!error_.empty()) return "stopped: numerical blow-up";
  std::string s = paused_ ? "paused" : "live";
  s += " \u00b7 " + Fixed("%.2g", speed_) + "\u00d7 real time";
  return s;
}

// ---- The render thread ---------------------------------------------------------------------

// The frame as drawn, kept with what draws and packs it.
struct LiveSession::Painter {
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<TiledJpegEncoder> jpeg;
  // Each frame only what was drawn again is read back into it. A copy is published as the
  // still (/snapshot.png) only when one is asked for.
  Image canvas;
  std::uint64_t number = 0;       // frames drawn
  std::size_t message_bytes = 0;  // the last frame's: the next one's about as long
};

// What one frame draws, taken from the shared state under the lock.
struct LiveSession::RenderWork {
  explicit RenderWork(History history) : picture(std::move(history)) {}
  History picture;  // the history as a frame shows it (its storage reused)
  std::string status, colormap;
  OrbitCamera camera;
  std::uint64_t seq = 0, fresh = 0, step = 0;
  std::uint64_t input = 0, view = ~0ull;  // the versions drawn
  bool want_record = false;
};

void LiveSession::RenderLoop() {
  Painter painter;
  if (!StartRenderer(&painter)) return;
  LiveRecorder recorder;
  RenderWork work = [&] {
    std::lock_guard<std::mutex> lock(mu_);
    return RenderWork(history_);
  }();
  while (WaitForWork(painter, &work)) {
    if (!UpdateRecording(&recorder, work)) continue;
    DrawFrame(&painter, &recorder, work);
  }
  FinishRecording(&recorder);
}

bool LiveSession::StartRenderer(Painter* painter) {
  try {
    RenderOptions ro;
    ro.width = options_.width;
    ro.height = options_.height;
    ro.shader_dir = options_.shader_dir;
    ro.redraw_changes = true;  // from one frame to the next, little of the picture changes
    painter->renderer = std::make_unique<Renderer>(ro);
    painter->jpeg = std::make_unique<TiledJpegEncoder>(options_.jpeg_quality);
    return true;
  } catch (const std::exception& e) {
    std::lock_guard<std::mutex> lock(mu_);
    render_error_ = std::string("live: cannot start the renderer: ") + e.what();
    frame_cv_.notify_all();
    return false;
  }
}

void LiveSession::PublishStillLocked(const Image& canvas) {
  if (still_done_ == still_wanted_) return;
  image_ = std::make_shared<const Image>(canvas);
  still_done_ = still_wanted_;
  frame_cv_.notify_all();
}

bool LiveSession::WaitForWork(const Painter& painter, RenderWork* work) {
  std::unique_lock<std::mutex> lock(mu_);
  while (true) {
    // Nobody watching, nothing asked: no drawing, no encoding (the first frame is drawn
    // regardless, for the constructor).
    auto changed = [&] {
      const bool watching = viewers_ > 0 || recording_ || record_wanted_ || !frame_;
      return fresh_wanted_ != fresh_done_ ||
             (watching && (input_version_ != work->input || view_version_ != work->view));
    };
    render_cv_.wait(lock, [&] {
      return stop_ || changed() || record_wanted_ != recording_ ||
             (still_wanted_ != still_done_ && frame_);
    });
    if (stop_) return false;
    const bool redraw = changed();
    if (!redraw) PublishStillLocked(painter.canvas);  // the newest frame drawn is the state now
    if (!redraw && record_wanted_ == recording_) continue;
    work->want_record = record_wanted_;
    work->input = input_version_;
    work->view = view_version_;
    work->fresh = fresh_wanted_;
    work->picture = history_;
    work->status = StatusLocked();
    work->colormap = colormap_;
    work->camera = camera_;
    work->seq = seq_applied_;
    work->step = steps_;
    return true;
  }
}

bool LiveSession::UpdateRecording(LiveRecorder* recorder, const RenderWork& work) {
  if (work.want_record && !recorder->recording()) {
    try {
      recorder->Start(options_.out_dir, options_.width, options_.height, options_.fps,
                      work.picture.now().t, work.step);
      std::lock_guard<std::mutex> lock(mu_);
      recording_ = true;
      record_error_.clear();
      ++state_version_;
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lock(mu_);
      record_error_ = e.what();
      record_wanted_ = false;
      ++state_version_;
      return false;
    }
  } else if (!work.want_record && recorder->recording()) {
    FinishRecording(recorder);
  }
  return true;
}

void LiveSession::FinishRecording(LiveRecorder* recorder) {
  if (!recorder->recording()) return;
  std::uint64_t end_step;
  double end_t;
  {
    std::lock_guard<std::mutex> lock(mu_);
    end_step = record_end_step_;
    end_t = record_end_t_;
  }
  try {
    const LiveRecorder::Film film = recorder->Finish(end_step, end_t);
    std::lock_guard<std::mutex> lock(mu_);
    recordings_.push_back(film);
    std::printf("live: wrote %s (%ld frames)\n", film.path.c_str(), film.frames);
    std::fflush(stdout);
  } catch (const std::exception& e) {
    std::lock_guard<std::mutex> lock(mu_);
    record_error_ = e.what();
  }
  std::lock_guard<std::mutex> lock(mu_);
  recording_ = false;
  ++state_version_;
}

std::shared_ptr<LiveFrame> LiveSession::PackFrame(Painter* painter, double t,
                                                  std::uint64_t seq) const {
  auto out = std::make_shared<LiveFrame>();
  out->number = ++painter->number;
  out->t = t;
  out->seq = seq;
  out->message.reserve(LiveFrame::kHeaderBytes + painter->message_bytes +
                       painter->message_bytes / 4);
  out->message.resize(LiveFrame::kHeaderBytes);
  for (int i = 0; i < 8; ++i) {  // little-endian, whatever the machine
    std::uint64_t t_bits;
    std::memcpy(&t_bits, &out->t, 8);
    out->message[i] = static_cast<char>((out->number >> (8 * i)) & 0xff);
    out->message[8 + i] = static_cast<char>((t_bits >> (8 * i)) & 0xff);
    out->message[16 + i] = static_cast<char>((out->seq >> (8 * i)) & 0xff);
  }
  // Only the tiles that changed encoded again, looked for where the renderer drew.
  const Renderer& r = *painter->renderer;
  painter->jpeg->Encode(painter->canvas, &out->message,
                        r.redrawn() < 1 ? &r.redrawn_rects() : nullptr);
  painter->message_bytes = out->message.size();
  return out;
}

void LiveSession::DrawFrame(Painter* painter, LiveRecorder* recorder, const RenderWork& work) {
  try {
    const Snapshot& shown = work.picture.now();
    const FrameLayout layout =
        MakeFrameLayout(view_, work.picture, options_.width, options_.height);
    const Frame frame = MakeFrame(view_, work.picture, shown, layout, Colormap(work.colormap),
                                  Theme::Dark(), work.status, &work.camera);
    painter->renderer->DrawOnto(frame, &painter->canvas);
    std::shared_ptr<LiveFrame> out = PackFrame(painter, shown.t, work.seq);
    recorder->Add(painter->canvas, work.step);
    PublishFrame(std::move(out), *painter, work, layout.space ? layout.space_view : PixelRect{});
  } catch (const std::exception& e) {
    std::lock_guard<std::mutex> lock(mu_);
    render_error_ = e.what();
    if (work.fresh > fresh_done_) fresh_done_ = work.fresh;  // the asker gets the newest there is
    PublishStillLocked(painter->canvas);
    ++state_version_;
    frame_cv_.notify_all();
  }
}

void LiveSession::PublishFrame(std::shared_ptr<LiveFrame> frame, const Painter& painter,
                               const RenderWork& work, const PixelRect& space_view) {
  const double now = Seconds(start_, Clock::now());
  std::lock_guard<std::mutex> lock(mu_);
  frame_ = std::move(frame);
  frame_input_ = work.input;
  frame_view_ = work.view;
  space_view_ = space_view;
  if (work.fresh > fresh_done_) fresh_done_ = work.fresh;
  PublishStillLocked(painter.canvas);
  frame_times_.push_back(now);
  while (!frame_times_.empty() && frame_times_.front() < now - 1.0) frame_times_.pop_front();
  render_error_.clear();
  frame_cv_.notify_all();
}

// ---- The face for the network --------------------------------------------------------------

LiveSession::Reply LiveSession::Control(const std::string& body) {
  ControlRequest r;
  try {
    r = ParseControl(body, limits_);
  } catch (const ControlError& e) {
    return {400, Json{{"error", e.what()}}.dump(-1, ' ', true, Json::error_handler_t::replace)};
  }
  std::string reply;
  {
    std::lock_guard<std::mutex> lock(mu_);
    if (stop_) return {503, Json{{"error", "the live view is stopping"}}.dump()};
    // Every control goes through the simulation thread in order, so the sequence number a
    // frame carries says which controls it shows.
    if (pending_.size() >= 64) return {503, Json{{"error", "too many controls at once; try again"}}.dump()};
    Pending p;
    p.seq = ++seq_;
    p.restart = r.restart;
    p.amplitude_scale = r.amplitude_scale;
    p.period = r.period;
    p.current = r.current;
    p.current_heading = r.current_heading;
    p.wave_height = r.wave_height;
    p.wave_period = r.wave_period;
    p.wave_heading = r.wave_heading;
    p.offset_x = r.offset_x;
    p.offset_z = r.offset_z;
    p.force_x = r.force_x;
    p.force_z = r.force_z;
    pending_.push_back(p);
    if (r.restart) {
      targets_ = sim_->scene_sea();
      steps_requested_ = 0;
    }
    if (r.amplitude_scale) targets_.amplitude_scale = *r.amplitude_scale;
    if (r.period) targets_.period = *r.period;
    if (r.current) targets_.current = *r.current;
    if (r.current_heading) targets_.current_heading = *r.current_heading;
    if (r.wave_heading) targets_.wave_heading = *r.wave_heading;
    if (r.wave_height) targets_.wave_height = *r.wave_height;
    if (r.wave_period) targets_.wave_period = *r.wave_period;
    if (r.wave_period && sim_->end_follows_wave()) targets_.period = *r.wave_period;
    if (r.offset_x) targets_.offset_x = *r.offset_x;
    if (r.offset_z) targets_.offset_z = *r.offset_z;
    if (r.force_x) targets_.force_x = *r.force_x;
    if (r.force_z) targets_.force_z = *r.force_z;
    if (r.pause) paused_ = *r.pause;
    if (r.step) {
      paused_ = true;
      ++steps_requested_;
    }
    if (r.speed) speed_ = *r.speed;
    if (r.colormap) colormap_ = *r.colormap;
    if (r.reset_range) history_.ResetRange();  // first: a range or lock sent with it wins
    if (r.tension_range) history_.SetRange((*r.tension_range)[0], (*r.tension_range)[1]);
    if (r.lock_range) history_.LockRange(*r.lock_range);
    if (r.record) {
      if (record_wanted_ && !*r.record) {  // the film ends at the state this stop sees
        record_end_step_ = steps_;
        record_end_t_ = t_;
      }
      record_wanted_ = *r.record;
    }
    if (r.camera) {  // over the camera as it is; clamped: a hostile value only turns the view
      OrbitCamera c = r.camera->reset ? DefaultCamera(view_) : camera_;
      if (r.camera->azimuth) c.azimuth = *r.camera->azimuth;
      if (r.camera->elevation) c.elevation = *r.camera->elevation;
      if (r.camera->zoom) c.zoom = *r.camera->zoom;
      camera_ = ClampCamera(c);
    }
    if (r.colormap || r.tension_range || r.lock_range || r.reset_range || r.pause || r.speed ||
        r.camera)
      ++view_version_;
    ++state_version_;
    // The state this control made, not a later one: a film stopped here ends at its t.
    reply = StateJsonLocked();
  }
  sim_cv_.notify_all();
  render_cv_.notify_all();
  return {200, reply};
}

std::string LiveSession::StateJson() const {
  std::lock_guard<std::mutex> lock(mu_);
  return StateJsonLocked();
}

std::string LiveSession::StateJsonLocked() const {
  double realtime = 0;
  if (progress_.size() >= 2) {
    const double wall = progress_.back().first - progress_.front().first;
    if (wall > 0) realtime = (progress_.back().second - progress_.front().second) / wall;
  }
  Json recordings = Json::array();
  for (const LiveRecorder::Film& r : recordings_)
    recordings.push_back({{"name", r.name}, {"url", "/recordings/" + r.name}, {"frames", r.frames},
                          {"seconds", r.frames / options_.fps},
                          {"t_start", Finite(r.t_start)}, {"t_end", Finite(r.t_end)}});
  Json j{
      {"t", Finite(t_)},
      {"frame", frame_ ? frame_->number : 0},
      {"seq", seq_},
      {"seq_applied", seq_applied_},
      {"paused", paused_},
      {"speed", speed_},
      {"amplitude_scale", targets_.amplitude_scale},
      {"period", sim_->has_driven_end() ? Json(targets_.period) : Json(nullptr)},
      {"has_period", sim_->has_driven_end()},
      {"ends", {{"start", start_kind_}, {"end", end_kind_}}},
      {"current", targets_.current},
      {"current_now", Finite(current_now_)},
      {"current_heading", targets_.current_heading},
      {"current_heading_now", Finite(current_heading_now_)},
      {"current_from_table", limits_.current_history},
      {"wave_height", limits_.has_waves ? Json(targets_.wave_height) : Json(nullptr)},
      {"wave_period", limits_.has_waves ? Json(targets_.wave_period) : Json(nullptr)},
      {"wave_heading", limits_.has_waves ? Json(targets_.wave_heading) : Json(nullptr)},
      {"wave_heading_now", limits_.has_waves ? Json(Finite(wave_heading_now_)) : Json(nullptr)},
      {"has_waves", limits_.has_waves},
      {"colormap", colormap_},
      {"colormaps", limits_.colormaps},
      {"range", {{"min", history_.range_min()}, {"max", history_.range_max()},
                 {"locked", history_.range_locked()}}},
      {"tension", {{"start", Finite(tension_start_)}, {"end", Finite(tension_end_)},
                   {"max", Finite(tension_max_)}, {"link_max", link_max_}}},
      {"peak", {{"value", Finite(history_.peak())}, {"t", history_.peak_t()},
                {"link", history_.peak_link()}}},
      {"fps", static_cast<double>(frame_times_.size())},
      {"realtime", Finite(realtime)},
      {"viewers", viewers_.load()},
      {"recording", recording_},
      {"recordings", recordings},
      {"title", scene_.title},
      {"scene", scene_.name},
      {"duration", scene_.simulation.duration},
      {"space", view_.space},
      {"camera", {{"azimuth", camera_.azimuth}, {"elevation", camera_.elevation},
                  {"zoom", camera_.zoom}}},
      {"space_view", {space_view_.x0, space_view_.y0, space_view_.x1, space_view_.y1}},
      {"width", options_.width},
      {"height", options_.height},
      {"limits", {{"speed", {limits_.speed_min, limits_.speed_max}},
                  {"amplitude_scale", {0.0, limits_.amplitude_max}},
                  {"period", {limits_.period_min, limits_.period_max}},
                  {"current", {-limits_.current_max, limits_.current_max}},
                  {"current_heading", {-limits_.heading_max, limits_.heading_max}},
                  {"wave_height", {0.0, limits_.wave_height_max}},
                  {"wave_period", {limits_.wave_period_min, limits_.wave_period_max}},
                  {"wave_heading", {-limits_.heading_max, limits_.heading_max}}}},
  };
  // Each line's numbers now and its peak (the picture names them), the vessel's offset and the
  // free bodies' extra force.
  Json lines = Json::array();
  for (std::size_t i = 0; i < lines_now_.size() && i < view_.lines.size(); ++i) {
    const LineNumbers& n = lines_now_[i];
    lines.push_back({{"name", view_.lines[i].label}, {"start", Finite(n.start)},
                     {"end", Finite(n.end)}, {"max", Finite(n.max)}, {"link_max", n.link_max},
                     {"peak", Finite(history_.peak(i))}, {"peak_t", Finite(history_.peak_t(i))}});
  }
  j["lines"] = lines;
  if (lines_now_.size() > 1) {  // the peak of all lines so far, and its line
    std::size_t top = 0;
    for (std::size_t i = 0; i < view_.lines.size(); ++i)
      if (history_.has_peak(i) && !(history_.peak(i) <= history_.peak(top))) top = i;
    j["peak"] = {{"value", Finite(history_.peak(top))}, {"t", history_.peak_t(top)},
                 {"link", history_.peak_link(top)}, {"line", view_.lines[top].label}};
  }
  j["has_offset"] = limits_.has_vessel;
  j["offset_x"] = targets_.offset_x;
  j["offset_z"] = targets_.offset_z;
  j["offset_x_now"] = Finite(offset_x_now_);
  j["offset_z_now"] = Finite(offset_z_now_);
  j["limits"]["offset"] = {-limits_.offset_max, limits_.offset_max};
  j["has_force"] = limits_.has_free_body;
  j["force_x"] = targets_.force_x;
  j["force_z"] = targets_.force_z;
  j["force_x_now"] = Finite(force_x_now_);
  j["force_z_now"] = Finite(force_z_now_);
  j["limits"]["force"] = {-limits_.force_max, limits_.force_max};
  if (!error_.empty()) j["error"] = error_;
  if (!render_error_.empty()) j["render_error"] = render_error_;
  if (!record_error_.empty()) j["record_error"] = record_error_;
  return j.dump(-1, ' ', true, Json::error_handler_t::replace);
}

std::shared_ptr<const LiveFrame> LiveSession::NewestFrame() const {
  std::lock_guard<std::mutex> lock(mu_);
  return frame_;
}

std::shared_ptr<const LiveFrame> LiveSession::WaitFrame(std::uint64_t after,
                                                        std::chrono::milliseconds timeout) const {
  std::unique_lock<std::mutex> lock(mu_);
  frame_cv_.wait_for(lock, timeout, [&] { return stop_ || (frame_ && frame_->number > after); });
  if (stop_ || !frame_ || frame_->number <= after) return nullptr;
  return frame_;
}

void LiveSession::AddViewer(int delta) {
  {
    std::lock_guard<std::mutex> lock(mu_);
    viewers_ += delta;
  }
  render_cv_.notify_all();  // a first viewer gets the state now, not the one last drawn
}

std::uint64_t LiveSession::frames_drawn() const {
  std::lock_guard<std::mutex> lock(mu_);
  return frame_ ? frame_->number : 0;
}

std::shared_ptr<const LiveFrame> LiveSession::FreshFrame(std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(mu_);
  const bool watching = viewers_ > 0 || recording_;
  const bool current = frame_input_ == input_version_ && frame_view_ == view_version_;
  if (watching || current || stop_) return frame_;  // being drawn anyway, or still true
  const std::uint64_t want = ++fresh_wanted_;
  render_cv_.notify_all();
  frame_cv_.wait_for(lock, timeout, [&] { return stop_ || fresh_done_ >= want; });
  return frame_;
}

std::string LiveSession::SnapshotPng() {
  FreshFrame(std::chrono::milliseconds(2000));
  std::shared_ptr<const Image> image;
  {  // the render thread copies out its newest frame
    std::unique_lock<std::mutex> lock(mu_);
    const std::uint64_t want = ++still_wanted_;
    render_cv_.notify_all();
    frame_cv_.wait_for(lock, std::chrono::milliseconds(2000),
                       [&] { return stop_ || still_done_ >= want; });
    image = image_;
  }
  if (!image) throw Error("live: no frame drawn yet");
  PngOptions o;
  o.compression_level = 3;
  return EncodePng(*image, o);
}

void LiveSession::ReadTimeseries(const std::function<bool(const char*, std::size_t)>& sink) {
  long size = 0;
  {
    std::lock_guard<std::mutex> lock(mu_);
    size = rows_.Flush();
  }
  rows_.Read(size, sink);
}

std::string LiveSession::RecordingPath(const std::string& name) const {
  std::lock_guard<std::mutex> lock(mu_);
  for (const LiveRecorder::Film& r : recordings_)
    if (r.name == name) return r.path;
  return "";
}

}  // namespace cablefilm
