#pragma once
// The one vector type of the physics, so that the core is written once for any number of
// dimensions: a position [m], velocity [m/s], acceleration [m/s^2] or force [N], its matrices
// (an inertia tensor [kg], a stiffness [N/m]) and a column per station.
#include <Eigen/Core>
#include <cmath>

namespace cablefilm {

constexpr int kDim = 3;  // x, z horizontal, y up (the paper's plane is z = 0)
using Vec = Eigen::Matrix<double, kDim, 1>;
using Mat = Eigen::Matrix<double, kDim, kDim>;
using Points = Eigen::Matrix<double, kDim, Eigen::Dynamic>;  // column j: station j
using Gradients = Eigen::Matrix<double, kDim * kDim, Eigen::Dynamic>;  // column j: a Mat,
                                                                        // column-major
constexpr int kVertical = 1;  // the axis of gravity (along -y) and of the seabed's reaction

// The horizontal unit vector at `heading` [rad] from +x towards +z: (cos, 0, sin).
inline Vec Horizontal(double heading) {
  // Exact at 0 (cos and sin of 0 are exact, but not of pi / 2): a 2D scene's current and
  // waves along +x are its own.
  if (heading == 0) return Vec(1.0, 0.0, 0.0);
  return Vec(std::cos(heading), 0.0, std::sin(heading));
}

// A point or vector in the paper's plane (z = 0).
inline Vec InPlane(double x, double y) { return Vec(x, y, 0.0); }

// The horizontal part of v (y set to 0).
inline Vec HorizontalPart(const Vec& v) { return Vec(v[0], 0.0, v[2]); }

}  // namespace cablefilm
