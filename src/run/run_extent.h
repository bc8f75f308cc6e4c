#pragma once
// What the whole run covers, gathered during the first pass so that every frame of the film
// uses one colour range and one world box.
#include <Eigen/Core>

#include "core/cable_state.h"

namespace cablefilm {

struct RunExtent {
  explicit RunExtent(const CableState& initial);
  void Add(const CableState& s, const Eigen::VectorXd& tension);

  double tension_min = 0, tension_max = 0;  // over all links and output times [N]
  Eigen::Vector2d box_min, box_max;         // of all stations over the run [m]
};

}  // namespace cablefilm
