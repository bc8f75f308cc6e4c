#pragma once
// A scene's model stepped on demand while its sea and its motions are changed between steps:
// the physics half of the live view (no threads, no clock, no drawing: it only describes its
// lines for the picture). It is the run's model (PrepareRun: its initial state, its grid, its
// initial Data) stepped by the run's own stepping (StepSpan), so that with no control changed
// it repeats `cablefilm run`'s rows. The model stays the scene's; the controls change its
// Inputs (core/inputs.h), ramped along SmoothSchedule, so that nothing a control changes jumps:
//   - the driven ends' amplitude and period (any point with a trochoid or table motion): the
//     scale of their motions and the rate of their clock, over one period of the motion;
//   - the current's speed and heading, the waves' height, period and heading (sea_ramps.h);
//   - the vessel's horizontal offset [m] along x and z (y is up): the points a vessel carries
//     (a point with a motion of its own, such as a ship's fairlead, and the points of a driven
//     or held body) move by it as well as by their motion, along the same smootherstep, so
//     that their position, velocity and acceleration never jump;
//   - an extra steady force [N] along x and z on every free body (a wind gust, a thrust),
//     ramped as the current, held over each frame's step at its mid-step value.
// Each is offered where the scene has what it moves (has_driven_end, has_waves, has_vessel,
// has_free_body).
#include <Eigen/Core>
#include <cstdio>
#include <string>
#include <vector>

#include "core/cancel.h"
#include "core/data.h"
#include "core/end_loads.h"
#include "core/inputs.h"
#include "core/point_loads.h"
#include "live/sea_ramps.h"
#include "run/run.h"
#include "scene/scene_def.h"
#include "view/scene_view.h"
#include "view/snapshot.h"

namespace cablefilm {

class LiveSimulation {
 public:
  // The model and its initial state (its free bodies at their initial offsets, as a run
  // starts), its vessel's points marked as carried. Throws Error, CancelledError when `stop`
  // is raised while the statics run.
  explicit LiveSimulation(const SceneDef& scene, const CancelFlag* stop = nullptr);

  // Back to the scene's initial state and sea.
  void Restart();
  // Advances by `seconds` of simulated time in the run's steps: as many as the grid's step
  // (the scene's time_step, or with "auto" its output interval, each adaptive within) takes to
  // cover it. The current and the waves held over each step at its middle, as in a run.
  // Throws BlowUpError (naming the line of a model of several).
  void Advance(double seconds);
  double t() const { return data_.t; }  // [s]

  // The controls: each a new target reached along a ramp that starts now (at t()). False when
  // not taken: not this scene's (no driven end, no waves, no vessel, no free body) or too many
  // changes still ramping (then try again a moment later).
  // The driven ends' amplitude (times the scene's) and period [s], over one period of their
  // motion as it is now (kMotionRamp to 30 s).
  bool SetAmplitudeScale(double scale);
  bool SetPeriod(double period);
  bool SetCurrent(double current);          // [m/s], over kCurrentRamp
  // The current's direction [deg from +x towards +z], over kCurrentRamp as its speed; the whole
  // current turns (a profile too). It turns the short way round, through at most 180 degrees
  // (350 after 0 is -10), so any two headings 360 degrees apart are the same target.
  bool SetCurrentHeading(double degrees);
  // The waves' height H [m], over one wave period (kMotionRamp to 30 s). The wave's amplitude
  // is held over each step at its value mid-step, as the current is.
  bool SetWaveHeight(double height);
  // The waves' period T [s], over one wave period. Each step takes the period at its middle,
  // with the wave number of the new period and the phase that keeps the wave's phase
  // continuous at the vessel (where a ship would see the wave change; core/inputs.h,
  // UpdateWater); elsewhere the crests shift as k changes. An end that follows the wave
  // (motion = "wave") changes its period along the same ramp. A wave higher than its breaking
  // height at the period of the moment is held at that height (Miche's limit).
  bool SetWavePeriod(double period);
  // The way the waves travel [deg from +x towards +z], over one wave period, the short way
  // round as the current's, the phase kept as for the period (the crests swing round that
  // point). An end that follows the wave keeps its RAOs along x and z (a ship's surge and sway
  // as the scene gives them, not turned with the waves).
  bool SetWaveHeading(double degrees);
  // The vessel's offset from the scene's position [m], over kOffsetRamp at least, longer for a
  // long move so that the vessel never moves faster than kOffsetSpeed.
  bool SetOffsetX(double metres);
  bool SetOffsetZ(double metres);
  // The extra force on every free body [N], added to its scene's constant force, over
  // kForceRamp.
  bool SetForceX(double newtons);
  bool SetForceZ(double newtons);

  static constexpr double kMotionRamp = kShortestMotionRamp;  // shortest amplitude/period ramp [s]
  static constexpr double kCurrentRamp = kSeaCurrentRamp;     // current ramp [s]
  static constexpr double kOffsetRamp = 5.0;   // shortest offset ramp [s]
  static constexpr double kForceRamp = 5.0;    // force ramp [s], as the current's
  static constexpr double kOffsetSpeed = 2.0;  // the vessel's fastest ramped speed [m/s]

  const SeaTargets& scene_sea() const { return scene_sea_; }
  SeaTargets targets() const;  // what the sea is ramping to (headings as the ramps hold them:
                               // turned the short way, 370 may be 10)
  const Inputs& inputs() const { return inputs_; }  // as the controls have ramped them
  double current_now() const;          // the current acting now [m/s]
  double current_heading_now() const;  // its direction now [deg], as the ramp turns it
  double wave_heading_now() const;     // the waves' heading now [deg], as the ramp turns it
  double wave_height_now() const;      // H acting now [m]
  double wave_period_now() const;      // T acting now [s]
  Vec offset_now() const;              // the vessel's offset acting now [m] (y 0)
  Vec force_now() const;               // the free bodies' extra force acting now [N]
  // A tenth of the shortest line: a few times a vessel's drift, about a leg's slack (more would
  // pull it taut and snap it).
  double offset_max() const;
  // The sum of the lines' largest tensions at the start: the order of what the mooring holds.
  double force_max() const;

  bool has_driven_end() const { return base_period_ > 0; }  // amplitude and period controls
  bool end_follows_wave() const { return end_follows_wave_; }
  bool has_waves() const { return model().lines.front().has_waves(); }
  bool has_vessel() const { return !carried_.empty(); }             // offset controls
  bool has_free_body() const { return !model().free_bodies.empty(); }  // force controls

  const Model& model() const { return run_.model; }  // its carried ends marked
  const Run& run() const { return run_; }            // its grid, its initial Data
  const Data& data() const { return data_; }
  const Wave& wave() const { return data_.lines.front().water.wave; }  // of the last step
  const std::vector<int>& carried_points() const { return carried_; }
  int line_count() const { return static_cast<int>(data_.lines.size()); }
  const Eigen::VectorXd& line_tensions(int line) const { return data_.lines[line].tension(); }
  // The points' positions [m] and loads [N] now (PointLoads of the state now).
  const PointLoads& point_loads();
  StepStats stats() const { return ModelStepStats(run_.model, data_); }

  // The picture: the scene view of its lines as the film draws them (view/film_pass.h), in
  // space or not (`view`: "auto", "2d" or "3d"), and the state now as the history takes it
  // (its lines in the view's order, the current).
  SceneView MakeView(const SceneDef& scene, const std::string& view) const;
  void TakeSnapshot(Snapshot* snapshot) const;

  // The time series: its header (with its newline) and the row of now. A line alone: a run's
  // timeseries.csv columns. Several: t, current, current_heading, offset_x, offset_z,
  // force_x, force_z (acting now), then per line tension_max_<line>, link_max_<line>, then per
  // point x_, y_, z_, fx_, fy_, fz_<point> (the lines' load on it, as points.csv's). Names as
  // the scene gives them, any character but a letter, digit, '_', '-' or '.' as '_'.
  std::string timeseries_header() const;
  void WriteTimeseriesRow(std::FILE* file);

 private:
  bool ChangeOffset(SmoothSchedule& s, double metres);
  double MotionRamp() const;  // [s]

  Run run_;                       // the scene's run as PrepareRun makes it
  Data data_;                     // the one stepped
  Inputs scene_inputs_, inputs_;  // the scene's; those the controls ramp
  SeaTargets scene_sea_;
  double base_period_ = 0;        // the driven ends' period in the scene [s] (0: none)
  bool end_follows_wave_ = false; // the driven end's motion is the wave's (motion = "wave")
  std::vector<int> carried_;      // the points the vessel carries
  std::vector<Vec> scene_forces_;  // each body's constant force as the scene gives it [N]
  SmoothSchedule force_x_{0}, force_z_{0};  // the extra force on the free bodies [N]
  PointLoads loads_;
  EndLoads row_ends_;             // a line alone's time series row's end loads' scratch
};

}  // namespace cablefilm
