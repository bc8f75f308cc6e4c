#pragma once
// An implicit, second-order, unconditionally stable scheme: generalized-alpha (Chung & Hulbert
// 1993) in the form of Arnold & Bruels (2007), where eq. (1) holds exactly at the end of each
// step and a pseudo-acceleration abar carries the method's memory:
//   (1 - am) abar_{n+1} + am abar_n = (1 - af) a_{n+1} + af a_n
//   x_{n+1} = x_n + h v_n + h^2 (1/2 - beta) abar_n + h^2 beta abar_{n+1}
//   v_{n+1} = v_n + h (1 - gamma) abar_n + h gamma abar_{n+1}
// rho_inf in [0, 1] is the spectral radius at infinite frequency: 1 keeps every mode (the
// trapezoidal rule), smaller values damp the unresolved axial modes; low frequencies are
// damped only at third order in omega h. Each step solves M(x) a - F(x, v, t) = 0 for x_{n+1}
// by Newton's method with the analytic Jacobian, block tridiagonal, O(s) per iteration. A step
// whose Newton iteration fails is rejected and retried in halves. With an error tolerance the
// step adapts to a local error estimate (never above the step asked of StepLine()); without one
// the step asked for is taken.
#include "core/line_data.h"

namespace cablefilm {

// The implicit scheme's step of dt [s] (data.options: rho_inf, tolerance).
void ImplicitStep(const LineModel& m, LineData& d, const Inputs& in, double dt);

// Generalized-alpha's coefficients for rho_inf (Chung & Hulbert 1993).
struct GeneralizedAlpha {
  double am, af, beta, gamma;
  // d v_{n+1} / d x_{n+1} of a step of h [s]: gamma / (beta h) [1/s].
  double VelocityPerPosition(double h) const { return gamma / (beta * h); }
};
GeneralizedAlpha GeneralizedAlphaCoefficients(double rho_inf);

}  // namespace cablefilm
