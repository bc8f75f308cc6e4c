#pragma once
// A body's rotation R(theta(t)) as it turns, and its first two time derivatives, exactly: the
// angles theta [rad] (about x, then y, then z, fixed axes: R = Rz Ry Rx, as body.h) with their
// rates theta' [rad/s] and theta'' [rad/s^2]. A point fixed to the body at local position p is
// at r + R p, moves at r' + R' p and accelerates at r'' + R'' p.
#include "core/vec.h"

namespace cablefilm {

struct RotationRates {
  Mat R;    // R(theta) [1]
  Mat dR;   // dR/dt [1/s]
  Mat d2R;  // d2R/dt2 [1/s^2]
};

RotationRates RotationInTime(const Vec& angles, const Vec& rates, const Vec& rates2);

}  // namespace cablefilm
