#include "view/film_writer.h"

#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <exception>
#include <filesystem>
#include <future>
#include <mutex>
#include <thread>

#include "core/error.h"
#include "encode/png_writer.h"
#include "encode/video_encoder.h"
#include "io/output_ledger.h"
#include "view/max_tension_figure.h"
#include "view/renderer.h"

namespace cablefilm {

struct FilmWriter::Impl {
  FilmOptions options;
  SceneView scene;
  FixedPolicy policy;
  std::string out_dir;
  int total_frames = 0;

  std::mutex mutex;
  std::condition_variable not_full, not_empty;
  std::deque<Snapshot> queue;
  bool closing = false;
  bool complete = true;    // false: FinishPartial (the film stays under its partial name)
  bool failed = false;
  std::exception_ptr error;
  bool error_thrown = false;  // the error has reached the caller (it is reported there, once)
  bool finished = false;
  long done = 0;
  std::vector<MaxTensionSeries> series;  // a line each; copied out under the mutex
  std::promise<void> ready;  // set by the worker once set up (or with its set-up error)
  std::thread worker;

  void Run(std::promise<void>* ready);
  void SetError(std::exception_ptr e) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!error) error = e;
    failed = true;
    not_full.notify_all();
  }
};

namespace {

class Progress {
 public:
  Progress(bool enabled, int total) : enabled_(enabled && ::isatty(2)), total_(total) {}
  void Update(long done, bool final = false) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (!final && now - last_ < std::chrono::milliseconds(250)) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double fps = elapsed > 0 ? done / elapsed : 0;
    char line[160];
    if (total_ > 0) {
      const double left = fps > 0 ? std::max(0.0, (total_ - done) / fps) : 0;
      const int s = static_cast<int>(left + 0.5);
      std::snprintf(line, sizeof line, "\rfilm: frame %ld/%d (%3.0f%%)  %5.1f fps  %d:%02d left   ",
                    done, total_, 100.0 * done / total_, fps, s / 60, s % 60);
    } else {
      std::snprintf(line, sizeof line, "\rfilm: frame %ld  %5.1f fps   ", done, fps);
    }
    std::fputs(line, stderr);
    if (final) std::fputs("\n", stderr);
    std::fflush(stderr);
    printed_ = true;
  }
  bool printed() const { return printed_; }

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  int total_;
  bool printed_ = false;
  Clock::time_point start_ = Clock::now(), last_{};
};

}  // namespace

void FilmWriter::Impl::Run(std::promise<void>* ready) {
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<VideoEncoder> encoder;
  std::unique_ptr<History> history;
  const bool draw = options.write_film || options.write_frames;
  try {
    history = std::make_unique<History>(scene, policy);
    if (draw) {
      RenderOptions ro;
      ro.width = options.width;
      ro.height = options.height;
      ro.shader_dir = options.shader_dir;
      ro.font_path = options.font_path;
      // A film's frames differ where the lines, the newest samples and the clock move: the rest
      // is kept from the frame before (the same pixels as drawing it whole, renderer.h).
      ro.redraw_changes = true;
      renderer = std::make_unique<Renderer>(ro);
    }
    if (options.write_film) {
      VideoOptions vo;
      vo.width = options.width;
      vo.height = options.height;
      vo.fps = options.fps;
      vo.crf = options.crf;
      vo.preset = options.preset;
      encoder = std::make_unique<VideoEncoder>(out_dir + "/film.mp4", vo);
    }
  } catch (...) {
    ready->set_exception(std::current_exception());
    return;
  }
  ready->set_value();

  try {
    const Colormap colormap(options.colormap);
    const FrameLayout layout = MakeFrameLayout(scene, *history, options.width, options.height);
    Progress progress(options.progress, total_frames);
    Image image;
    PngOptions png;
    png.compression_level = options.png_compression;
    for (;;) {
      Snapshot snapshot;
      {
        std::unique_lock<std::mutex> lock(mutex);
        not_empty.wait(lock, [&] { return !queue.empty() || closing; });
        if (queue.empty()) break;
        snapshot = std::move(queue.front());
        queue.pop_front();
        not_full.notify_one();
      }
      history->Add(snapshot);
      if (draw) {
        const Frame frame = MakeFrame(scene, *history, snapshot, layout, colormap);
        renderer->DrawOnto(frame, &image);  // `image` holds the frame before: its changes
        if (encoder)
          encoder->AddFrame(image, renderer->redrawn() < 1 ? &renderer->redrawn_rects() : nullptr);
        if (options.write_frames) {
          char name[64];
          std::snprintf(name, sizeof name, "/frames/frame_%06ld.png", done);
          WritePng(out_dir + name, image, png);
        }
      }
      {
        std::lock_guard<std::mutex> lock(mutex);
        ++done;
      }
      progress.Update(done);
    }
    {  // the time plot's data as the last frame shows it (every row the snapshots carried)
      std::lock_guard<std::mutex> lock(mutex);
      for (std::size_t i = 0; i < series.size(); ++i) {
        series[i].t = history->times();
        series[i].tension = history->max_tension()[i];
      }
    }
    if (progress.printed()) progress.Update(done, true);
    bool complete = true;
    {
      std::lock_guard<std::mutex> lock(mutex);
      complete = this->complete;
    }
    if (encoder) complete ? encoder->Finish() : encoder->FinishPartial();
    encoder.reset();
    renderer.reset();  // one context at a time
    if (options.write_max_tension && history->count() > 0) {
      std::vector<MaxTensionSeries> all;
      {
        std::lock_guard<std::mutex> lock(mutex);
        all = series;
      }
      WriteMaxTensionPng(out_dir + (complete ? "/max_tension.png" : "/max_tension.partial.png"),
                         all, options.still_width,
                         options.still_height,
                         scene.title.empty()
                             ? "Maximum tension along the cable"
                             : "Maximum tension along the cable \u2014 " + scene.title,
                         options.font_path);
    }
  } catch (...) {
    SetError(std::current_exception());
  }
}

FilmWriter::FilmWriter(const FilmOptions& options, const SceneView& scene,
                       const FixedPolicy& policy, const std::string& out_dir, int total_frames)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.options = options;
  m.scene = scene;
  m.policy = policy;
  m.out_dir = out_dir.empty() ? "." : out_dir;
  m.total_frames = total_frames;
  if (options.width <= 0 || options.height <= 0 || options.width % 2 || options.height % 2)
    throw Error("film: width and height must be positive and even, got " +
                std::to_string(options.width) + "x" + std::to_string(options.height));
  if (!(options.fps > 0)) throw Error("film: fps must be positive, got " + std::to_string(options.fps));
  if (options.queue_capacity < 1)
    throw Error("film: queue capacity must be at least 1, got " + std::to_string(options.queue_capacity));
  Colormap check(options.colormap);  // unknown names fail here, with the known ones
  MakeFrameLayout(scene, History(scene, policy), options.width, options.height);  // checks both
  for (std::size_t i = 0; i < scene.lines.size(); ++i) {
    const std::string& label = scene.lines[i].label;
    const bool first_unnamed = i == 0 && label.empty();
    m.series.push_back({first_unnamed ? options.series_label : LineName(scene, i), {}, {}});
  }
  std::error_code ec;
  std::filesystem::create_directories(m.out_dir, ec);
  if (ec) throw Error("film: cannot create " + m.out_dir + ": " + ec.message());
  if (options.write_frames) CreateOutputFolder(m.out_dir + "/frames");
  std::future<void> started = m.ready.get_future();
  m.worker = std::thread([&m] { m.Run(&m.ready); });
  try {
    started.get();
  } catch (...) {
    m.worker.join();
    m.finished = true;
    throw;
  }
}

FilmWriter::~FilmWriter() {
  if (!impl_ || impl_->finished) return;
  try {
    FinishPartial();  // not finished by the caller: it failed or was stopped part way
  } catch (const std::exception& e) {
    if (!impl_->error_thrown) std::fprintf(stderr, "film: %s\n", e.what());
  }
}

void FilmWriter::Push(Snapshot snapshot) {
  Impl& m = *impl_;
  std::unique_lock<std::mutex> lock(m.mutex);
  if (m.finished || m.closing) throw Error("film: snapshot pushed after Finish()");
  m.not_full.wait(lock, [&] {
    return m.failed || m.queue.size() < static_cast<std::size_t>(m.options.queue_capacity);
  });
  if (m.failed) {
    m.error_thrown = true;
    std::rethrow_exception(m.error);
  }
  m.queue.push_back(std::move(snapshot));
  m.not_empty.notify_one();
}

void FilmWriter::FinishPartial() {
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->complete = false;
  }
  Finish();
}

void FilmWriter::Finish() {
  Impl& m = *impl_;
  if (m.finished) return;
  {
    std::lock_guard<std::mutex> lock(m.mutex);
    m.closing = true;
    m.not_empty.notify_all();
  }
  if (m.worker.joinable()) m.worker.join();
  m.finished = true;
  if (m.error) std::rethrow_exception(m.error);
}

long FilmWriter::frames_done() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->done;
}

MaxTensionSeries FilmWriter::max_tension_series() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  MaxTensionSeries first = impl_->series.front();
  first.label = impl_->options.series_label;
  return first;
}

std::vector<MaxTensionSeries> FilmWriter::all_max_tension_series() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->series;
}

}  // namespace cablefilm
