#pragma once
// The stages of one explicit (velocity Verlet) step of one line (explicit_step.h), which the
// line's explicit step and the explicit step of a coupled island (coupled_explicit_step.h)
// both run: the drift to the new positions, the check of the snaps in it, the accelerations
// there, the velocities' second half. A line's trial values live in its LineData's scratch.
#include "core/line_data.h"

namespace cablefilm {

// The positions x_{n+1} of a step h into scratch.x (prescribed ends exact at t + h), with
// v_{n+1/2} (scratch.v) and the predicted v_{n+1} (scratch.v_pred) of the free stations; true
// if a link changes between slack and taut in it.
bool Drift(const LineModel& m, LineData& d, const Inputs& in, double h);

// False if a link changing between slack and taut in the drifted step h has an energy error
// above the bounds (explicit_step.h).
bool SnapsResolved(const LineModel& m, const LineData& d, double h);

// The drifted step made the state's positions and half-step velocities (the prescribed ends'
// velocities exact at t + h), the forces and accelerations at t + h computed (d.forces, d.a;
// the free stations' each under its own forces and inertia).
void MoveToDrift(const LineModel& m, LineData& d, const Inputs& in, double h);

// The step completed: v_{n+1} = v_{n+1/2} + h/2 a_{n+1} at the free stations, the seabed's
// friction anchors moved, the clock and the statistics advanced, the snaps observed.
void FinishDrift(const LineModel& m, LineData& d, double h);

// The refinement k of the steps asked (each cut into 2^k substeps) for a step of dt [s]: raised
// at once to the least that keeps the substeps at most max_substep [s] (a step asked just above
// it by round-off is not cut; an infinite max_substep asks for none), lowered by one after
// kQuietSteps steps asked without a slack-taut change (quiet_time [s], reset then).
void SettleRefinement(double dt, double max_substep, int* refinement, double* quiet_time);

}  // namespace cablefilm
