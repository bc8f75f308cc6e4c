#include "view/history.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "view/plot_layout.h"

namespace cablefilm {
namespace {

constexpr double kRangeHeadroom = 1.05;  // following: the range ends 5 % above the largest seen
constexpr double kBoxPad = 0.04;         // following: of the box's larger side, on every side
constexpr double kBoxShrink = 0.02;      // following: of the excess given back per snapshot
constexpr double kInf = std::numeric_limits<double>::infinity();

// The smallest and largest link tension of every line (false when there is none).
bool TensionSpan(const Snapshot& s, double* lo, double* hi) {
  *lo = kInf;
  *hi = -kInf;
  for (const LineSnapshot& l : s.lines)
    for (double T : l.tension) {
      *lo = std::min(*lo, T);
      *hi = std::max(*hi, T);
    }
  return *lo <= *hi;
}

// The first index of the largest value (-1 when empty).
int ArgMax(const std::vector<double>& v) {
  return v.empty() ? -1 : static_cast<int>(std::max_element(v.begin(), v.end()) - v.begin());
}

// Drops the first n values.
template <class T>
void DropFront(std::vector<T>* v, std::size_t n) {
  v->erase(v->begin(), v->begin() + static_cast<std::ptrdiff_t>(n));
}

}  // namespace

History::History(const SceneView& scene, bool following)
    : following_(following), sea_(scene.sea) {
  CheckSceneView(scene);
  const std::size_t lines = scene.lines.size();
  initial_.lines.resize(lines);
  for (std::size_t i = 0; i < lines; ++i) {
    const LineView& line = scene.lines[i];
    stations_.push_back(line.arc_length.size());
    static_cast<LineState&>(initial_.lines[i]) = line.reference;
    for (int e : line.marks.moving_ends) end_paths_.push_back({static_cast<int>(i), e, {}});
  }
  const auto& c = scene.sea.current;
  initial_.current = Vec(c[0], c[1], c[2]);
  window_max_.resize(lines);
  sample_.resize(lines);
  sample_link_.resize(lines);
  link_min_.resize(lines);
  link_max_.resize(lines);
  path_last_.resize(end_paths_.size());
  path_seen_.resize(end_paths_.size());
}

History::History(const SceneView& scene, const FixedPolicy& policy) : History(scene, false) {
  const FixedPolicy& p = policy;
  if (!(p.tension_max > p.tension_min) || !std::isfinite(p.tension_min) ||
      !std::isfinite(p.tension_max))
    throw Error("frame: tension range must be finite and increasing, got [" +
                std::to_string(p.tension_min) + ", " + std::to_string(p.tension_max) + "] N");
  const WorldBox& b = p.box;
  if (!(b.x_max >= b.x_min) || !(b.y_max >= b.y_min) || !std::isfinite(b.x_min) ||
      !std::isfinite(b.x_max) || !std::isfinite(b.y_min) || !std::isfinite(b.y_max))
    throw Error("frame: invalid world box x [" + std::to_string(b.x_min) + ", " +
                std::to_string(b.x_max) + "], y [" + std::to_string(b.y_min) + ", " +
                std::to_string(b.y_max) + "] m");
  fixed_ = p;
  range_lo_ = p.tension_min;
  range_hi_ = p.tension_max;
  x0_ = b.x_min;
  y0_ = b.y_min;
  z0_ = b.z_min;
  cell_ = std::max({b.x_max - b.x_min, b.y_max - b.y_min, b.z_max - b.z_min, 1e-9}) / 1000;
  Reset();
}

History::History(const SceneView& scene, const FollowingPolicy& policy) : History(scene, true) {
  if (!(policy.window > 0) || !std::isfinite(policy.window))
    throw Error("frame: the time window must be finite and positive, got " +
                std::to_string(policy.window) + " s");
  follow_ = policy;
  if (sea_.surface) initial_.wave = policy.wave;
  Reset();
}

void History::Reset() {
  count_ = 0;
  const std::size_t lines = stations_.size();
  if (!following_) {
    const double d = fixed_.duration;
    const double span = d > 0 && std::isfinite(d) ? d / kTimeTraceSpans : 0;  // [s]
    trace_ = ThinnedTrace(static_cast<int>(lines), span);
  }
  window_times_.clear();
  for (auto& v : window_max_) v.clear();
  markers_.clear();
  for (std::size_t i = 0; i < lines; ++i) {
    link_min_[i].assign(stations_[i] - 1, 0);
    link_max_[i].assign(stations_[i] - 1, 0);
  }
  for (EndPath& path : end_paths_) path.pieces.clear();
  for (auto& seen : path_seen_) seen.clear();
  peaks_.assign(lines, Peak{});
  if (!following_) return;
  double lo, hi;
  if (!locked_) {
    range_lo_ = 0;
    range_hi_ = 1;
    if (TensionSpan(initial_, &lo, &hi)) GrowRange(lo, hi);
  }
  box_ = union_box_ = {kInf, -kInf, kInf, -kInf, kInf, -kInf};
  FollowBox(initial_);
}

void History::SetWave(const Wave& wave) { follow_.wave = wave; }

void History::GrowRange(double lo, double hi) {
  if (locked_) return;
  double new_lo = std::min({0.0, range_lo_, lo});
  double new_hi = std::max(range_hi_, kRangeHeadroom * hi);
  if (new_lo == range_lo_ && new_hi == range_hi_) return;
  // Nice ends, so the colour bar's ticks do not crawl as the range grows.
  NiceRange(&new_lo, &new_hi, 6);
  range_lo_ = new_lo;
  range_hi_ = new_hi;
}

void History::FollowBox(const Snapshot& s) {
  double lo_x = kInf, hi_x = -kInf, lo_y = kInf, hi_y = -kInf, lo_z = 0, hi_z = 0;
  bool space = false;  // a line with z: the box's z follows it too
  for (const LineSnapshot& l : s.lines)
    for (std::size_t j = 0; j < l.x.size(); ++j) {
      lo_x = std::min(lo_x, l.x[j]);
      hi_x = std::max(hi_x, l.x[j]);
      lo_y = std::min(lo_y, l.y[j]);
      hi_y = std::max(hi_y, l.y[j]);
      if (l.z.empty()) continue;
      lo_z = space ? std::min(lo_z, l.z[j]) : l.z[j];
      hi_z = space ? std::max(hi_z, l.z[j]) : l.z[j];
      space = true;
    }
  if (!(lo_x <= hi_x)) return;  // no positions (a scene without reference states)
  for (const EndPath& path : end_paths_)
    for (const auto& piece : path.pieces)
      for (const Vec3f& p : piece) {
        lo_x = std::min<double>(lo_x, p.x);
        hi_x = std::max<double>(hi_x, p.x);
        lo_y = std::min<double>(lo_y, p.y);
        hi_y = std::max<double>(hi_y, p.y);
        lo_z = std::min<double>(lo_z, p.z);
        hi_z = std::max<double>(hi_z, p.z);
      }
  const double pad = kBoxPad * std::max({hi_x - lo_x, hi_y - lo_y, hi_z - lo_z, 1e-3});
  // z is padded only for lines in space: in the plane the box stays at z = 0.
  const double z_pad = space ? pad : 0;
  const double want[6] = {lo_x - pad, hi_x + pad, lo_y - pad, hi_y + pad, lo_z - z_pad, hi_z + z_pad};
  double* box[6] = {&box_.x_min, &box_.x_max, &box_.y_min, &box_.y_max, &box_.z_min, &box_.z_max};
  double* all[6] = {&union_box_.x_min, &union_box_.x_max, &union_box_.y_min,
                    &union_box_.y_max, &union_box_.z_min, &union_box_.z_max};
  for (int i = 0; i < 6; ++i) {
    const bool is_min = i % 2 == 0;
    double& b = *box[i];
    const bool outside = is_min ? want[i] < b : want[i] > b;
    if (!std::isfinite(b) || outside)
      b = want[i];  // grow at once: the lines never leave the picture
    else
      b += kBoxShrink * (want[i] - b);  // shrink slowly
    *all[i] = is_min ? std::min(*all[i], b) : std::max(*all[i], b);
  }
}

void History::AddToPath(std::size_t e, Vec3f p) {
  auto& pieces = end_paths_[e].pieces;
  if (following_) {
    if (pieces.empty()) pieces.emplace_back();
    std::vector<Vec3f>& path = pieces[0];
    // Points a thousandth of the view apart (the film's grid, a pixel or two): the newest one
    // moves with the end until it is that far from the one before, so the path ends where the
    // end is. A fairlead's orbit of a metre in a view of a kilometre is a few points, not a
    // frame's each: every point is a tube's ring to draw (three ends of 4096 points each grew
    // the live server by 170 MB, most of it the rasteriser's, and cut its frames to a sixth).
    const double step = std::max({box_.x_max - box_.x_min, box_.y_max - box_.y_min,
                                  box_.z_max - box_.z_min}) / 1000;  // [m]
    if (path.size() >= 2) {
      const Vec3f& kept = path[path.size() - 2];
      const double dx = p.x - kept.x, dy = p.y - kept.y, dz = p.z - kept.z;
      if (dx * dx + dy * dy + dz * dz < step * step) {
        path.back() = p;
        return;
      }
    }
    path.push_back(p);
    // The recent orbit: at the spacing above, many periods of a typical motion.
    if (path.size() > kMaxPathPoints) DropFront(&path, 1);
    return;
  }
  if (count_ == 0) {
    path_last_[e] = p;
    return;
  }
  auto cell = [&](Vec3f q) {
    auto axis = [&](double v, double origin) {
      return static_cast<std::uint64_t>(std::clamp((v - origin) / cell_, -1e4, 1e4) + 16384);
    };
    return axis(q.x, x0_) << 32 | axis(q.y, y0_) << 16 | axis(q.z, z0_);  // 15 bits each
  };
  const std::uint64_t from = cell(path_last_[e]), to = cell(p);
  if (from == to) return;
  if (path_seen_[e].insert({std::min(from, to), std::max(from, to)}).second) {
    // A new piece unless the segment starts where the last one ended (most do).
    const Vec3f a = path_last_[e];
    const Vec3f& last = pieces.empty() ? a : pieces.back().back();
    if (pieces.empty() || last.x != a.x || last.y != a.y || last.z != a.z)
      pieces.push_back({a});
    pieces.back().push_back(p);
  }
  path_last_[e] = p;
}

void History::AddSample(double t, const double* values, const int* links) {
  if (following_) {
    window_times_.push_back(t);
    for (std::size_t i = 0; i < window_max_.size(); ++i) window_max_[i].push_back(values[i]);
  } else {
    trace_.Add(t, values);
  }
  for (std::size_t i = 0; i < peaks_.size(); ++i) {
    Peak& peak = peaks_[i];
    if (std::isnan(values[i]) || (peak.seen && !(values[i] > peak.value))) continue;
    peak = {true, values[i], t, links[i]};
  }
}

void History::Add(const Snapshot& s) {
  CheckSnapshotSizes(s, stations_);
  const std::size_t lines = stations_.size();
  for (std::size_t i = 0; i < lines; ++i) {
    const LineSnapshot& l = s.lines[i];
    const bool rows = !l.row_link_min.empty();  // sized with the links (checked)
    for (std::size_t j = 0; j < l.tension.size(); ++j) {
      const double T = l.tension[j];
      const double lo = rows ? std::min(T, l.row_link_min[j]) : T;
      const double hi = rows ? std::max(T, l.row_link_max[j]) : T;
      link_min_[i][j] = count_ == 0 ? lo : std::min(link_min_[i][j], lo);
      link_max_[i][j] = count_ == 0 ? hi : std::max(link_max_[i][j], hi);
    }
  }
  if (s.row_t.empty()) {  // the snapshot's own largest tensions, at their links
    for (std::size_t i = 0; i < lines; ++i) {
      sample_link_[i] = ArgMax(s.lines[i].tension);
      sample_[i] = s.lines[i].tension[sample_link_[i]];
    }
    AddSample(s.t, sample_.data(), sample_link_.data());
  } else {  // every output row since the previous snapshot; a row's link is its envelope's
    for (std::size_t i = 0; i < lines; ++i) sample_link_[i] = ArgMax(s.lines[i].row_link_max);
    for (std::size_t r = 0; r < s.row_t.size(); ++r) {
      for (std::size_t i = 0; i < lines; ++i) sample_[i] = s.lines[i].row_max[r];
      AddSample(s.row_t[r], sample_.data(), sample_link_.data());
    }
  }
  for (std::size_t e = 0; e < end_paths_.size(); ++e) {
    const LineSnapshot& l = s.lines[end_paths_[e].line];
    const int j = end_paths_[e].station;
    AddToPath(e, {static_cast<float>(l.x[j]), static_cast<float>(l.y[j]),
                  l.z.empty() ? 0.0f : static_cast<float>(l.z[j])});
  }
  now_ = s;
  if (following_) {
    // The rolling window: drop what scrolled out (and, at absurd rates, the oldest).
    const double keep_from = s.t - follow_.window;
    std::size_t drop = 0;
    const std::size_t n = window_times_.size();
    while (drop < n && (window_times_[drop] < keep_from || n - drop > kMaxTracePoints)) ++drop;
    DropFront(&window_times_, drop);
    for (auto& v : window_max_) DropFront(&v, drop);
    drop = 0;
    while (drop < markers_.size() && markers_[drop].t < keep_from) ++drop;
    DropFront(&markers_, drop);
    double lo, hi;
    if (TensionSpan(s, &lo, &hi)) GrowRange(lo, hi);
    FollowBox(s);
    if (sea_.surface) {
      AddWaterSurface(follow_.wave, box_, &now_);
      now_.wave = follow_.wave;
    }
  }
  ++count_;
}

void History::AddMarker(double t, std::string label) {
  markers_.push_back({t, std::move(label)});
  if (markers_.size() > kMaxMarkers) DropFront(&markers_, markers_.size() - kMaxMarkers);
}

void History::LockRange(bool locked) {
  if (!following_) return;
  locked_ = locked;
  double lo, hi;
  if (locked || count_ == 0 || !TensionSpan(now_, &lo, &hi)) return;
  double peak = hi;  // catch up with what was seen while locked
  bool seen = false;
  for (const Peak& p : peaks_)
    if (p.seen) {
      peak = seen ? std::max(peak, p.value) : p.value;
      seen = true;
    }
  GrowRange(std::min(lo, peak), peak);
}

void History::ResetRange() {
  if (!following_) return;
  locked_ = false;
  range_lo_ = 0;
  range_hi_ = 1;
  double lo, hi;
  if (TensionSpan(now(), &lo, &hi)) GrowRange(lo, hi);
}

void History::SetRange(double lo, double hi) {
  if (!following_) return;
  range_lo_ = lo;
  range_hi_ = hi;
  locked_ = true;
}

WorldBox History::box() const {
  return following_ ? ShownBox(box_, sea_, follow_.wave) : fixed_.box;
}

WorldBox History::view_box() const {
  return following_ ? ShownBox(union_box_, sea_, follow_.wave) : fixed_.box;
}

double History::layout_aspect() const {
  if (!following_) return 0;
  const WorldBox& u = union_box_;
  return (u.x_max - u.x_min) / std::max(u.y_max - u.y_min, 1e-9);
}

double History::time_min() const {
  return following_ ? std::max(0.0, now().t - follow_.window) : fixed_.start;
}

double History::time_max() const {
  if (!following_) return fixed_.start + (fixed_.duration > 0 ? fixed_.duration : 1);
  return std::max(follow_.window, now().t);
}

const std::vector<double>& History::times() const {
  return following_ ? window_times_ : trace_.times();
}

const std::vector<std::vector<double>>& History::max_tension() const {
  return following_ ? window_max_ : trace_.all_values();
}

}  // namespace cablefilm
