#include "live/live_recorder.h"

#include <ctime>
#include <filesystem>

namespace cablefilm {

void LiveRecorder::Start(const std::string& out_dir, int width, int height, double fps, double t,
                         std::uint64_t step) {
  char stamp[32];
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  localtime_r(&now, &tm);
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
  Film film{std::string("live-") + stamp + ".mp4", "", 0, t, t};
  film.path = out_dir + "/" + film.name;
  std::filesystem::create_directories(out_dir);
  VideoOptions vo;
  vo.width = width;
  vo.height = height;
  vo.fps = fps;
  vo.threads = 1;  // the machine's cores belong to the simulation and the viewers
  video_ = std::make_unique<VideoEncoder>(film.path, vo);
  film_ = film;
  first_step_ = step;
  last_ = Image();
}

void LiveRecorder::Add(const Image& picture, std::uint64_t step) {
  if (!video_) return;
  const long at = static_cast<long>(step) - static_cast<long>(first_step_);
  while (video_->frames_added() < at) video_->AddFrame(last_.rgba.empty() ? picture : last_);
  if (video_->frames_added() == at) video_->AddFrame(picture);
  last_ = picture;  // its storage reused
}

LiveRecorder::Film LiveRecorder::Finish(std::uint64_t end_step, double t_end) {
  std::unique_ptr<VideoEncoder> video = std::move(video_);
  Film film = film_;
  film.t_end = t_end;
  if (!last_.rgba.empty())
    while (video->frames_added() <= static_cast<long>(end_step) - static_cast<long>(first_step_))
      video->AddFrame(last_);
  last_ = Image();
  video->Finish();
  film.frames = video->frames_added();
  return film;
}

}  // namespace cablefilm
