#pragma once
// The explicit scheme (explicit_step.h: central differences in velocity-Verlet form) on a
// coupled island, as MoorDyn integrates a mooring: every line's stations as the line's scheme
// steps them (explicit_stages.h); a shared station's acceleration that of its whole mass under
// all its forces (the sum of its copies' rows: its lines' lumped shares and the point's own
// terms); a free body's from its mass matrix (and added mass) with the inertia of the stations
// on it, M_b + sum T^T M_j T, under its own loads and those stations' forces, sum T^T f_j
// (T the point's 3x6 Jacobian, dx = T dq), its stations then where its pose puts them, moving
// with it (v_j = T dq/dt). The velocity-squared terms of a turning body are left out (slow
// turns), as the implicit step leaves them out.
//
// Each step asked is cut into 2^k equal substeps: at most the least of its lines' safety x
// stability limit (StepOptions::safety_factor > 0; 0: the step asked, as it is), refined where
// a link of any line changes between slack and taut with an energy error above the line
// scheme's bounds (explicit_step.h), as a line's automatic explicit steps are.
#include "core/data.h"

namespace cablefilm {

// Advances coupled island k by dt [s] from its clock (IslandData::t), which it leaves at
// t + dt (its lines' too). Throws CancelledError (in.stop, each substep).
void StepCoupledExplicit(const Model& model, int k, Data& d, const Inputs& in, double dt);

// The accelerations of island k's coupled stations and free bodies at the state of its
// lines (their forces and accelerations as computed for each line alone: d.lines[].forces,
// .a) at time t [s]: a shared station's from the sum of its copies' rows, set in every copy;
// a free body's (Data::bodies[].a) from its mass matrix and loads at its pose q moving at
// `rates` (per free body of the island: dq/dt for its damping), its stations' T a_q.
void CoupleAccelerations(const Model& model, int k, Data& d, double t,
                         const std::vector<Vec6>& rates);

}  // namespace cablefilm
