#pragma once
// H.264 in MP4 through libavcodec/libavformat, in process, following the send-frame /
// receive-packet loop of FFmpeg's doc/examples/mux.c. RGBA frames are converted to yuv420p
// (BT.709, limited range) with libswscale, only where they changed when the caller says where
// (yuv_converter.h). Until Finish() the film is a fragmented MP4 under a ".partial.mp4" name,
// which plays up to its last frame whatever stops the program; Finish() remuxes it to its
// final name with the moov atom at the start (+faststart) so it streams.
// Not thread-safe: one thread feeds one encoder.
#include <memory>
#include <string>
#include <vector>

#include "encode/image.h"

namespace cablefilm {

struct VideoOptions {
  int width = 1920, height = 1080;  // must be even (yuv420p)
  double fps = 30;                  // frames per second of film
  int crf = 20;                     // x264 constant rate factor: 0 lossless .. 51 worst; ~18-23 good
  std::string preset = "veryfast";  // x264 preset: ultrafast .. placebo
  std::string codec = "libx264";    // encoder name
  int threads = 0;                  // encoder threads, 0 = automatic
};

class VideoEncoder {
 public:
  // Opens the encoder and the temporary output beside `path`. Throws Error on any failure.
  VideoEncoder(const std::string& path, const VideoOptions& options);
  ~VideoEncoder();  // without Finish(): abandons the temporary file (no partial film.mp4)
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // Encodes one frame; its size must match the options. Frames get consecutive timestamps.
  // With `changed`, the frame differs from the one added before only within those rectangles
  // (the renderer redrew only them): only there is it converted to yuv420p again.
  void AddFrame(const Image& image, const std::vector<ImageRect>* changed = nullptr);
  // Flushes the encoder (null frame), closes the partial film and remuxes it into the final
  // one (index first). Idempotent. With no frame added it still writes a valid (empty) file.
  void Finish();
  // For a film that will not be complete (interrupted, failed): closes it under its partial
  // name (partial_path()), where it plays. Idempotent; nothing after it.
  void FinishPartial();

  long frames_added() const;
  const std::string& path() const;
  // Where the film is written until Finish(): "film.mp4" -> "film.partial.mp4", a fragmented
  // MP4 (a fragment per frame) that plays up to its last frame whatever stops the program.
  const std::string& partial_path() const;

 private:
  void Close();  // flushes and closes the partial film
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// What a film file holds, read back with libavformat (tests, checks).
// "film.mp4" -> "film.partial.mp4": the name of a film that is not (yet) whole.
std::string PartialPath(const std::string& path);

struct VideoInfo {
  std::string codec;         // e.g. "h264"
  std::string pixel_format;  // e.g. "yuv420p"
  int width = 0, height = 0;
  long frames = 0;           // counted by demuxing every packet
  double duration = 0;       // seconds (stream duration, else container duration)
  double fps = 0;            // average frame rate
  long long moov_offset = -1;  // byte offset of the 'moov' atom (faststart puts it before 'mdat')
  long long mdat_offset = -1;
};
VideoInfo ProbeVideo(const std::string& path);

}  // namespace cablefilm
