#pragma once
// What a live session (live_session.h) steps and shows, whatever the scene: one line
// (LiveSimulation) or a system of lines, points and bodies (LiveSystemSimulation). The session
// paces it, hands it the viewers' controls, draws its lines and logs its time series; it
// never asks which kind it holds. No threads, no clock: the session's simulation thread owns it.
#include <Eigen/Core>
#include <cstdio>
#include <memory>
#include <string>

#include "core/cancel.h"
#include "core/inputs.h"
#include "core/line_model.h"
#include "core/waves.h"
#include "scene/scene_def.h"
#include "view/scene_view.h"
#include "view/snapshot.h"

namespace cablefilm {

// The sea (and a system's vessel) as a scene sets it, or as the controls ramp it to.
struct SeaTargets {
  double amplitude_scale = 1;  // times the scene's end-motion amplitudes
  double period = 0;           // of the driven end [s]; 0 when no end is driven
  double current = 0;          // c [m/s], the uniform part, along current_heading
  double current_heading = 0;  // the way the current flows [deg] from +x towards +z
  double wave_height = 0;      // H [m] of the scene's [waves]; 0 without
  double wave_period = 0;      // T [s] of the scene's [waves]; 0 without
  double wave_heading = 0;     // the way the waves travel [deg] from +x towards +z; 0 without
  double offset_x = 0;         // a system's vessel offset from the scene's [m], along x...
  double offset_z = 0;         // ...and z (y is up); 0 for a line
  double force_x = 0;          // a system's extra steady force on its free bodies [N], along x...
  double force_z = 0;          // ...and z; 0 for a line
};

class LivePhysics {
 public:
  virtual ~LivePhysics() = default;

  // Back to the scene's initial state and sea.
  virtual void Restart() = 0;
  // Advances by `seconds` of simulated time. Throws BlowUpError.
  virtual void Advance(double seconds) = 0;
  virtual double t() const = 0;  // [s]

  // The controls: each a new target reached along a ramp that starts now (the implementations
  // say how long). False when not taken: not this scene's (no driven end, no waves, no vessel)
  // or too many changes still ramping (then try again a moment later).
  virtual bool SetAmplitudeScale(double scale) = 0;
  virtual bool SetPeriod(double period) = 0;            // [s]
  virtual bool SetCurrent(double current) = 0;          // [m/s]
  virtual bool SetCurrentHeading(double degrees) = 0;   // [deg from +x towards +z]
  virtual bool SetWaveHeight(double height) = 0;        // [m]
  virtual bool SetWavePeriod(double period) = 0;        // [s]
  virtual bool SetWaveHeading(double degrees) = 0;      // [deg from +x towards +z]
  virtual bool SetOffsetX(double /*metres*/) { return false; }  // a line has no vessel
  virtual bool SetOffsetZ(double /*metres*/) { return false; }
  virtual bool SetForceX(double /*newtons*/) { return false; }  // a line has no free body
  virtual bool SetForceZ(double /*newtons*/) { return false; }

  virtual const SeaTargets& scene_sea() const = 0;
  virtual const Inputs& inputs() const = 0;  // as the controls have ramped them
  double current_now() const;          // the current acting now [m/s]
  double current_heading_now() const;  // its direction now [deg], as the ramp turns it
  double wave_heading_now() const;     // the waves' heading now [deg], as the ramp turns it
  virtual bool has_driven_end() const = 0;         // amplitude and period controls
  virtual bool end_follows_wave() const = 0;
  virtual bool has_vessel() const { return false; }  // offset controls
  virtual Vec offset_now() const { return Vec::Zero(); }  // the vessel's acting now [m]
  virtual double offset_max() const { return 0; }       // the largest |offset| asked [m]
  virtual bool has_free_body() const { return false; }  // force controls
  virtual Vec force_now() const { return Vec::Zero(); }  // the extra force acting now [N]
  virtual double force_max() const { return 0; }        // the largest |force| asked [N]
  virtual bool is_system() const { return false; }
  // A model of the scene's environment (a system: its first line's; all share the sea).
  virtual const LineModel& model() const = 0;
  virtual const Wave& wave() const = 0;  // the waves of the last step

  // The picture: the scene view of its lines as the film draws them (in space or not), and
  // the state now as the history takes it (its lines in the view's order, the current).
  // `view`: "auto", "2d" or "3d" (scene/film_view.h).
  virtual SceneView MakeView(const SceneDef& scene, const std::string& view) const = 0;
  virtual void TakeSnapshot(Snapshot* snapshot) const = 0;
  virtual int line_count() const { return 1; }
  virtual const Eigen::VectorXd& line_tensions(int line) const = 0;  // [N] per link

  // The time series: its header (with its newline) and the row of now.
  virtual std::string timeseries_header() const = 0;
  virtual void WriteTimeseriesRow(std::FILE* file) = 0;
};

// A line's (LiveSimulation) or a system's (LiveSystemSimulation), as the scene is. Throws Error,
// CancelledError when `stop` is raised while the statics run.
std::unique_ptr<LivePhysics> MakeLivePhysics(const SceneDef& scene,
                                             const CancelFlag* stop = nullptr);

}  // namespace cablefilm
