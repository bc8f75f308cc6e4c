#pragma once
// The film a live session records while it is watched (the page's Record button): one frame
// per simulation step it covers (speed/fps of simulated time each, so it plays at the pace it
// was watched: at 1x, the simulated time), from the step of its first picture to the one at
// which it was stopped; each frame shows the newest picture drawn at or before its step. Its
// length thus follows the steps, not the render thread: however many states that thread skips
// (it draws only the newest) or however late it draws the last, no frame is missing, only
// pictures are repeated. Owned by the render thread.
#include <cstdint>
#include <memory>
#include <string>

#include "encode/image.h"
#include "encode/video_encoder.h"

namespace cablefilm {

class LiveRecorder {
 public:
  struct Film {
    std::string name, path;
    long frames = 0;
    double t_start = 0, t_end = 0;  // the simulated time it covers [s]
  };

  bool recording() const { return video_ != nullptr; }
  // A film into out_dir/live-<date>-<time>.mp4 of width x height at fps, from simulated time t
  // [s] and simulation step `step`. Throws on an encoder's or the folder's error.
  void Start(const std::string& out_dir, int width, int height, double fps, double t,
             std::uint64_t step);
  // The picture drawn at `step`: the steps since the last picture show that one; this one
  // shows from its own step on (a redraw with no step between has its frame written already).
  void Add(const Image& picture, std::uint64_t step);
  // Ends the film at `end_step` and time `t_end` [s] (the steps after the last picture show
  // it); returns it. Throws on the encoder's error (the film then closed as it is).
  Film Finish(std::uint64_t end_step, double t_end);

 private:
  std::unique_ptr<VideoEncoder> video_;
  Film film_;
  std::uint64_t first_step_ = 0;
  Image last_;  // the newest picture added (empty: none yet)
};

}  // namespace cablefilm
