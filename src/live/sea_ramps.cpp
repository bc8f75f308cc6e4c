#include "live/sea_ramps.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {
namespace {

// The target [rad] a heading of `degrees` gives a schedule now at `target`: the same direction,
// reached the short way round (at most half a turn either way).
double NearestHeading(double target, double degrees) {
  return target + std::remainder(degrees * kDegree - target, 2.0 * M_PI);
}

double OneWavePeriod(double period) {
  return std::clamp(period, kShortestMotionRamp, kLongestMotionRamp);
}

}  // namespace

bool RampCurrent(Inputs& in, double t, double current) {
  return in.current.Change(t, current, kSeaCurrentRamp);
}

bool RampCurrentHeading(Inputs& in, double t, double degrees) {
  if (!std::isfinite(degrees)) return false;
  SmoothSchedule& s = in.current_heading;
  return s.Change(t, NearestHeading(s.target(), degrees), kSeaCurrentRamp);
}

bool RampWaveHeight(Inputs& in, double t, double height, double period_now) {
  return in.wave_height.Change(t, height, OneWavePeriod(period_now));
}

bool RampWavePeriod(Inputs& in, double t, double period, double* ramp) {
  const double r = OneWavePeriod(in.wave_period.ValueAt(t));
  if (ramp) *ramp = r;
  return in.wave_period.Change(t, period, r);
}

bool RampWaveHeading(Inputs& in, double t, double degrees) {
  if (!std::isfinite(degrees)) return false;
  SmoothSchedule& s = in.wave_heading;
  return s.Change(t, NearestHeading(s.target(), degrees), OneWavePeriod(in.wave_period.ValueAt(t)));
}

void SeaTargetsOf(const Inputs& in, SeaTargets* s) {
  s->current = in.current.target();
  s->current_heading = in.current_heading.target() / kDegree;
  s->wave_height = in.wave_height.target();
  s->wave_period = in.wave_period.target();
  s->wave_heading = in.wave_heading.target() / kDegree;
  s->offset_x = in.offset_x.target();
  s->offset_z = in.offset_z.target();
}

void RetireRamps(Inputs& in, double t) {
  for (SmoothSchedule* s : {&in.end_scale, &in.end_clock, &in.current, &in.current_heading,
                            &in.wave_height, &in.wave_period, &in.wave_heading, &in.offset_x,
                            &in.offset_z})
    s->Retire(t);
}

}  // namespace cablefilm
