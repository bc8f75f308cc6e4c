#pragma once
// The sea's controls on a simulation's Inputs (core/inputs.h), as the live simulation
// (live_simulation.h) ramps them: the current's speed and heading
// over kCurrentRamp, the waves' height, period and heading over one wave period (kMotionRamp
// to 30 s). Each returns false when the schedule refuses (too many changes still ramping).
#include "core/inputs.h"

namespace cablefilm {

constexpr double kDegree = 3.14159265358979323846 / 180.0;  // [rad]: the controls' headings are degrees
constexpr double kShortestMotionRamp = 2.0;  // [s]
constexpr double kLongestMotionRamp = 30.0;  // [s]
constexpr double kSeaCurrentRamp = 5.0;      // [s]

// The sea and the motions as a scene sets them, or as the controls ramp them to.
struct SeaTargets {
  double amplitude_scale = 1;  // times the scene's driven motions' amplitudes
  double period = 0;           // of the driven ends [s]; 0 when no end is driven
  double current = 0;          // c [m/s], the uniform part, along current_heading
  double current_heading = 0;  // the way the current flows [deg] from +x towards +z
  double wave_height = 0;      // H [m] of the scene's [waves]; 0 without
  double wave_period = 0;      // T [s] of the scene's [waves]; 0 without
  double wave_heading = 0;     // the way the waves travel [deg] from +x towards +z; 0 without
  double offset_x = 0;         // the vessel's offset from the scene's [m], along x...
  double offset_z = 0;         // ...and z (y is up)
  double force_x = 0;          // the extra steady force on the free bodies [N], along x...
  double force_z = 0;          // ...and z
};


bool RampCurrent(Inputs& in, double t, double current);            // [m/s]
bool RampCurrentHeading(Inputs& in, double t, double degrees);     // the short way round
// Over one period of the waves of the last step (`period_now` [s]).
bool RampWaveHeight(Inputs& in, double t, double height, double period_now);
// Over one period as it is now; `ramp` [s] (optional) the ramp taken, for an end that follows.
bool RampWavePeriod(Inputs& in, double t, double period, double* ramp = nullptr);
bool RampWaveHeading(Inputs& in, double t, double degrees);

// The sea's targets the inputs ramp to (headings in degrees, as the ramps hold them); the
// amplitude and period are the caller's (a driven end's).
void SeaTargetsOf(const Inputs& in, SeaTargets* targets);
// Folds the ramps complete at t into their bases (every schedule of the inputs).
void RetireRamps(Inputs& in, double t);

}  // namespace cablefilm
