#include "scene/moordyn_axes.h"

#include <cmath>

namespace cablefilm {
namespace {

// sin and cos of an angle in degrees, exact at multiples of 90 (a yaw of 90 degrees turns x
// into y with no 6e-17 left over).
void SinCos(double degrees, double* s, double* c) {
  const double turn = std::fmod(degrees, 360.0);
  if (std::fmod(turn, 90.0) == 0) {
    const int quarter = (static_cast<int>(turn / 90.0) + 4) % 4;
    const double sines[4] = {0, 1, 0, -1};
    *s = sines[quarter];
    *c = sines[(quarter + 1) % 4];
    return;
  }
  const double radians = degrees * M_PI / 180.0;
  *s = std::sin(radians);
  *c = std::cos(radians);
}

// Right-handed rotations about MoorDyn's x, y and z.
MoorDynVec RotateX(double deg, const MoorDynVec& v) {
  double s, c;
  SinCos(deg, &s, &c);
  return {v[0], c * v[1] - s * v[2], s * v[1] + c * v[2]};
}
MoorDynVec RotateY(double deg, const MoorDynVec& v) {
  double s, c;
  SinCos(deg, &s, &c);
  return {c * v[0] + s * v[2], v[1], -s * v[0] + c * v[2]};
}
MoorDynVec RotateZ(double deg, const MoorDynVec& v) {
  double s, c;
  SinCos(deg, &s, &c);
  return {c * v[0] - s * v[1], s * v[0] + c * v[1], v[2]};
}

}  // namespace

MoorDynVec MoorDynToCablefilm(const MoorDynVec& p) { return {p[0], p[2], -p[1]}; }

MoorDynVec MoorDynBodyPoint(const MoorDynBody& body, const MoorDynVec& p) {
  // R p = Rx (Ry (Rz p)): the yaw first, in the matrices' order.
  const MoorDynVec r =
      RotateX(body.rotation[0], RotateY(body.rotation[1], RotateZ(body.rotation[2], p)));
  return {body.position[0] + r[0], body.position[1] + r[1], body.position[2] + r[2]};
}

MoorDynVec MoorDynPointPosition(const MoorDynSystem& system, const MoorDynPoint& point) {
  if (point.attachment != MoorDynAttachment::kBody) return point.position;
  return MoorDynBodyPoint(system.bodies.at(static_cast<std::size_t>(point.body - 1)),
                          point.position);
}

}  // namespace cablefilm
