#include "live/live_simulation.h"

#include <algorithm>
#include <cmath>

#include "app/simulation_run.h"
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
  Restart();
}

void LiveSimulation::Restart() {
  model_ = scene_model_;
  state_ = initial_;
  scale_ = SmoothSchedule(1);
  rate_ = SmoothSchedule(1);
  current_ = SmoothSchedule(scene_sea_.current);
  wave_height_ = SmoothSchedule(scene_sea_.wave_height);
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
  return s;
}

double LiveSimulation::current_now() const { return current_.ValueAt(state_.t); }
double LiveSimulation::wave_height_now() const { return wave_height_.ValueAt(state_.t); }

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
    if (model_.has_waves()) {  // likewise the waves' height (the scene's exactly when unchanged)
      model_.wave.spec.height = wave_height_.ValueAt(state_.t + 0.5 * dt);
      model_.wave.amplitude = 0.5 * model_.wave.spec.height;
    }
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
  if (retired) ApplyModulation();
}

}  // namespace cablefilm
