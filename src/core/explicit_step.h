#pragma once
// Central differences in velocity-Verlet form (the paper's scheme), second order:
//   v_{n+1/2} = v_n + dt/2 a_n,  x_{n+1} = x_n + dt v_{n+1/2},
//   a_{n+1} = a(x_{n+1}, v_n + dt a_n, t_{n+1}),  v_{n+1} = v_{n+1/2} + dt/2 a_{n+1}.
// The velocity in the drag terms is predicted to O(dt^2), which keeps the scheme second order
// with drag; without velocity-dependent forces it is exactly velocity Verlet (symplectic: the
// energy error stays bounded, O(dt^2), with no drift). Stable for dt below 2 / omega_max.
//
// A link going slack or snapping taut within a step breaks that: the tension is continuous but
// its stiffness jumps from 0 to sigma E / l at L = l, and the step's trapezoidal work on the link,
// -(T_n t_n + T_{n+1} t_{n+1})/2 . (d_{n+1} - d_n), misses the change of its strain energy by
//   delta = -T_{n+1} (l - t_{n+1} . d_n) / 2   (snapping taut: energy lost),
//   delta = +T_n (l - t_n . d_{n+1}) / 2       (going slack: energy gained),
// with d the link's vector and t its direction. These do not cancel: near the stability limit a
// chain whipping in vacuum gains energy from them without bound (4 J in its first second, 8 kJ
// in 20 s at 0.8 of the limit). The stability limit itself is not the cause: it holds in every
// state (see stability.h).
//
// With automatic steps (StepOptions::safety_factor > 0) each step asked of StepLine() is cut into
// 2^k equal substeps, k chosen as the run goes: before a substep is taken its positions are predicted
// (they are explicit: x_n + h v_{n+1/2}), and if a link would change between slack and taut with
// |delta| above kSnapEnergyFraction of that link's own energy (the kinetic energy of its two
// stations' motion along it, at the start or the end of the step, with their reduced mass, plus
// its strain energy) and above kCableEnergyFloor of the whole cable's kinetic and strain energy,
// k is raised until it is not. k stays while links keep changing, and comes down one level after
// kQuietSteps steps asked of StepLine() without any. The energy error at a snap is then O(h^2) of
// the snap's energy, as elsewhere, and the energy is conserved (without drag) to the scheme's
// O(h^2): on the whipping chain k settles at 3 (0.1 of the limit), with the energy error of a
// fixed 0.1 of the limit. A case that never goes slack takes the steps asked, exactly as with
// fixed steps; the check costs O(s) per step (3 % of a step on case P63).
#include "core/line_data.h"

namespace cablefilm {

// |delta| allowed at a link changing between slack and taut, as a fraction of its own energy.
constexpr double kSnapEnergyFraction = 1e-2;
// ... or as a fraction of the cable's kinetic + strain energy (a change too small to matter).
constexpr double kCableEnergyFloor = 1e-8;
// Steps asked of StepLine() without a link changing between slack and taut before k comes down.
constexpr int kQuietSteps = 64;
// The finest subdivision: 2^kMaxRefinement substeps per step asked.
constexpr int kMaxRefinement = 24;

// The explicit scheme's step of dt [s] (data.options.safety_factor > 0: automatic substeps).
void ExplicitStep(const LineModel& m, LineData& d, const Inputs& in, double dt);

}  // namespace cablefilm
