#include "core/integrator.h"

#include <cmath>
#include <sstream>

#include "core/explicit_integrator.h"
#include "core/generalized_alpha.h"
#include "core/inextensible.h"

namespace cablefilm {

std::unique_ptr<Integrator> MakeIntegrator(IntegratorKind kind, const CableModel& m,
                                           double rho_inf, double error_tolerance) {
  switch (kind) {
    case IntegratorKind::kExplicit:
      return std::make_unique<ExplicitIntegrator>(m);
    case IntegratorKind::kImplicit:
      return std::make_unique<GeneralizedAlphaIntegrator>(m, rho_inf, error_tolerance);
    case IntegratorKind::kInextensible:
      return std::make_unique<InextensibleIntegrator>(m, error_tolerance);
  }
  throw Error("unknown integrator");
}

void CheckStateSane(const CableModel& m, const CableState& state, const Eigen::VectorXd& length) {
  // A strain of 100 % is far past the breaking strain of any rope or wire: if the solution gets
  // there, it is a numerical blow-up, not physics.
  constexpr double kMaxStretch = 2.0;  // L / l
  for (int j = 0; j <= m.links; ++j) {
    if (!std::isfinite(state.x(0, j) + state.x(1, j) + state.v(0, j) + state.v(1, j))) {
      std::ostringstream os;
      os << "numerical blow-up at t = " << state.t << " s: station " << j
         << " has a non-finite position or velocity";
      throw BlowUpError(os.str(), state.t, j);
    }
  }
  for (int j = 0; j < m.links; ++j) {
    if (length[j] > kMaxStretch * m.rest_length[j]) {
      std::ostringstream os;
      os << "numerical blow-up at t = " << state.t << " s: link " << j << " (stations " << j
         << "-" << j + 1 << ") stretched to " << length[j] / m.rest_length[j]
         << " times its rest length";
      throw BlowUpError(os.str(), state.t, j);
    }
  }
}

}  // namespace cablefilm
