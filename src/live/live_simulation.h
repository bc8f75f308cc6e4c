#pragma once
// A scene's cable stepped on demand while the sea is changed between steps: the physics half of
// the live view (no threads, no clock, no pictures). The driven end's amplitude and period and
// the current are ramped along SmoothSchedule, so a change never jumps the prescribed end's
// position, velocity or acceleration, and the current never jumps either.
#include <Eigen/Core>
#include <memory>

#include "core/cable_model.h"
#include "core/cable_state.h"
#include "core/integrator.h"
#include "run/simulation_run.h"
#include "core/smooth_schedule.h"
#include "scene/scene_def.h"

namespace cablefilm {

struct SeaTargets {
  double amplitude_scale = 1;  // times the scene's end-motion amplitudes
  double period = 0;           // of the driven end [s]; 0 when no end is driven
  double current = 0;          // c [m/s] along +x
  double wave_height = 0;      // H [m] of the scene's [waves]; 0 without
  double wave_period = 0;      // T [s] of the scene's [waves]; 0 without
};

class LiveSimulation {
 public:
  // Builds the model and its static equilibrium (the initial state). Throws Error.
  explicit LiveSimulation(const SceneDef& scene);

  // Back to the scene's initial state and sea.
  void Restart();
  // Advances by `seconds` of simulated time, in steps of the scene's scheme (the explicit one
  // below its stability limit, the implicit one with its error control). Throws BlowUpError.
  void Advance(double seconds);

  // New targets, reached along a ramp that starts now (at t()): amplitude and period over one
  // period of the driven end (kMotionRamp at least), the current over kCurrentRamp. False when
  // too many changes are still ramping (then nothing changes; try again a moment later).
  bool SetAmplitudeScale(double scale);
  bool SetPeriod(double period);  // [s]
  bool SetCurrent(double current);  // [m/s]
  // The waves' height H [m], over one wave period (kMotionRamp to 30 s); false without waves.
  // The wave's amplitude is held over each step at its value mid-step, as the current is.
  bool SetWaveHeight(double height);
  // The waves' period T [s], over one wave period (kMotionRamp to 30 s); false without waves.
  // Each step takes the period at its middle, with the wave number of the new period and the
  // phase that keeps the wave's phase continuous at the driven end's x (where a ship would
  // see the wave change); elsewhere the crests shift as k changes. An end that follows the
  // wave (motion = "wave") changes its period along the same ramp. A wave higher than its
  // breaking height at the period of the moment is held at that height (Miche's limit).
  bool SetWavePeriod(double period);

  static constexpr double kMotionRamp = 2.0;   // shortest amplitude/period ramp [s]
  static constexpr double kCurrentRamp = 5.0;  // current ramp [s]

  double t() const { return state_.t; }
  const CableState& state() const { return state_; }
  const Eigen::VectorXd& tensions() const { return integrator_->tensions(); }
  const CableModel& model() const { return model_; }
  const CableState& initial_state() const { return initial_; }
  const Eigen::VectorXd& initial_tensions() const { return initial_tension_; }
  const SeaTargets& scene_sea() const { return scene_sea_; }
  SeaTargets targets() const;  // what the sea is ramping to
  double current_now() const;  // the current acting now [m/s]
  double wave_height_now() const;  // H acting now [m]
  double wave_period_now() const;  // T acting now [s]
  bool has_driven_end() const { return base_period_ > 0; }
  bool end_follows_wave() const { return end_follows_wave_; }  // set once, at construction
  IntegratorStats stats() const { return integrator_->stats(); }

 private:
  void ApplyModulation();
  void UpdateWave(double t);  // the wave's height, period and phase at time t [s]
  double MotionRamp() const;  // [s]

  const CableModel scene_model_;  // as built from the scene
  CableModel model_;              // the one stepped: its ends modulated, its current ramped
  TimeGrid grid_;                 // the scene's scheme and step rule
  IntegratorKind kind_;
  double fixed_step_ = 0;         // [s]; 0: the scheme chooses (adaptive or internal split)
  std::unique_ptr<Integrator> integrator_;
  CableState initial_, state_;
  Eigen::VectorXd initial_tension_;
  SeaTargets scene_sea_;
  double base_period_ = 0;        // the driven end's period in the scene [s]
  double wave_x_ = 0;             // where a period change keeps the wave's phase [m]
  bool end_follows_wave_ = false; // the driven end's motion is the wave's (motion = "wave")
  SmoothSchedule scale_{1}, rate_{1}, current_{0}, wave_height_{0}, wave_period_{0};
};

}  // namespace cablefilm
