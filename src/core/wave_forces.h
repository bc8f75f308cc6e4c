#pragma once
// The forces of the water in waves (waves.h) on the cable: Morison's equation on each link's
// normal and on the prisms, with the surface cutting the buoyancy, drag and added mass of the
// stations above it. Used by forces.cpp and force_jacobian.cpp only when the model has waves;
// O(s), nothing allocates once the geometry's sea arrays are sized (on the first call).
//
// Per link k+1/2 (stations k, k+1), half to each station, with psi_k = (phi_k + phi_{k+1}) / 2
// its wet fraction:
//   drag      D = -psi f^D q |q|,  q = n . (mean station velocity - c(y_mid) e_x - mean U)
//   inertia   F = psi rho sigma l (1 + k) (n . mean A) n        (Froude-Krylov + added mass)
//   along     F^t = psi rho sigma l (1 + k^t) (t . mean A) t    (the same along the link, as
//                                                               MoorDyn's 1 + CaAx; e^t alone
//                                                               without axial Froude-Krylov)
// with U, A the water's velocity and acceleration at the stations (waves.h). Per prism:
//   drag      -phi u f (.) rel,  rel = v - c(y) e_x - U
//   inertia   phi rho (V* + V^x, V* + V^y) (.) A
// With the tangential drag coefficient (line_model.h) a link adds along itself
//   drag      -psi f^T |p| p t,  p = t . (mean station velocity - c(y_mid) e_x - mean U)
// Buoyancy: a station loses (1 - phi_j) of its buoyancy B_j (its links' halves and V*). Added
// masses in the inertia tensor: psi e (and psi e^t along) for the links, phi rho V for the prisms.
//
// The surface: phi_j = S((eta(x_j, t) - y_j) / l_j + 1/2), S(u) = 3u^2 - 2u^3 clamped to
// [0, 1], with l_j the station's share of the line: the submerged fraction of a vertical
// stretch of line l_j long centred on the station, smoothed to C^1 so that the implicit
// scheme's Newton iteration sees no jump when a station crosses the surface.
#include <Eigen/Core>

#include "core/block_tridiagonal.h"
#include "core/line_model.h"
#include "core/forces.h"

namespace cablefilm {

// Fills g.sea for time t at the positions x (sizes it on the first call).
void ComputeSea(const LineModel& m, const Water& water, double t, const Points& x, SeaState& sea);

// The wet fraction phi(u) of the surface band and its derivative d phi / du.
double WetFraction(double u);
double WetFractionSlope(double u);

// The potential [J] of the buoyancy lost above the still water level (the static problem's
// surface): -dV/dy_j = -(1 - phi_j) B_j, V_j = B_j (y_j + l_j G(u_j)) with G(u) the integral of
// phi from 0 to u, u_j = (y_surface - y_j) / l_j + 1/2; constant for a station under water.
double SurfaceBuoyancyEnergy(const LineModel& m, const Points& x);

// The external forces with waves (the formulas above), weight included, seabed excluded.
void AddWaveExternalForces(const LineModel& m, const Water& water, const LinkGeometry& g,
                           const Points& v, Points& force);

// -dF/dx - kv dF/dv of the forces above (force_jacobian.h's convention): through the links'
// orientation, the water's velocity and acceleration gradients, the current profile, the wet
// fractions' gradients (drag, inertia, buoyancy) and the relative velocity.
void AddWaveForceJacobian(const LineModel& m, const Water& water, const LinkGeometry& g,
                          const Points& v, double kv, BlockTridiagonal& system);

// d(M(x) a)/dx through the wet fractions of the added masses (the orientation part is in
// SetInertiaJacobian).
void AddWaveInertiaJacobian(const LineModel& m, const LinkGeometry& g, const Points& a,
                            BlockTridiagonal& system);

}  // namespace cablefilm
