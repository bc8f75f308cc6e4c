#include "live/live_simulation.h"

#include <algorithm>
#include <cmath>

#include "run/simulation_run.h"
#include "scene/build_model.h"

namespace cablefilm {
namespace {

// The end whose period the controls show: the far end if it moves, else the start.
const EndMotion* DrivenEnd(const CableModel& m) {
  if (m.end.moves()) return &m.end;
  if (m.start.moves()) return &m.start;
  return nullptr;
}

}  // namespace

LiveSimulation::LiveSimulation(const SceneDef& scene)
    : scene_model_(BuildModel(scene)), model_(scene_model_) {
  // The scene's own scheme and step rule; the output interval only bounds the implicit step.
  grid_ = ChooseTimeGrid(scene_model_, scene.simulation, 1.0 / 30);
  const TimeGrid& grid = grid_;
  kind_ = grid.kind;
  if (grid.kind == IntegratorKind::kExplicit)
    fixed_step_ = grid.automatic ? grid.safety_factor * grid.limit.time_step
                                 : scene.simulation.time_step;
  else if (!grid.automatic)
    fixed_step_ = scene.simulation.time_step;
  integrator_ = MakeIntegrator(scene_model_, grid);
  EquilibriumReport report;
  initial_ = MakeInitialState(scene, scene_model_, &report);
  integrator_->Initialize(scene_model_, initial_);
  initial_tension_ = integrator_->tensions();
  if (const EndMotion* e = DrivenEnd(scene_model_)) base_period_ = e->period();
  scene_sea_.period = base_period_;
  scene_sea_.current = scene_model_.current;
  scene_sea_.wave_height = scene_model_.has_waves() ? scene_model_.wave.spec.height : 0.0;
  scene_sea_.wave_period = scene_model_.has_waves() ? scene_model_.wave.spec.period : 0.0;
  // The wave's phase is kept where the driven end is (else mid-way between the ends).
  const int last = scene_model_.links;
  wave_x_ = scene_model_.end.moves()     ? initial_.x(0, last)
            : scene_model_.start.moves() ? initial_.x(0, 0)
                                         : 0.5 * (initial_.x(0, 0) + initial_.x(0, last));
  end_follows_wave_ = (scene_model_.end.moves() && scene.end.follows_wave) ||
                      (!scene_model_.end.moves() && scene_model_.start.moves() &&
                       scene.start.follows_wave);
  Restart();
}

void LiveSimulation::Restart() {
  model_ = scene_model_;
  state_ = initial_;
  scale_ = SmoothSchedule(1);
  rate_ = SmoothSchedule(1);
  current_ = SmoothSchedule(scene_sea_.current);
  wave_height_ = SmoothSchedule(scene_sea_.wave_height);
  wave_period_ = SmoothSchedule(scene_sea_.wave_period);
  if (has_driven_end()) ApplyModulation();
  // A new integrator: an adaptive one would otherwise keep the step size it had reached.
  integrator_ = MakeIntegrator(model_, grid_);
  integrator_->Initialize(model_, state_);
}

SeaTargets LiveSimulation::targets() const {
  SeaTargets s;
  s.amplitude_scale = scale_.target();
  s.period = has_driven_end() ? base_period_ / rate_.target() : 0;
  s.current = current_.target();
  s.wave_height = wave_height_.target();
  s.wave_period = wave_period_.target();
  return s;
}

double LiveSimulation::current_now() const { return current_.ValueAt(state_.t); }
double LiveSimulation::wave_height_now() const { return wave_height_.ValueAt(state_.t); }
double LiveSimulation::wave_period_now() const { return wave_period_.ValueAt(state_.t); }

double LiveSimulation::MotionRamp() const {
  // One period of the motion as it is now: the change takes a cycle, as a ship's would.
  const double period = base_period_ / rate_.ValueAt(state_.t);
  return std::clamp(period, kMotionRamp, 30.0);
}

void LiveSimulation::ApplyModulation() {
  if (model_.start.moves()) model_.start.Modulate(scale_, rate_);
  if (model_.end.moves()) model_.end.Modulate(scale_, rate_);
}

bool LiveSimulation::SetAmplitudeScale(double scale) {
  if (!has_driven_end()) return false;
  if (!scale_.Change(state_.t, scale, MotionRamp())) return false;
  ApplyModulation();
  return true;
}

bool LiveSimulation::SetPeriod(double period) {
  if (!has_driven_end() || !(period > 0)) return false;
  if (!rate_.Change(state_.t, base_period_ / period, MotionRamp())) return false;
  ApplyModulation();
  return true;
}

bool LiveSimulation::SetCurrent(double current) {
  return current_.Change(state_.t, current, kCurrentRamp);
}

bool LiveSimulation::SetWaveHeight(double height) {
  if (!model_.has_waves() || !(height >= 0)) return false;
  const double ramp = std::clamp(model_.wave.spec.period, kMotionRamp, 30.0);
  return wave_height_.Change(state_.t, height, ramp);
}

bool LiveSimulation::SetWavePeriod(double period) {
  if (!model_.has_waves() || !(period > 0)) return false;
  const double ramp = std::clamp(wave_period_.ValueAt(state_.t), kMotionRamp, 30.0);
  if (!wave_period_.Change(state_.t, period, ramp)) return false;
  // The end that follows the wave: the same ramp of its clock (its rate is base / period).
  if (end_follows_wave_ && has_driven_end() && rate_.Change(state_.t, base_period_ / period, ramp))
    ApplyModulation();
  return true;
}

void LiveSimulation::UpdateWave(double t) {
  Wave& wave = model_.wave;
  const double period = wave_period_.ValueAt(t);
  if (period != wave.spec.period) {
    // theta = k x - omega t + phase kept at wave_x_: the new phase takes up the old theta there.
    const double theta = wave.k * wave_x_ - wave.omega * t + wave.spec.phase;
    WaveSpec spec = wave.spec;
    spec.period = period;
    wave = MakeWave(spec, model_.gravity);
    wave.spec.phase = std::remainder(theta - wave.k * wave_x_ + wave.omega * t, 2.0 * M_PI);
  }
  // At most Miche's breaking height at this period: a higher wave would break.
  wave.spec.height = std::min(wave_height_.ValueAt(t), wave.breaking_height());
  wave.amplitude = 0.5 * wave.spec.height;
}

void LiveSimulation::Advance(double seconds) {
  if (!(seconds > 0)) return;
  const int steps =
      fixed_step_ > 0 ? std::max(1, static_cast<int>(std::ceil(seconds / fixed_step_ - 1e-9))) : 1;
  const double dt = seconds / steps;
  const double t0 = state_.t;
  for (int i = 0; i < steps; ++i) {
    // The current of each step at its middle: a ramp of kCurrentRamp spans many steps, so the
    // drag changes by small increments.
    model_.current = current_.ValueAt(state_.t + 0.5 * dt);
    // Likewise the waves' height and period (the scene's wave exactly when unchanged).
    if (model_.has_waves() && !(wave_height_.constant() && wave_period_.constant() &&
                                model_.wave.spec.height == wave_height_.target() &&
                                model_.wave.spec.period == wave_period_.target()))
      UpdateWave(state_.t + 0.5 * dt);
    integrator_->Step(model_, state_, dt);
    state_.t = t0 + (i + 1) * dt;  // no round-off drift
  }
  bool retired = false;
  for (SmoothSchedule* s : {&scale_, &rate_}) {
    const int before = s->ramping();
    s->Retire(state_.t);
    retired = retired || s->ramping() != before;
  }
  current_.Retire(state_.t);
  wave_height_.Retire(state_.t);
  wave_period_.Retire(state_.t);
  if (retired) ApplyModulation();
}

}  // namespace cablefilm
