#include "core/stability.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/seabed_friction.h"

namespace cablefilm {

StabilityLimit ComputeStabilityLimit(const LineModel& m) {
  // Axial stiffness k = sigma E / l of each link; the smallest eigenvalue of the station inertia
  // is at least m_j + min(m^x, m^y) (the normal added mass only adds). Gershgorin's bound on
  // the mass-scaled stiffness matrix M^-1/2 K M^-1/2, row j:
  //   (k_l + k_r)/m_j + k_l/sqrt(m_j m_{j-1}) + k_r/sqrt(m_j m_{j+1}).
  auto inertia = [&](int j) { return m.line.cable_mass[j] + m.SmallestPrismMass(j); };
  // The same bound on M^-1/2 C M^-1/2 for the axial damping c gives gamma_max [1/s].
  auto coefficient = [&](const Eigen::VectorXd& per_link, int k, bool stiffness) {
    if (per_link.size() == 0) return 0.0;
    return stiffness ? per_link[k] / m.line.rest_length[k] : per_link[k];
  };
  StabilityLimit out;
  double lambda_max = 0, gamma_max = 0;
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    const double mj = inertia(j);
    double row[2] = {0, 0};  // stiffness, damping
    for (int which = 0; which < 2; ++which) {
      const Eigen::VectorXd& per_link = which == 0 ? m.line.axial_stiffness : m.line.axial_damping;
      if (j > 0) {
        const double k = coefficient(per_link, j - 1, which == 0);
        row[which] += k / mj;
        if (!m.prescribed(j - 1)) row[which] += k / std::sqrt(mj * inertia(j - 1));
      }
      if (j < m.line.links) {
        const double k = coefficient(per_link, j, which == 0);
        row[which] += k / mj;
        if (!m.prescribed(j + 1)) row[which] += k / std::sqrt(mj * inertia(j + 1));
      }
    }
    // The seabed's spring and dashpot act on the station alone (the diagonal): any station
    // may come to rest on it, so every one counts. Its reaction is at most twice the spring's
    // (forces.cpp), a stiffness of up to 2 k l_j; the stick-slip friction's shear spring K l_j
    // and dashpot C_j act across it, on the horizontal axes (seabed_friction.h).
    if (m.env.seabed.present) {
      row[0] += std::max(2.0 * m.line.seabed_stiffness[j], ShearStiffness(m, j)) / mj;
      row[1] += std::max(m.line.seabed_damping[j], ShearDamping(m, j)) / mj;
    }
    if (row[0] > lambda_max) {
      lambda_max = row[0];
      out.station = j;
    }
    gamma_max = std::max(gamma_max, row[1]);
  }
  out.omega_max = std::sqrt(lambda_max);
  // The explicit scheme (velocity Verlet, the damping taken at the predicted velocity
  // v_n + h a_n) on x'' + gamma x' + omega^2 x = 0 is stable for
  //   omega h <= 2 (sqrt(1 + 4 zeta^2) - 2 zeta),  zeta = gamma / (2 omega)
  // (its amplification matrix's spectral radius reaches 1 there: found numerically to 1e-3 for
  // zeta from 0 to 2 and checked by tests/core/axial_damping_test.cpp; plain central
  // differences allow the same with zeta for 2 zeta). With the bounds omega_max and gamma_max
  // (a larger zeta only shortens the step) it holds for every mode.
  const double zeta = lambda_max > 0 ? gamma_max / (2.0 * out.omega_max) : 0.0;
  out.time_step = lambda_max > 0
                      ? 2.0 * (std::sqrt(1.0 + 4.0 * zeta * zeta) - 2.0 * zeta) / out.omega_max
                      : std::numeric_limits<double>::infinity();
  return out;
}

}  // namespace cablefilm
