#include "scene/moordyn_axes.h"

#include <algorithm>
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

MoorDynVec MoorDynAnglesToCablefilm(const MoorDynVec& rpy) {
  if (rpy[0] == 0 && rpy[1] == 0) return {0.0, rpy[2], 0.0};  // exact for the usual yaw alone
  // The turn's matrix in cablefilm's axes, column k: MoorDyn's R applied to the MoorDyn vector
  // that is cablefilm's axis k, mapped back.
  const MoorDynVec axes[3] = {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}};  // cablefilm x, y, z in MoorDyn's
  double R[3][3];
  for (int k = 0; k < 3; ++k) {
    const MoorDynVec v = MoorDynToCablefilm(
        RotateX(rpy[0], RotateY(rpy[1], RotateZ(rpy[2], axes[k]))));
    for (int i = 0; i < 3; ++i) R[i][k] = v[i];
  }
  // R = Rz(c) Ry(b) Rx(a): R[2][0] = -sin b, R[2][1] = cos b sin a, R[2][2] = cos b cos a,
  // R[1][0] = sin c cos b, R[0][0] = cos c cos b.
  const double deg = 180.0 / M_PI;
  const double b = std::asin(std::max(-1.0, std::min(1.0, -R[2][0])));
  return {std::atan2(R[2][1], R[2][2]) * deg, b * deg, std::atan2(R[1][0], R[0][0]) * deg};
}

MoorDynVec MoorDynPointPosition(const MoorDynSystem& system, const MoorDynPoint& point) {
  if (point.attachment != MoorDynAttachment::kBody) return point.position;
  return MoorDynBodyPoint(system.bodies.at(static_cast<std::size_t>(point.body - 1)),
                          point.position);
}

}  // namespace cablefilm
