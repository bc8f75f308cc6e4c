#pragma once
// A body's hull drawn as a box: its 12 edges in the world at the body's pose (core/body.h: a
// local point p is at r + R(theta) p), the box `size` long along the body's x, y, z axes about
// `center` (in its axes, from its reference point).
#include <array>

#include "core/body.h"
#include "core/vec.h"

namespace cablefilm {

using BoxEdges = std::array<std::array<Vec, 2>, 12>;  // each edge's two ends [m]

// The corners in the order of their signs (-x, -y, -z first; bit 0 x, bit 1 y, bit 2 z:
// corner i is centre + size/2 * (+-1, +-1, +-1), + where bit set), at reference point r turned
// by R.
std::array<Vec, 8> BoxCorners(const Vec& r, const Mat& R, const Vec& size, const Vec& center);
// The edges joining corners that differ along one axis: four along each of x, y, z.
BoxEdges BodyBoxEdges(const Vec& r, const Mat& R, const Vec& size, const Vec& center);
// The same at `pose` (r, theta): R = BodyRotation(theta).
BoxEdges BodyBoxEdges(const Vec6& pose, const Vec& size, const Vec& center);

}  // namespace cablefilm
