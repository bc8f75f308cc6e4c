#pragma once
// What the whole run covers, gathered as the rows come so that every frame of the film uses one
// colour range and one world box.
#include <Eigen/Core>
#include <limits>

#include "core/line_data.h"

namespace cablefilm {

struct RunExtent {
  RunExtent() = default;
  explicit RunExtent(const State& initial);
  void Add(const State& s, const Eigen::VectorXd& tension);

  // Over all links and rows [N].
  double tension_min = std::numeric_limits<double>::infinity();
  double tension_max = -std::numeric_limits<double>::infinity();
  Vec box_min = Vec::Zero(), box_max = Vec::Zero();  // of all stations over the run [m]
};

}  // namespace cablefilm
