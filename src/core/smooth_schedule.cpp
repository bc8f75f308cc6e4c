#include "core/smooth_schedule.h"

#include <cmath>

namespace cablefilm {
namespace {

// h(u) and its derivatives in u, and its integral from 0 (H(1) = 1/2), for 0 <= u <= 1.
double H0(double u) { return u * u * u * (10 + u * (-15 + 6 * u)); }
double H1(double u) { return 30 * u * u * (1 + u * (-2 + u)); }
double H2(double u) { return 60 * u * (1 + u * (-3 + 2 * u)); }
double HInt(double u) { return u * u * u * u * (2.5 + u * (-3 + u)); }

}  // namespace

bool SmoothSchedule::Change(double t0, double target, double duration) {
  if (count_ == kMaxRamps || !(duration > 0)) return false;
  ramps_[count_++] = Ramp{t0, duration, target - target_};
  target_ = target;
  return true;
}

void SmoothSchedule::Retire(double t) {
  int kept = 0;
  for (int k = 0; k < count_; ++k) {
    const Ramp& r = ramps_[k];
    if (t >= r.t0 + r.duration) {
      // For t past the ramp its part is delta (t - t0 - duration / 2): linear, into the base.
      base_ += r.delta;
      integral_offset_ -= r.delta * (r.t0 + 0.5 * r.duration);
    } else {
      ramps_[kept++] = r;
    }
  }
  count_ = kept;
}

SmoothSchedule::Value SmoothSchedule::At(double t) const {
  Value v;
  v.value = base_;
  v.integral = base_ * t + integral_offset_;
  for (int k = 0; k < count_; ++k) {
    const Ramp& r = ramps_[k];
    const double u = (t - r.t0) / r.duration;
    if (u <= 0) continue;
    if (u >= 1) {
      v.value += r.delta;
      v.integral += r.delta * (t - r.t0 - 0.5 * r.duration);
      continue;
    }
    v.value += r.delta * H0(u);
    v.rate += r.delta * H1(u) / r.duration;
    v.rate2 += r.delta * H2(u) / (r.duration * r.duration);
    v.integral += r.delta * r.duration * HInt(u);
  }
  return v;
}

}  // namespace cablefilm
