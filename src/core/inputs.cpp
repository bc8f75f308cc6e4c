#include "core/inputs.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {

Inputs SceneInputs(const Model& m) { return SceneInputs(m.lines.front()); }

double HeadingOf(const Vec& direction) { return std::atan2(direction[2], direction[0]); }

Inputs SceneInputs(const LineModel& m) {
  Inputs in;
  in.current = SmoothSchedule(m.env.current);
  in.current_heading = SmoothSchedule(HeadingOf(m.env.current_direction));
  in.wave_height = SmoothSchedule(m.env.wave.spec.height);
  in.wave_period = SmoothSchedule(m.has_waves() ? m.env.wave.spec.period : 0.0);
  in.wave_heading = SmoothSchedule(m.env.wave.spec.heading);
  return in;
}

Water SceneWater(const LineModel& m, double current_scale) {
  Water w;
  w.current = m.env.current;
  w.current_scale = current_scale;
  w.current_direction = m.env.current_direction;
  if (const CurrentHistory* h = m.env.current_history.get()) {  // as at t = 0
    w.current_scale *= h->FactorAt(0.0);
    w.current_direction = Horizontal(h->HeadingAt(0.0));
  }
  w.wave = m.env.wave;
  return w;
}

void UpdateWater(const LineModel& m, const Inputs& in, double t, Water* water) {
  water->current = in.current.ValueAt(t);
  water->current_scale = in.current_scale;
  // The scene's direction exactly while the heading is the scene's (no round trip through an
  // angle), else the heading's.
  const double heading = in.current_heading.ValueAt(t);
  water->current_direction = in.current_heading.constant() &&
                                     heading == HeadingOf(m.env.current_direction)
                                 ? m.env.current_direction
                                 : Horizontal(heading);
  if (const CurrentHistory* h = m.env.current_history.get()) {  // the table's at t
    water->current_scale *= h->FactorAt(t);
    water->current_direction = Horizontal(h->HeadingAt(t));
  }
  if (!m.has_waves()) return;
  Wave& wave = water->wave;
  const WaveSpec& scene = m.env.wave.spec;
  const bool as_scene = in.wave_height.constant() && in.wave_period.constant() &&
                        in.wave_heading.constant() && in.wave_height.target() == scene.height &&
                        in.wave_period.target() == scene.period &&
                        in.wave_heading.target() == scene.heading;
  if (as_scene && wave.spec.height == scene.height && wave.spec.period == scene.period &&
      wave.spec.heading == scene.heading)
    return;  // the scene's wave, as it was (its phase too)
  if (wave.irregular()) {
    // An irregular sea: a new height scales every component (Hs); its spectrum's shape, period
    // and heading stay the scene's.
    const double hs = in.wave_height.ValueAt(t);
    wave.spec.height = hs;
    wave.amplitude = 0.5 * hs;
    wave.sea_scale = scene.height > 0 ? hs / scene.height : 0.0;
    return;
  }
  const double period = in.wave_period.ValueAt(t), heading_now = in.wave_heading.ValueAt(t);
  if (period != wave.spec.period || heading_now != wave.spec.heading) {
    // theta = k e . x - omega t + phase kept at the phase point: the new phase takes up the old
    // theta there.
    const Vec& p = in.wave_phase_point;
    const double theta = wave.k * wave.direction.dot(p) - wave.omega * t + wave.spec.phase;
    WaveSpec spec = wave.spec;
    spec.period = period;
    spec.heading = heading_now;
    wave = MakeWave(spec, m.env.gravity);
    wave.spec.phase =
        std::remainder(theta - wave.k * wave.direction.dot(p) + wave.omega * t, 2.0 * M_PI);
  }
  // At most Miche's breaking height at this period: a higher wave would break.
  wave.spec.height = std::min(in.wave_height.ValueAt(t), wave.breaking_height());
  wave.amplitude = 0.5 * wave.spec.height;
}

Vec WaterVelocityAt(const LineModel& m, const Water& w, const Vec& position, double t) {
  Vec u = CurrentAt(m, w, position[kVertical]);
  if (m.has_waves()) u += KinematicsAt(w.wave, position, t).velocity;
  return u;
}

bool HasCurrent(const LineModel& m, const Water& w) {
  const CurrentProfile& p = m.env.current_profile;
  const double c = w.current * w.current_scale;
  if (c != 0 && p.empty()) return true;
  for (double v : p.speed)
    if (c + v * w.current_scale != 0) return true;
  return false;
}

double MaxCurrent(const LineModel& m, const Water& w) {
  // c + profile(y) is piecewise linear in y: its extremes are at the points.
  const CurrentProfile& p = m.env.current_profile;
  const double c0 = w.current * w.current_scale;
  double c = p.empty() ? std::abs(c0) : 0.0;
  for (double v : p.speed) c = std::max(c, std::abs(c0 + v * w.current_scale));
  return c;
}

namespace {

// A prescribed end as the inputs move it, order 0, 1 or 2: the scene's motion (its amplitude
// and clock scaled) and, for an end a vessel carries, the vessel's offset (its rate and its
// second derivative for the velocity and acceleration: the ramps keep them continuous).
Vec EndMotionAt(const LineModel& m, const Inputs& in, int j, double t, int order) {
  const EndMotion& e = m.end_motion(j);
  Vec x = e.Evaluate(t, order, in.end_scale, in.end_clock);
  if (!e.carried()) return x;
  const SmoothSchedule::Value ox = in.offset_x.At(t), oz = in.offset_z.At(t);
  const double dx[3] = {ox.value, ox.rate, ox.rate2}, dz[3] = {oz.value, oz.rate, oz.rate2};
  return x + Vec(dx[order], 0.0, dz[order]);
}

}  // namespace

Vec EndPosition(const LineModel& m, const Inputs& in, int j, double t) {
  return EndMotionAt(m, in, j, t, 0);
}

Vec EndVelocity(const LineModel& m, const Inputs& in, int j, double t) {
  return EndMotionAt(m, in, j, t, 1);
}

Vec EndAcceleration(const LineModel& m, const Inputs& in, int j, double t) {
  return EndMotionAt(m, in, j, t, 2);
}

}  // namespace cablefilm
