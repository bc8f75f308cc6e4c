#include "view/cable_style.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {

std::vector<Vec2f> OffsetPolyline(const std::vector<Vec2f>& p, float d) {
  std::vector<Vec2f> out(p.size());
  auto normal = [&](std::size_t i) {  // of segment i -> i+1; zero if degenerate
    const float dx = p[i + 1].x - p[i].x, dy = p[i + 1].y - p[i].y;
    const float len = std::sqrt(dx * dx + dy * dy);
    return len > 1e-6f ? Vec2f{-dy / len, dx / len} : Vec2f{0, 0};
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    Vec2f n{0, 0};
    if (i > 0) n = normal(i - 1);
    if (i + 1 < p.size()) {
      const Vec2f m = normal(i);
      n = {n.x + m.x, n.y + m.y};
    }
    const float len = std::sqrt(n.x * n.x + n.y * n.y);
    if (len > 1e-6f) n = {n.x / len, n.y / len};
    out[i] = {p[i].x + d * n.x, p[i].y + d * n.y};
  }
  return out;
}

void DrawOverlayRim(Painter& p, const std::vector<Vec2f>& pts, float rim_width,
                    const Theme& th) {
  const float k = p.k(), dot = std::max(1.0f, 1.6f * k);
  for (float side : {-1.0f, 1.0f})  // round caps lengthen each dash by the dot width
    p.Dashed(OffsetPolyline(pts, side * (rim_width - dot) / 2), dot, th.overlay_rim, 2.5f * k,
             6.5f * k);
}

void DrawOverlayLine(Painter& p, const std::vector<Vec2f>& pts, float width, float rim_width,
                     Rgba color, const Theme& th) {
  DrawOverlayRim(p, pts, rim_width, th);
  p.Polyline(pts, width, color);
}

}  // namespace cablefilm
