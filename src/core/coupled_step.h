#pragma once
// The implicit step of a coupled island (model.h, Island: lines joined at shared points or
// free bodies): generalized-alpha (implicit_step.h) on every line of the island at once, with
// one step size for all, one Newton iteration for the whole island and one error estimate.
// Each Newton iteration assembles every line's block tridiagonal system, eliminates each
// line's interior (its stations that are not coupled) for its right-hand side and for the few
// columns that couple it to its coupled end stations, and solves the small dense system of
// the island's shared stations (their Schur complement, kDim unknowns per shared point); then
// each line's interior follows. O(s) per line and iteration, plus (kDim x shared points)^3
// for the dense solve.
//
// A free body (body.h) is 6 more unknowns of that dense system: the line ends at its points
// are free stations of their lines whose corrections follow the body's (dx = T dq, T the
// point's 3x6 Jacobian), so its rows are the sum of T^T times theirs (the stations' mass and
// forces carried by the body) plus its own: its mass and added mass, damping, weight,
// buoyancy, waterplane and constant loads. Its pose steps by the same generalized-alpha.
#include "core/data.h"

namespace cablefilm {

// Island k's memory sized and its couplings set (MakeData's part for a coupled island).
void PrepareCoupledIsland(const Model& model, int k, Data& d);

// Advances coupled island k by dt [s] (adaptive within it with the options' tolerance > 0,
// through snaps by explicit steps with explicit_snaps), from d.t. Throws BlowUpError (naming
// the line in its message), CancelledError as Step() does. Its lines' clocks are left at
// d.t + dt.
void StepCoupledIsland(const Model& model, int k, Data& d, const Inputs& in, double dt);

// Explicit steps through snaps (explicit_snaps.h, as a line takes them): a solved implicit
// step of h [s] that snapped a line's link taut too fast is left; the island's state's forces
// and coupled accelerations computed and its explicit window opened over that step and its
// lines' longest snap window after it (or to the run's end, when the windows and the implicit
// steps between them have cost more than the explicit scheme alone would).
void EnterCoupledExplicitWindow(const Model& model, int k, Data& d, const Inputs& in, double h);
// Explicit steps (coupled_explicit_step.h) from the island's clock to t_end [s] or the
// window's end, whichever is first; at the window's end the implicit scheme's memory is made
// from the state.
void StepCoupledExplicitWindow(const Model& model, int k, Data& d, const Inputs& in,
                               double t_end);

// A free body's own generalized load at pose q [N, N m]: weight, buoyancy, waterplane,
// constant loads.
Vec6 BodyOwnLoad(const Model& model, const BodySpec& body, const Vec6& q);

// Makes every copy of island k's shared stations equal to its owner's (position, velocity and
// accelerations of the state), and puts each station on a free body where the body's pose puts
// its point (the maps T with it).
void SyncCoupledState(const Model& model, int k, Data& d);

}  // namespace cablefilm
