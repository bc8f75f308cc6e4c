#pragma once
// Explicit second-order stepping of the constrained system (velocity Verlet form, as the
// elastic explicit scheme) with projection of positions and velocities back onto the
// constraints after each step, so link lengths stay at rest length to 1e-12 relative. Each
// requested step is split into substeps below the stability limit of the transverse waves,
// recomputed from the current tensions.
//
// With an error tolerance (time_step = "auto") the substeps also follow a local error estimate,
// as the implicit scheme's do: the position update x_n + h v_n + h^2/2 a_n misses the cubic term
// h^3/6 a', estimated from the accelerations at both ends of the step as
//   err = h^2/6 max_j |a_{n+1,j} - a_{n,j}|_inf   [m],
// and a substep whose err exceeds the tolerance (or whose projection fails) is rejected and
// retried shorter; the next substep is 0.9 (tol/err)^(1/3) times the last (err ~ h^3), at most
// twice it and at least a fifth, and never above the transverse-wave limit or the step asked.
// The transverse-wave limit is unbounded while the tensions are near zero (a chain released
// from a horizontal line), which the error estimate is not. A substep below kSmallestSubstep of
// the step asked, or kMaxSubstepRejections rejections in a row, ends the run with a BlowUpError.
#include "core/line_data.h"

namespace cablefilm {

constexpr double kSmallestSubstep = 1e-9;  // of the step asked of StepLine()
constexpr int kMaxSubstepRejections = 40;

// The inextensible scheme's step of dt [s] (the tensions of data.forces are the constraints').
void InextensibleStep(const LineModel& m, LineData& d, const Inputs& in, double dt);

// The largest stable substep for the tensions of d [s] (the transverse-wave limit).
double StableSubstep(const LineModel& m, const LineData& d);

}  // namespace cablefilm
