#include "core/inputs.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {

Inputs SceneInputs(const Model& m) {
  Inputs in;
  in.current = SmoothSchedule(m.env.current);
  in.wave_height = SmoothSchedule(m.env.wave.spec.height);
  in.wave_period = SmoothSchedule(m.has_waves() ? m.env.wave.spec.period : 0.0);
  return in;
}

Water SceneWater(const Model& m, double current_scale) {
  Water w;
  w.current = m.env.current;
  w.current_scale = current_scale;
  w.wave = m.env.wave;
  return w;
}

void UpdateWater(const Model& m, const Inputs& in, double t, Water* water) {
  water->current = in.current.ValueAt(t);
  water->current_scale = in.current_scale;
  if (!m.has_waves()) return;
  Wave& wave = water->wave;
  const bool as_scene = in.wave_height.constant() && in.wave_period.constant() &&
                        in.wave_height.target() == m.env.wave.spec.height &&
                        in.wave_period.target() == m.env.wave.spec.period;
  if (as_scene && wave.spec.height == m.env.wave.spec.height &&
      wave.spec.period == m.env.wave.spec.period)
    return;  // the scene's wave, as it was (its phase too)
  const double period = in.wave_period.ValueAt(t);
  if (period != wave.spec.period) {
    // theta = k x - omega t + phase kept at wave_phase_x: the new phase takes up the old theta.
    const double x = in.wave_phase_x;
    const double theta = wave.k * x - wave.omega * t + wave.spec.phase;
    WaveSpec spec = wave.spec;
    spec.period = period;
    wave = MakeWave(spec, m.env.gravity);
    wave.spec.phase = std::remainder(theta - wave.k * x + wave.omega * t, 2.0 * M_PI);
  }
  // At most Miche's breaking height at this period: a higher wave would break.
  wave.spec.height = std::min(in.wave_height.ValueAt(t), wave.breaking_height());
  wave.amplitude = 0.5 * wave.spec.height;
}

double CurrentAt(const Model& m, const Water& w, double y) {
  const CurrentProfile& p = m.env.current_profile;
  const double c = w.current * w.current_scale;
  return p.empty() ? c : c + p.At(y, w.current_scale);
}

double CurrentSlope(const Model& m, const Water& w, double y) {
  const CurrentProfile& p = m.env.current_profile;
  return p.empty() ? 0.0 : p.Slope(y, w.current_scale);
}

bool HasCurrent(const Model& m, const Water& w) {
  const CurrentProfile& p = m.env.current_profile;
  const double c = w.current * w.current_scale;
  if (c != 0 && p.empty()) return true;
  for (double v : p.speed)
    if (c + v * w.current_scale != 0) return true;
  return false;
}

double MaxCurrent(const Model& m, const Water& w) {
  // c + profile(y) is piecewise linear in y: its extremes are at the points.
  const CurrentProfile& p = m.env.current_profile;
  const double c0 = w.current * w.current_scale;
  double c = p.empty() ? std::abs(c0) : 0.0;
  for (double v : p.speed) c = std::max(c, std::abs(c0 + v * w.current_scale));
  return c;
}

Vec EndPosition(const Model& m, const Inputs& in, int j, double t) {
  return m.end_motion(j).Evaluate(t, 0, in.end_scale, in.end_clock);
}

Vec EndVelocity(const Model& m, const Inputs& in, int j, double t) {
  return m.end_motion(j).Evaluate(t, 1, in.end_scale, in.end_clock);
}

Vec EndAcceleration(const Model& m, const Inputs& in, int j, double t) {
  return m.end_motion(j).Evaluate(t, 2, in.end_scale, in.end_clock);
}

}  // namespace cablefilm
