#pragma once
// A system of lines, points and bodies (core/model.h) stepped on demand while the sea and the
// vessel are changed between steps: a system's physics half of the live view, as
// LiveSimulation is a line's. It is the run's system (PrepareSystemRun: its equilibrium, its
// grid, its initial LineData) stepped by the run's own stepping (StepSpan), so that with no
// control changed it repeats `cablefilm run`'s rows.
//
// Its controls: the current's speed and heading and the waves' height, period and heading,
// ramped as a line's (sea_ramps.h); and the vessel's horizontal offset [m] along x and z (y is
// up): the points a vessel carries (a point with a motion of its own, such as a ship's
// fairlead, and the points of a driven or held body) move by it as well as by their motion,
// ramped along the same smootherstep (core/smooth_schedule.h) so that the fairleads' position,
// velocity and acceleration never jump. A free body has no offset: the sea and its own loads
// place it; its control is an extra steady force [N] along x and z on every free body (a wind
// gust, a thrust), ramped as the current, held over each frame's step at its mid-step value
// (as the current is). The driven ends' amplitude and period are not a system's controls.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/inputs.h"
#include "core/point_loads.h"
#include "live/live_physics.h"
#include "run/system_run.h"
#include "scene/scene_def.h"

namespace cablefilm {

class LiveSystemSimulation : public LivePhysics {
 public:
  // The system's equilibrium (its free bodies at their initial offsets, as a run starts), its
  // vessel's points marked as carried. Throws Error, CancelledError when `stop` is raised
  // while the statics run.
  explicit LiveSystemSimulation(const SceneDef& scene, const CancelFlag* stop = nullptr);

  void Restart() override;
  // In the run's steps: as many as the grid's step (the scene's time_step, or with "auto" the
  // output interval, each adaptive within) takes to cover `seconds`. The current and the waves
  // held over each step at its middle, as in a run. Throws BlowUpError naming the line.
  void Advance(double seconds) override;
  double t() const override { return data_.t; }

  bool SetAmplitudeScale(double) override { return false; }  // not a system's control
  bool SetPeriod(double) override { return false; }
  bool SetCurrent(double current) override;
  bool SetCurrentHeading(double degrees) override;
  bool SetWaveHeight(double height) override;
  bool SetWavePeriod(double period) override;
  bool SetWaveHeading(double degrees) override;
  // The vessel's offset from the scene's position [m], over kOffsetRamp at least, longer for a
  // long move so that the vessel never moves faster than kOffsetSpeed. False without a vessel.
  bool SetOffsetX(double metres) override;
  bool SetOffsetZ(double metres) override;

  // The extra force on every free body [N], added to its scene's constant force, over
  // kForceRamp. False without a free body.
  bool SetForceX(double newtons) override;
  bool SetForceZ(double newtons) override;

  static constexpr double kOffsetRamp = 5.0;   // shortest offset ramp [s]
  static constexpr double kForceRamp = 5.0;    // force ramp [s], as the current's
  static constexpr double kOffsetSpeed = 2.0;  // the vessel's fastest ramped speed [m/s]

  const SeaTargets& scene_sea() const override { return scene_sea_; }
  SeaTargets targets() const;
  Vec offset_now() const override;  // the vessel's offset acting now [m] (y 0)
  // A tenth of the shortest line: a few times a vessel's drift, about a leg's slack (more would
  // pull it taut and snap it).
  double offset_max() const override;
  bool has_free_body() const override { return !run_.sys.free_bodies.empty(); }
  Vec force_now() const override;
  // The sum of the lines' largest tensions at the start: the order of what the mooring holds.
  double force_max() const override;
  bool has_driven_end() const override { return false; }
  bool end_follows_wave() const override { return false; }
  bool has_vessel() const override { return !carried_.empty(); }
  bool is_system() const override { return true; }
  const LineModel& model() const override { return run_.sys.lines.front(); }
  const Wave& wave() const override { return data_.lines.front().water.wave; }

  SceneView MakeView(const SceneDef& scene, const std::string& view) const override;
  void TakeSnapshot(Snapshot* snapshot) const override;
  int line_count() const override { return static_cast<int>(data_.lines.size()); }
  const Eigen::VectorXd& line_tensions(int line) const override {
    return data_.lines[line].tension();
  }
  // Columns: t, current, current_heading, offset_x, offset_z, force_x, force_z (acting now),
  // then per line
  // tension_max_<line>, link_max_<line>, then per point x_, y_, z_, fx_, fy_, fz_<point> (the
  // lines' load on it, as points.csv's). Names as the scene gives them, any character but a
  // letter, digit, '_', '-' or '.' as '_'.
  std::string timeseries_header() const override;
  void WriteTimeseriesRow(std::FILE* file) override;

  const SystemRun& run() const { return run_; }  // its model (carried ends marked), grid
  const Data& data() const { return data_; }
  const Inputs& inputs() const override { return inputs_; }
  const std::vector<int>& carried_points() const { return carried_; }
  // The points' positions [m] and loads [N] now (PointLoads of the state now).
  const PointLoads& point_loads();

 private:
  bool ChangeOffset(SmoothSchedule& s, double metres);

  SystemRun run_;                 // the system as the run prepares it
  Data data_;               // the one stepped
  Inputs scene_inputs_, inputs_;  // the scene's; those the controls ramp
  SeaTargets scene_sea_;
  std::vector<int> carried_;      // the points the vessel carries
  std::vector<Vec> scene_forces_;  // each body's constant force as the scene gives it [N]
  SmoothSchedule force_x_{0}, force_z_{0};  // the extra force on the free bodies [N]
  PointLoads loads_;
};

}  // namespace cablefilm
