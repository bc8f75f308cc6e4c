#include "core/stability.h"

#include <cmath>
#include <limits>

namespace cablefilm {

StabilityLimit ComputeStabilityLimit(const CableModel& m) {
  // Axial stiffness k = sigma E / l of each link; the smallest eigenvalue of the station inertia
  // is at least m_j + min(m^x, m^y) (the normal added mass only adds). Gershgorin's bound on
  // the mass-scaled stiffness matrix M^-1/2 K M^-1/2, row j:
  //   (k_l + k_r)/m_j + k_l/sqrt(m_j m_{j-1}) + k_r/sqrt(m_j m_{j+1}).
  auto inertia = [&](int j) { return m.cable_mass[j] + m.prism_mass.col(j).minCoeff(); };
  StabilityLimit out;
  double lambda_max = 0;
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    const double mj = inertia(j);
    double row = 0;
    if (j > 0) {
      const double k = m.axial_stiffness[j - 1] / m.rest_length[j - 1];
      row += k / mj;
      if (!m.prescribed(j - 1)) row += k / std::sqrt(mj * inertia(j - 1));
    }
    if (j < m.links) {
      const double k = m.axial_stiffness[j] / m.rest_length[j];
      row += k / mj;
      if (!m.prescribed(j + 1)) row += k / std::sqrt(mj * inertia(j + 1));
    }
    if (row > lambda_max) {
      lambda_max = row;
      out.station = j;
    }
  }
  out.omega_max = std::sqrt(lambda_max);
  out.time_step = lambda_max > 0 ? 2.0 / out.omega_max : std::numeric_limits<double>::infinity();
  return out;
}

}  // namespace cablefilm
