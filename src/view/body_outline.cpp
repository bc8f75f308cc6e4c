#include "view/body_outline.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {
namespace {

// The points ordered by their angle about their centre in the plane of (u, v).
template <class P, class U, class V>
std::vector<P> Loop(std::vector<P> points, U u, V v) {
  if (points.size() < 2) return {};
  float cu = 0, cv = 0;
  for (const P& q : points) cu += u(q), cv += v(q);
  cu /= points.size();
  cv /= points.size();
  std::sort(points.begin(), points.end(), [&](const P& a, const P& b) {
    return std::atan2(v(a) - cv, u(a) - cu) < std::atan2(v(b) - cv, u(b) - cu);
  });
  if (points.size() > 2) points.push_back(points.front());
  return points;
}

}  // namespace

std::vector<Vec2f> BodyOutline(std::vector<Vec2f> points) {
  return Loop(std::move(points), [](const Vec2f& q) { return q.x; },
              [](const Vec2f& q) { return q.y; });
}

std::vector<Vec3f> BodyOutline(std::vector<Vec3f> points) {
  return Loop(std::move(points), [](const Vec3f& q) { return q.x; },
              [](const Vec3f& q) { return q.z; });
}

}  // namespace cablefilm
