#pragma once
// The one vector type of the physics, so that the core is written once for any number of
// dimensions: a position [m], velocity [m/s], acceleration [m/s^2] or force [N], its matrices
// (an inertia tensor [kg], a stiffness [N/m]) and a column per station.
#include <Eigen/Core>

namespace cablefilm {

constexpr int kDim = 2;  // the paper's plane: x horizontal, y up
using Vec = Eigen::Matrix<double, kDim, 1>;
using Mat = Eigen::Matrix<double, kDim, kDim>;
using Points = Eigen::Matrix<double, kDim, Eigen::Dynamic>;  // column j: station j
using Gradients = Eigen::Matrix<double, kDim * kDim, Eigen::Dynamic>;  // column j: a Mat, column-major

}  // namespace cablefilm
