#include "view/live_history.h"

#include <algorithm>
#include <cmath>

#include "view/cable_panel.h"
#include "view/plot_layout.h"

namespace cablefilm {
namespace {

constexpr double kRangeHeadroom = 1.05;  // the range ends 5 % above the largest tension seen
constexpr double kBoxPad = 0.04;         // of the box's larger side, on every side
constexpr double kBoxShrink = 0.02;      // fraction of the excess given back per frame

}  // namespace

LiveHistory::LiveHistory(LiveScenery scenery) : scenery_(std::move(scenery)) { Reset(); }

void LiveHistory::Reset() {
  has_frame_ = false;
  times_.clear();
  max_tension_.clear();
  markers_.clear();
  const std::size_t links = scenery_.arc_length.size() - 1;
  link_min_.assign(links, 0);
  link_max_.assign(links, 0);
  paths_.assign(scenery_.moving_ends.size(), {});
  peak_ = peak_t_ = 0;
  peak_link_ = 0;
  const auto& eq = scenery_.equilibrium;
  if (!locked_) {
    range_lo_ = 0;
    range_hi_ = 1;
    if (!eq.tension.empty()) GrowRange(*std::min_element(eq.tension.begin(), eq.tension.end()),
                                       *std::max_element(eq.tension.begin(), eq.tension.end()));
  }
  Eigen::Matrix2Xd x(2, eq.x.size());
  for (std::size_t j = 0; j < eq.x.size(); ++j) x.col(j) << eq.x[j], eq.y[j];
  box_[0] = box_[2] = union_box_[0] = union_box_[2] = INFINITY;
  box_[1] = box_[3] = union_box_[1] = union_box_[3] = -INFINITY;
  if (x.cols() > 0) FollowBox(x);
}

void LiveHistory::GrowRange(double lo, double hi) {
  if (locked_) return;
  double new_lo = std::min({0.0, range_lo_, lo});
  double new_hi = std::max(range_hi_, kRangeHeadroom * hi);
  if (new_lo == range_lo_ && new_hi == range_hi_) return;
  // Nice ends, so the colour bar's ticks do not crawl as the range grows.
  NiceRange(&new_lo, &new_hi, 6);
  range_lo_ = new_lo;
  range_hi_ = new_hi;
}

void LiveHistory::FollowBox(const Eigen::Matrix2Xd& x) {
  double lo_x = x.row(0).minCoeff(), hi_x = x.row(0).maxCoeff();
  double lo_y = x.row(1).minCoeff(), hi_y = x.row(1).maxCoeff();
  for (const auto& path : paths_)
    for (const Vec2f& p : path) {
      lo_x = std::min<double>(lo_x, p.x);
      hi_x = std::max<double>(hi_x, p.x);
      lo_y = std::min<double>(lo_y, p.y);
      hi_y = std::max<double>(hi_y, p.y);
    }
  const double pad = kBoxPad * std::max({hi_x - lo_x, hi_y - lo_y, 1e-3});
  const double want[4] = {lo_x - pad, hi_x + pad, lo_y - pad, hi_y + pad};
  for (int i = 0; i < 4; ++i) {
    const bool is_min = i % 2 == 0;
    const bool outside = is_min ? want[i] < box_[i] : want[i] > box_[i];
    if (!std::isfinite(box_[i]) || outside)
      box_[i] = want[i];  // grow at once: the cable never leaves the picture
    else
      box_[i] += kBoxShrink * (want[i] - box_[i]);  // shrink slowly
    union_box_[i] = is_min ? std::min(union_box_[i], box_[i]) : std::max(union_box_[i], box_[i]);
  }
}

void LiveHistory::Add(double t, const Eigen::Matrix2Xd& x, const Eigen::VectorXd& tension) {
  const Eigen::Index links = tension.size();
  now_.t = t;
  now_.x.resize(x.cols());
  now_.y.resize(x.cols());
  for (Eigen::Index j = 0; j < x.cols(); ++j) {
    now_.x[j] = x(0, j);
    now_.y[j] = x(1, j);
  }
  now_.tension.assign(tension.data(), tension.data() + links);
  Eigen::Index link = 0;
  const double tmax = links ? tension.maxCoeff(&link) : 0;
  const double tmin = links ? tension.minCoeff() : 0;
  for (Eigen::Index j = 0; j < links && static_cast<std::size_t>(j) < link_min_.size(); ++j) {
    link_min_[j] = has_frame_ ? std::min(link_min_[j], tension[j]) : tension[j];
    link_max_[j] = has_frame_ ? std::max(link_max_[j], tension[j]) : tension[j];
  }
  if (!has_frame_ || tmax > peak_) {
    peak_ = tmax;
    peak_t_ = t;
    peak_link_ = static_cast<int>(link);
  }
  has_frame_ = true;
  times_.push_back(t);
  max_tension_.push_back(tmax);
  // The rolling window: drop what scrolled out (and, at absurd frame rates, the oldest).
  const double keep_from = t - scenery_.window;
  while (!times_.empty() && (times_.front() < keep_from || times_.size() > kMaxTracePoints)) {
    times_.pop_front();
    max_tension_.pop_front();
  }
  while (!markers_.empty() && markers_.front().t < keep_from) markers_.pop_front();
  for (std::size_t e = 0; e < paths_.size(); ++e) {
    const int j = scenery_.moving_ends[e];
    const Vec2f p{static_cast<float>(x(0, j)), static_cast<float>(x(1, j))};
    paths_[e].push_back(p);
    // About one period of a typical motion at 30 frames/s and more: enough to show the orbit.
    if (paths_[e].size() > kMaxPathPoints) paths_[e].pop_front();
  }
  GrowRange(tmin, tmax);
  FollowBox(x);
  if (scenery_.waves)  // a box's width beyond it on either side (the storage reused)
    SurfaceProfile(scenery_.wave, t, 2 * box_[0] - box_[1], 2 * box_[1] - box_[0], now_.surface_x,
                   now_.surface_y);
}

void LiveHistory::AddMarker(double t, std::string label) {
  markers_.push_back({t, std::move(label)});
  while (markers_.size() > 256) markers_.pop_front();
}

void LiveHistory::LockRange(bool locked) {
  locked_ = locked;
  if (!locked && has_frame_) {
    const double lo = *std::min_element(now_.tension.begin(), now_.tension.end());
    GrowRange(std::min(lo, peak_), peak_);
  }
}

void LiveHistory::ResetRange() {
  locked_ = false;
  range_lo_ = 0;
  range_hi_ = 1;
  const std::vector<double>& T = has_frame_ ? now_.tension : scenery_.equilibrium.tension;
  if (!T.empty()) GrowRange(*std::min_element(T.begin(), T.end()), *std::max_element(T.begin(), T.end()));
}

void LiveHistory::SetRange(double lo, double hi) {
  range_lo_ = lo;
  range_hi_ = hi;
  locked_ = true;
}

LiveFrameInput LiveHistory::MakeInput(const std::string& status) const {
  LiveFrameInput in;
  in.title = scenery_.title;
  in.status = status;
  in.snapshot = has_frame_ ? now_ : scenery_.equilibrium;
  in.arc_length = scenery_.arc_length;
  in.section_boundaries = scenery_.section_boundaries;
  in.section_names = scenery_.section_names;
  in.weight_stations = scenery_.weight_stations;
  in.moving_ends = scenery_.moving_ends;
  in.fixed_ends = scenery_.fixed_ends;
  in.free_ends = scenery_.free_ends;
  in.equilibrium = scenery_.equilibrium;
  in.reference_label = scenery_.reference_label;
  in.tension_min = range_lo_;
  in.tension_max = range_hi_;
  in.range_locked = locked_;
  in.x_min = box_[0];
  in.x_max = box_[1];
  in.y_min = box_[2];
  in.y_max = box_[3];
  in.seabed = scenery_.seabed;
  in.seabed_y = scenery_.seabed_y;
  if (in.seabed)  // the bed in view, with a strip of ground below it
    in.y_min = std::min(in.y_min, in.seabed_y - SeabedMargin(in.y_max - in.y_min));
  in.surface = scenery_.waves;
  if (in.surface) {  // the surface in view, up to its crests
    const double crest = scenery_.wave.spec.surface_y + scenery_.wave.amplitude;
    in.y_max = std::max(in.y_max, crest + SeabedMargin(crest - in.y_min));
  }
  // The panels are shaped by the box over the whole run so far, so they do not move as the
  // cable swings.
  in.layout_aspect = (union_box_[1] - union_box_[0]) / std::max(union_box_[3] - union_box_[2], 1e-9);
  const double t = in.snapshot.t;
  in.window_start = std::max(0.0, t - scenery_.window);
  in.window_end = std::max(scenery_.window, t);
  in.times.assign(times_.begin(), times_.end());
  in.max_tension.assign(max_tension_.begin(), max_tension_.end());
  if (has_frame_) {
    in.link_min = link_min_;
    in.link_max = link_max_;
  }
  for (const auto& path : paths_) in.end_paths.emplace_back(path.begin(), path.end());
  in.markers.assign(markers_.begin(), markers_.end());
  in.peak = peak_;
  in.peak_t = peak_t_;
  in.peak_link = peak_link_;
  return in;
}

}  // namespace cablefilm
