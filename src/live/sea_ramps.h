#pragma once
// The sea's controls on a simulation's Inputs (core/inputs.h), ramped alike for a line
// (live_simulation.h) and a system (live_system_simulation.h): the current's speed and heading
// over kCurrentRamp, the waves' height, period and heading over one wave period (kMotionRamp
// to 30 s). Each returns false when the schedule refuses (too many changes still ramping).
#include "core/inputs.h"
#include "live/live_physics.h"

namespace cablefilm {

constexpr double kDegree = 3.14159265358979323846 / 180.0;  // [rad]: the controls' headings are degrees
constexpr double kShortestMotionRamp = 2.0;  // [s]
constexpr double kLongestMotionRamp = 30.0;  // [s]
constexpr double kSeaCurrentRamp = 5.0;      // [s]

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
