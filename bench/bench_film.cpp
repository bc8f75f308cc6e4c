// Film throughput on this machine: a procedural P63-like cable (61 stations, src/view/
// demo_cable.h; the real simulator is not involved) drawn and encoded end to end through
// FilmWriter at 1920x1080 and 1280x720, and separately the render+readback rate of whole
// frames (MakeFrame + Renderer::Draw) and of the changes alone as the film draws them
// (redraw_changes, Renderer::DrawOnto; with the share of pixels redrawn), and the encode rate
// of whole frames (RGBA->yuv420p + libx264). Prints frames per second.
//   bench_film [frames=240] [preset=veryfast] [crf=20]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "encode/video_encoder.h"
#include "view/demo_cable.h"
#include "view/film_writer.h"
#include "view/frame_builder.h"
#include "view/renderer.h"

using namespace cablefilm;
using Clock = std::chrono::steady_clock;

namespace {

double Seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

struct Size {
  int w, h;
};

double EndToEnd(Size size, int frames, const std::string& preset, int crf, const std::string& dir) {
  const double fps = 30;
  const SceneView scene = MakeDemoScene();
  const FixedPolicy policy = MakeDemoPolicy(frames / fps);
  FilmOptions o;
  o.width = size.w;
  o.height = size.h;
  o.fps = fps;
  o.preset = preset;
  o.crf = crf;
  o.progress = false;
  o.write_max_tension = false;
  const auto t0 = Clock::now();
  {
    FilmWriter writer(o, scene, policy, dir, frames);
    for (int i = 0; i < frames; ++i) writer.Push(MakeDemoSnapshot(scene, i / fps));
    writer.Finish();
  }
  return frames / Seconds(t0, Clock::now());
}

void RenderAndEncode(Size size, int frames, const std::string& preset, int crf,
                     const std::string& dir, double* render_fps, double* make_ms,
                     double* changes_fps, double* redrawn, double* encode_fps) {
  const double fps = 30;
  const SceneView scene = MakeDemoScene();
  History history(scene, MakeDemoPolicy(frames / fps));
  const FrameLayout layout = MakeFrameLayout(scene, history, size.w, size.h);
  const Colormap colormap("viridis");
  RenderOptions ro;
  ro.width = size.w;
  ro.height = size.h;
  Renderer renderer(ro);
  // A cycle of distinct rendered frames to feed the encoder afterwards.
  std::vector<Image> images(30);
  double make = 0;
  renderer.Draw(MakeFrame(scene, history, MakeDemoSnapshot(scene, 0), layout, colormap),
                &images[0]);
  const auto t0 = Clock::now();
  for (int i = 0; i < frames; ++i) {
    const Snapshot s = MakeDemoSnapshot(scene, i / fps);
    history.Add(s);
    const auto m0 = Clock::now();
    const Frame frame = MakeFrame(scene, history, s, layout, colormap);
    make += Seconds(m0, Clock::now());
    renderer.Draw(frame, &images[i % images.size()]);
  }
  *render_fps = frames / Seconds(t0, Clock::now());
  *make_ms = 1000 * make / frames;

  {  // the film's way: only what changed drawn and read back, into the one picture
    History film_history(scene, MakeDemoPolicy(frames / fps));
    RenderOptions changes = ro;
    changes.redraw_changes = true;
    Renderer partial(changes);
    Image picture;
    double shares = 0;
    const auto c0 = Clock::now();
    for (int i = 0; i < frames; ++i) {
      const Snapshot s = MakeDemoSnapshot(scene, i / fps);
      film_history.Add(s);
      partial.DrawOnto(MakeFrame(scene, film_history, s, layout, colormap), &picture);
      shares += partial.redrawn();
    }
    *changes_fps = frames / Seconds(c0, Clock::now());
    *redrawn = shares / frames;
  }

  VideoOptions vo;
  vo.width = size.w;
  vo.height = size.h;
  vo.fps = fps;
  vo.preset = preset;
  vo.crf = crf;
  const auto e0 = Clock::now();
  VideoEncoder encoder(dir + "/encode_only.mp4", vo);
  for (int i = 0; i < frames; ++i) encoder.AddFrame(images[i % images.size()]);
  encoder.Finish();
  *encode_fps = frames / Seconds(e0, Clock::now());
}

}  // namespace

int Bench(int argc, char** argv) {
  const int frames = argc > 1 ? std::atoi(argv[1]) : 240;
  const std::string preset = argc > 2 ? argv[2] : "veryfast";
  const int crf = argc > 3 ? std::atoi(argv[3]) : 20;
  if (argc > 4 || frames < 1 || frames > 100000 || crf < 0 || crf > 51) {
    std::fprintf(stderr, "usage: bench_film [frames=240, 1 to 100000] [preset=veryfast] "
                         "[crf=20, 0 to 51]\n");
    return 2;
  }
  const std::string dir =
      (std::filesystem::temp_directory_path() / "cablefilm_bench_film").string();
  std::filesystem::create_directories(dir);
  std::printf("bench_film: %d frames per run, 61 stations, x264 preset %s crf %d\n", frames,
              preset.c_str(), crf);
  {
    RenderOptions ro;
    ro.width = 64;
    ro.height = 64;
    std::printf("renderer: %s\n", Renderer(ro).Describe().c_str());
  }
  for (Size size : {Size{1920, 1080}, Size{1280, 720}}) {
    double render_fps = 0, make_ms = 0, changes_fps = 0, redrawn = 0, encode_fps = 0;
    RenderAndEncode(size, frames, preset, crf, dir, &render_fps, &make_ms, &changes_fps,
                    &redrawn, &encode_fps);
    const double e2e = EndToEnd(size, frames, preset, crf, dir);
    const auto bytes = std::filesystem::file_size(dir + "/film.mp4");
    std::printf("%4dx%-4d  end to end %6.1f fps | render+readback whole %6.1f fps (MakeFrame "
                "%.2f ms), changes %6.1f fps (%.0f %% redrawn) | encode whole %6.1f fps | "
                "film %.1f kB/s of film\n",
                size.w, size.h, e2e, render_fps, make_ms, changes_fps, 100 * redrawn,
                encode_fps, bytes / 1024.0 / (frames / 30.0));
    std::fflush(stdout);
  }
  std::filesystem::remove_all(dir);
  return 0;
}

int main(int argc, char** argv) {
  try {
    return Bench(argc, argv);
  } catch (const std::exception& e) {  // a preset x264 does not know, a renderer that fails
    std::fprintf(stderr, "bench_film: %s\n", e.what());
    return 1;
  }
}
