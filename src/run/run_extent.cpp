#include "run/run_extent.h"

namespace cablefilm {

RunExtent::RunExtent(const State& initial)
    : box_min(initial.x.rowwise().minCoeff()), box_max(initial.x.rowwise().maxCoeff()) {}

void RunExtent::Add(const State& s, const Eigen::VectorXd& tension) {
  tension_min = std::min(tension_min, tension.minCoeff());
  tension_max = std::max(tension_max, tension.maxCoeff());
  box_min = box_min.cwiseMin(s.x.rowwise().minCoeff());
  box_max = box_max.cwiseMax(s.x.rowwise().maxCoeff());
}

}  // namespace cablefilm
