#pragma once
// The state of the cable at one time: what a step advances.
#include <Eigen/Core>

namespace cablefilm {

struct CableState {
  double t = 0;         // time [s]
  Eigen::Matrix2Xd x;   // station positions (x_j, y_j) [m], 2 x (s+1)
  Eigen::Matrix2Xd v;   // station velocities (xdot_j, ydot_j) [m/s], 2 x (s+1)
};

}  // namespace cablefilm
