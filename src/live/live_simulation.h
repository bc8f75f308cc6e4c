#pragma once
// A scene's cable stepped on demand while the sea is changed between steps: the physics half of
// the live view (no threads, no clock, no drawing: it only describes its line for the picture),
// one of LivePhysics' two kinds (a system's: live_system_simulation.h). The model stays the
// scene's; the controls change its Inputs (core/inputs.h): the driven end's amplitude and
// period, the current and the waves, ramped along SmoothSchedule, so a change never jumps the
// prescribed end's position, velocity or acceleration, and the current never jumps either.
#include <Eigen/Core>

#include "core/line_data.h"
#include "core/inputs.h"
#include "core/line_model.h"
#include "core/end_loads.h"
#include "core/smooth_schedule.h"
#include "live/live_physics.h"
#include "live/sea_ramps.h"
#include "run/time_grid.h"
#include "scene/scene_def.h"

namespace cablefilm {

class LiveSimulation : public LivePhysics {
 public:
  // Builds the model and its static equilibrium (the initial state). Throws Error,
  // CancelledError when `stop` is raised while the statics run.
  explicit LiveSimulation(const SceneDef& scene, const CancelFlag* stop = nullptr);

  // Back to the scene's initial state and sea.
  void Restart() override;
  // Advances by `seconds` of simulated time, in steps of the scene's scheme (the explicit one
  // below its stability limit, the implicit one with its error control); the current and the
  // waves held over it at its middle. Throws BlowUpError.
  void Advance(double seconds) override;

  // New targets, reached along a ramp that starts now (at t()): amplitude and period over one
  // period of the driven end (kMotionRamp at least), the current over kCurrentRamp. False when
  // too many changes are still ramping (then nothing changes; try again a moment later).
  bool SetAmplitudeScale(double scale) override;
  bool SetPeriod(double period) override;  // [s]
  bool SetCurrent(double current) override;  // [m/s]
  // The current's direction [deg from +x towards +z], over kCurrentRamp as its speed; the whole
  // current turns (a profile too). It turns the short way round, through at most 180 degrees
  // (350 after 0 is -10), so any two headings 360 degrees apart are the same target.
  bool SetCurrentHeading(double degrees) override;
  // The waves' height H [m], over one wave period (kMotionRamp to 30 s); false without waves.
  // The wave's amplitude is held over each step at its value mid-step, as the current is.
  bool SetWaveHeight(double height) override;
  // The waves' period T [s], over one wave period (kMotionRamp to 30 s); false without waves.
  // Each step takes the period at its middle, with the wave number of the new period and the
  // phase that keeps the wave's phase continuous at the driven end's x (where a ship would
  // see the wave change; core/inputs.h, UpdateWater); elsewhere the crests shift as k changes.
  // An end that follows the wave (motion = "wave") changes its period along the same ramp. A
  // wave higher than its breaking height at the period of the moment is held at that height
  // (Miche's limit).
  bool SetWavePeriod(double period) override;
  // The way the waves travel [deg from +x towards +z], over one wave period (kMotionRamp to
  // 30 s), the short way round as the current's; false without waves. Each step takes the
  // heading at its middle, with the phase kept at the driven end's x as for the period (the
  // crests swing round that point). An end that follows the wave keeps its RAOs along x and z
  // (a ship's surge and sway as the scene gives them, not turned with the waves).
  bool SetWaveHeading(double degrees) override;

  static constexpr double kMotionRamp = kShortestMotionRamp;  // shortest amplitude/period ramp [s]
  static constexpr double kCurrentRamp = kSeaCurrentRamp;     // current ramp [s]

  double t() const override { return data_.state.t; }
  const State& state() const { return data_.state; }
  const LineData& data() const { return data_; }
  const Inputs& inputs() const override { return inputs_; }
  const Eigen::VectorXd& tensions() const { return data_.tension(); }
  const LineModel& model() const override { return model_; }
  const Wave& wave() const override { return data_.water.wave; }  // the waves of the last step
  const Water& water() const { return data_.water; }     // its current and waves
  const State& initial_state() const { return initial_.state; }
  const Eigen::VectorXd& initial_tensions() const { return initial_.tension(); }
  const SeaTargets& scene_sea() const override { return scene_sea_; }
  SeaTargets targets() const;  // what the sea is ramping to (headings as the ramps hold
                               // them: turned the short way, 370 may be 10)
  double wave_height_now() const;  // H acting now [m]
  double wave_period_now() const;  // T acting now [s]
  bool has_driven_end() const override { return base_period_ > 0; }
  bool end_follows_wave() const override { return end_follows_wave_; }  // set once, at construction
  StepStats stats() const { return data_.step_stats(); }

  // The live session's view of it: the one line, unnamed (a line alone needs no name); the
  // time series as a run's timeseries.csv.
  SceneView MakeView(const SceneDef& scene, const std::string& view) const override;
  void TakeSnapshot(Snapshot* snapshot) const override;
  const Eigen::VectorXd& line_tensions(int) const override { return tensions(); }
  std::string timeseries_header() const override;
  void WriteTimeseriesRow(std::FILE* file) override;

 private:
  double MotionRamp() const;  // [s]

  const LineModel model_;             // as built from the scene
  TimeGrid grid_;                 // the scene's scheme and step rule
  double fixed_step_ = 0;         // [s]; 0: the scheme chooses (adaptive, or its own substeps)
  LineData initial_;                  // the scene's initial state, ready to step: a restart's
  LineData data_;                     // the one stepped
  Inputs scene_inputs_, inputs_;  // the scene's; those the controls ramp
  SeaTargets scene_sea_;
  double base_period_ = 0;        // the driven end's period in the scene [s]
  bool end_follows_wave_ = false; // the driven end's motion is the wave's (motion = "wave")
  EndLoads row_ends_;             // a time series row's end loads' scratch
};

}  // namespace cablefilm
