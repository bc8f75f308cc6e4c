#include "encode/video_encoder.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "core/error.h"

namespace cablefilm {
namespace {

std::string TempDir() {
  const auto dir = std::filesystem::path(CABLEFILM_BINARY_DIR) / "test_output" / "encode";
  std::filesystem::create_directories(dir);
  return dir.string();
}

Image Pattern(int w, int h, int frame) {
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = image.row(y) + 4 * x;
      p[0] = static_cast<std::uint8_t>((x + 4 * frame) & 0xff);
      p[1] = static_cast<std::uint8_t>(y & 0xff);
      p[2] = static_cast<std::uint8_t>((x + y) / 2 & 0xff);
      p[3] = 255;
    }
  return image;
}

TEST(VideoEncoder, FilmReopensWithTheExpectedStream) {
  const std::string path = TempDir() + "/film.mp4";
  std::filesystem::remove(path);
  VideoOptions options;
  options.width = 320;
  options.height = 240;
  options.fps = 25;
  options.preset = "ultrafast";
  VideoEncoder encoder(path, options);
  for (int i = 0; i < 50; ++i) encoder.AddFrame(Pattern(320, 240, i));
  EXPECT_FALSE(std::filesystem::exists(path)) << "the film appears only when finished";
  encoder.Finish();
  encoder.Finish();  // idempotent
  EXPECT_EQ(encoder.frames_added(), 50);

  const VideoInfo info = ProbeVideo(path);
  EXPECT_EQ(info.codec, "h264");
  EXPECT_EQ(info.pixel_format, "yuv420p");
  EXPECT_EQ(info.width, 320);
  EXPECT_EQ(info.height, 240);
  EXPECT_EQ(info.frames, 50);
  // 50 frames at 25 fps last 2 s; the stream duration is counted in frame durations, so it is
  // exact up to one frame (1/25 s) depending on how the muxer rounds the last one.
  EXPECT_NEAR(info.duration, 2.0, 1.0 / 25 + 1e-6);
  EXPECT_NEAR(info.fps, 25.0, 1e-6);
  // +faststart: the index (moov) precedes the media data (mdat), so the film streams.
  ASSERT_GE(info.moov_offset, 0);
  ASSERT_GE(info.mdat_offset, 0);
  EXPECT_LT(info.moov_offset, info.mdat_offset);
  EXPECT_FALSE(std::filesystem::exists(PartialPath(path)));
}

// A film fed the changed rectangles of each frame (the film writer's renderer redraws only
// those) is byte for byte the film fed whole frames: the planes keep the rest. With one
// encoder thread, and with the film's defaults (preset veryfast, threads chosen by x264,
// frames in flight in its lookahead): x264 is deterministic for a given thread count.
TEST(VideoEncoder, FramesChangedInPlacesGiveTheFilmOfWholeFrames) {
  const int w = 326, h = 190;  // edges inside the converter's tiles
  std::vector<Image> frames;
  std::vector<std::vector<ImageRect>> changes;
  Image image = Pattern(w, h, 0);
  for (int i = 0; i < 40; ++i) {
    std::vector<ImageRect> changed;
    if (i > 0) {
      // A block that walks across the picture and one that blinks at the corner.
      const int x = (7 * i) % (w - 30), y = (5 * i) % (h - 20);
      changed.push_back({x, y, x + 30, y + 20});
      changed.push_back({w - 9, h - 7, w, h});
      for (const ImageRect& r : changed)
        for (int yy = r.y0; yy < r.y1; ++yy)
          for (int xx = r.x0; xx < r.x1; ++xx) {
            std::uint8_t* p = image.row(yy) + 4 * xx;
            p[0] = static_cast<std::uint8_t>(40 * i + xx);
            p[1] = static_cast<std::uint8_t>(255 - 3 * yy);
            p[2] = static_cast<std::uint8_t>(i * yy);
          }
    }
    frames.push_back(image);
    changes.push_back(changed);
  }
  auto film = [&](const char* name, bool tell_changes, bool defaults) {
    const std::string path = TempDir() + "/" + name;
    VideoOptions options;
    options.width = w;
    options.height = h;
    if (!defaults) {
      options.preset = "ultrafast";
      options.threads = 1;
    }
    VideoEncoder encoder(path, options);
    for (std::size_t i = 0; i < frames.size(); ++i)
      encoder.AddFrame(frames[i], tell_changes ? &changes[i] : nullptr);
    encoder.Finish();
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  for (const bool defaults : {false, true}) {
    const std::string whole = film("whole_frames.mp4", false, defaults);
    const std::string changed = film("changed_frames.mp4", true, defaults);
    ASSERT_GT(whole.size(), 1000u);
    EXPECT_TRUE(whole == changed) << (defaults ? "defaults: " : "one thread: ") << whole.size()
                                  << " against " << changed.size() << " bytes";
  }
}

TEST(VideoEncoder, NonIntegerFrameRate) {
  const std::string path = TempDir() + "/film_2997.mp4";
  VideoOptions options;
  options.width = 64;
  options.height = 64;
  options.fps = 30000.0 / 1001;
  options.preset = "ultrafast";
  VideoEncoder encoder(path, options);
  for (int i = 0; i < 30; ++i) encoder.AddFrame(Pattern(64, 64, i));
  encoder.Finish();
  const VideoInfo info = ProbeVideo(path);
  EXPECT_EQ(info.frames, 30);
  EXPECT_NEAR(info.fps, 29.97, 0.01);
  EXPECT_NEAR(info.duration, 30 / (30000.0 / 1001), 1.0 / 29.97 + 1e-6);
}

TEST(VideoEncoder, UnfinishedEncoderLeavesNoFilm) {
  const std::string path = TempDir() + "/abandoned.mp4";
  std::filesystem::remove(path);
  {
    VideoOptions options;
    options.width = 64;
    options.height = 48;
    options.preset = "ultrafast";
    VideoEncoder encoder(path, options);
    encoder.AddFrame(Pattern(64, 48, 0));
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(PartialPath(path)));
}

TEST(VideoEncoder, PartialFilmPlaysUnderItsPartialName) {
  const std::string path = TempDir() + "/cut_short.mp4";
  EXPECT_EQ(PartialPath(path), TempDir() + "/cut_short.partial.mp4");
  std::filesystem::remove(PartialPath(path));
  VideoOptions options;
  options.width = 64;
  options.height = 48;
  options.fps = 30;
  options.preset = "ultrafast";
  VideoEncoder encoder(path, options);
  for (int i = 0; i < 40; ++i) encoder.AddFrame(Pattern(64, 48, i));
  encoder.FinishPartial();
  encoder.Finish();  // after FinishPartial: nothing
  EXPECT_FALSE(std::filesystem::exists(path)) << "an incomplete film never takes the final name";
  const VideoInfo info = ProbeVideo(PartialPath(path));
  EXPECT_EQ(info.codec, "h264");
  EXPECT_EQ(info.frames, 40);  // every frame, the encoder flushed
}

// SIGKILL gives no chance to finish: the fragmented partial film must play as it is, up to
// the frames the encoder had released (x264 holds a few back for its look-ahead).
TEST(VideoEncoder, PartialFilmPlaysAfterSigkill) {
  const std::string path = TempDir() + "/killed.mp4";
  std::filesystem::remove(PartialPath(path));
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    VideoOptions options;
    options.width = 64;
    options.height = 48;
    options.preset = "ultrafast";
    VideoEncoder encoder(path, options);
    for (int i = 0; i < 120; ++i) encoder.AddFrame(Pattern(64, 48, i));
    raise(SIGKILL);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
  EXPECT_FALSE(std::filesystem::exists(path));
  const VideoInfo info = ProbeVideo(PartialPath(path));
  EXPECT_EQ(info.codec, "h264");
  // ultrafast has no look-ahead to speak of: nearly every frame is there.
  EXPECT_GE(info.frames, 100);
  EXPECT_LE(info.frames, 120);
}

TEST(VideoEncoder, RejectsBadOptionsAndFrames) {
  VideoOptions odd;
  odd.width = 321;
  odd.height = 240;
  EXPECT_THROW(VideoEncoder(TempDir() + "/odd.mp4", odd), Error);
  VideoOptions bad_preset;
  bad_preset.width = 64;
  bad_preset.height = 64;
  bad_preset.preset = "no-such-preset";
  EXPECT_THROW(VideoEncoder(TempDir() + "/preset.mp4", bad_preset), Error);
  VideoOptions ok;
  ok.width = 64;
  ok.height = 64;
  ok.preset = "ultrafast";
  VideoEncoder encoder(TempDir() + "/size.mp4", ok);
  EXPECT_THROW(encoder.AddFrame(Pattern(32, 32, 0)), Error);
  EXPECT_THROW(VideoEncoder("/nonexistent_dir_cablefilm/film.mp4", ok), Error);
}

}  // namespace
}  // namespace cablefilm
