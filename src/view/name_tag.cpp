#include "view/name_tag.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {
namespace {

constexpr float kFont = 14;  // [design px]
constexpr float kPad = 3;    // the veil beyond the text [design px]

bool Overlap(const PixelRect& a, const PixelRect& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

// Whether the segment a-b passes through the rectangle r (Liang-Barsky clipping).
bool Crosses(Vec2f a, Vec2f b, const PixelRect& r) {
  float t0 = 0, t1 = 1;
  const float d[2] = {b.x - a.x, b.y - a.y};
  const float lo[2] = {r.x0 - a.x, r.y0 - a.y}, hi[2] = {r.x1 - a.x, r.y1 - a.y};
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0) {
      if (lo[axis] > 0 || hi[axis] < 0) return false;
      continue;
    }
    float u0 = lo[axis] / d[axis], u1 = hi[axis] / d[axis];
    if (u0 > u1) std::swap(u0, u1);
    t0 = std::max(t0, u0);
    t1 = std::min(t1, u1);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

void NameTags::Avoid(const std::vector<Vec2f>& pts, float width) {
  for (std::size_t i = 1; i < pts.size(); ++i) lines_.push_back({pts[i - 1], pts[i], 0.5f * width});
}

bool NameTags::Clear(const PixelRect& box) const {
  if (box.x0 < bounds_.x0 || box.x1 > bounds_.x1 || box.y0 < bounds_.y0 || box.y1 > bounds_.y1)
    return false;
  for (const PixelRect& t : taken_)
    if (Overlap(t, box)) return false;
  for (const Segment& s : lines_)
    if (Crosses(s.a, s.b, {box.x0 - s.half, box.y0 - s.half, box.x1 + s.half, box.y1 + s.half}))
      return false;
  return true;
}

bool NameTags::Place(Painter& p, const std::string& text, const std::vector<Vec2f>& corners,
                     Rgba color, const Theme& th) {
  const float k = p.k(), font = kFont * k, pad = kPad * k;
  const float w = EstimateTextWidth(text, font, true), h = std::max(kMinFontSize, font);
  for (const Vec2f& c : corners) {
    const PixelRect box{c.x - pad, c.y - pad, c.x + w + pad, c.y + h + pad};
    if (!Clear(box)) continue;
    taken_.push_back(box);
    p.Rect(box, Rgba{th.panel.r, th.panel.g, th.panel.b, 0.72f});
    p.Text(text, {c.x, c.y + 0.5f * h}, font, color, HAlign::kLeft, VAlign::kMiddle, false, true);
    return true;
  }
  return false;
}

bool NameTags::AddLineName(Painter& p, const std::string& text, const std::vector<Vec2f>& pts,
                           Rgba color, const Theme& th) {
  if (pts.empty()) return false;
  const float k = p.k(), w = EstimateTextWidth(text, kFont * k, true);
  const float h = std::max(kMinFontSize, kFont * k), gap = 16 * k;  // clear of a point's name
  std::vector<Vec2f> corners;
  for (float f : {0.5f, 0.35f, 0.65f}) {
    // Off the line square to its direction there (the side up the frame first), by `gap`
    // beyond the half of the box that faces it: clear of a sloping line too.
    const Vec2f at = PolylineAt(pts, f);
    const Vec2f a = PolylineAt(pts, std::max(0.0f, f - 0.02f));
    const Vec2f b = PolylineAt(pts, std::min(1.0f, f + 0.02f));
    const float dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
    Vec2f n = len > 0 ? Vec2f{-dy / len, dx / len} : Vec2f{0, -1};
    if (n.y > 0) n = {-n.x, -n.y};
    const float reach = gap + 0.5f * (w * std::fabs(n.x) + h * std::fabs(n.y));
    for (float side : {1.0f, -1.0f})
      corners.push_back(
          {at.x + side * reach * n.x - 0.5f * w, at.y + side * reach * n.y - 0.5f * h});
  }
  return Place(p, text, corners, color, th);
}

bool NameTags::AddPointName(Painter& p, const std::string& text, Vec2f at, float middle_x,
                            Rgba color, const Theme& th) {
  const float k = p.k(), w = EstimateTextWidth(text, kFont * k, true);
  const float h = std::max(kMinFontSize, kFont * k), gap = 14 * k;
  const Vec2f right{at.x + gap, at.y - 0.5f * h}, left{at.x - gap - w, at.y - 0.5f * h};
  const bool towards_left = at.x > middle_x;
  return Place(p, text,
               {towards_left ? left : right, towards_left ? right : left,
                {at.x - 0.5f * w, at.y - gap - h}, {at.x - 0.5f * w, at.y + gap}},
               color, th);
}

Vec2f PolylineAt(const std::vector<Vec2f>& pts, float f) {
  if (pts.empty()) return {0, 0};
  float total = 0;
  for (std::size_t i = 1; i < pts.size(); ++i)
    total += std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
  float run = 0;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const float len = std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
    if (run + len >= f * total && len > 0) {
      const float u = (f * total - run) / len;
      return {pts[i - 1].x + u * (pts[i].x - pts[i - 1].x),
              pts[i - 1].y + u * (pts[i].y - pts[i - 1].y)};
    }
    run += len;
  }
  return pts.back();
}

}  // namespace cablefilm
