#include "view/body_box.h"

namespace cablefilm {

std::array<Vec, 8> BoxCorners(const Vec& r, const Mat& R, const Vec& size, const Vec& center) {
  std::array<Vec, 8> c;
  for (int i = 0; i < 8; ++i) {
    const Vec sign((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    c[i] = r + R * (center + 0.5 * size.cwiseProduct(sign));
  }
  return c;
}

BoxEdges BodyBoxEdges(const Vec& r, const Mat& R, const Vec& size, const Vec& center) {
  const std::array<Vec, 8> c = BoxCorners(r, R, size, center);
  BoxEdges edges;
  int k = 0;
  for (int axis = 0; axis < 3; ++axis)  // from each corner without that axis's bit to its pair
    for (int i = 0; i < 8; ++i)
      if (!(i & (1 << axis))) edges[k++] = {c[i], c[i | (1 << axis)]};
  return edges;
}

BoxEdges BodyBoxEdges(const Vec6& pose, const Vec& size, const Vec& center) {
  return BodyBoxEdges(pose.head<3>(), BodyRotation(pose.tail<3>()), size, center);
}

}  // namespace cablefilm
