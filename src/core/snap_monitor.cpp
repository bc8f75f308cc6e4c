#include "core/snap_monitor.h"

#include <cmath>
#include <limits>

namespace cablefilm {

SnapMonitor::SnapMonitor(const LineModel& m)
    : rest_length_(m.line.rest_length), tau_(m.line.links), taut_(m.line.links) {
  for (int j = 0; j < m.line.links; ++j) {
    // Station masses along the link [kg]: cable plus prism (the smaller axis, the faster mode).
    const double ma = m.line.cable_mass[j] + m.line.prism_mass.col(j).minCoeff();
    const double mb = m.line.cable_mass[j + 1] + m.line.prism_mass.col(j + 1).minCoeff();
    const double k = m.line.axial_stiffness[j] / m.line.rest_length[j];  // [N/m]
    const double omega2 = k * (1.0 / ma + 1.0 / mb);           // [1/s^2]
    tau_[j] = omega2 > 0 ? M_PI / std::sqrt(omega2) : std::numeric_limits<double>::infinity();
  }
  taut_.setConstant(false);
}

void SnapMonitor::Start(const Eigen::VectorXd& length) {
  for (Eigen::Index j = 0; j < taut_.size(); ++j)
    taut_[j] = !(length[j] < (1.0 - kSlackStrain) * rest_length_[j]);
}

void SnapMonitor::ObserveStep(double h) {
  if (record_.smallest_step == 0 || h < record_.smallest_step) record_.smallest_step = h;
  if (h > record_.largest_step) record_.largest_step = h;
}

void SnapMonitor::Observe(double t_end, double h, const Eigen::VectorXd& length) {
  ObserveStep(h);
  for (Eigen::Index j = 0; j < taut_.size(); ++j) {
    const bool taut = length[j] > rest_length_[j];
    if (taut && !taut_[j]) {
      ++record_.snaps;
      const double ratio = h / tau_[j];
      if (ratio > record_.worst_snap_ratio) record_.worst_snap_ratio = ratio;
      if (ratio > kResolvedSnapFraction) {
        if (record_.unresolved_snaps == 0) {
          record_.first_unresolved_time = t_end;
          record_.first_unresolved_link = static_cast<int>(j);
        }
        ++record_.unresolved_snaps;
      }
    }
    if (taut) taut_[j] = true;
    else if (length[j] < (1.0 - kSlackStrain) * rest_length_[j]) taut_[j] = false;
  }
}

}  // namespace cablefilm
