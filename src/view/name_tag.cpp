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

}  // namespace

bool NameTags::Place(Painter& p, const std::string& text, const std::vector<Vec2f>& corners,
                     Rgba color, const Theme& th) {
  const float k = p.k(), font = kFont * k, pad = kPad * k;
  const float w = EstimateTextWidth(text, font, true), h = std::max(kMinFontSize, font);
  for (const Vec2f& c : corners) {
    const PixelRect box{c.x - pad, c.y - pad, c.x + w + pad, c.y + h + pad};
    if (box.x0 < bounds_.x0 || box.x1 > bounds_.x1 || box.y0 < bounds_.y0 || box.y1 > bounds_.y1)
      continue;
    if (std::any_of(taken_.begin(), taken_.end(),
                    [&](const PixelRect& t) { return Overlap(t, box); }))
      continue;
    taken_.push_back(box);
    p.Rect(box, Rgba{th.panel.r, th.panel.g, th.panel.b, 0.72f});
    p.Text(text, {c.x, c.y + 0.5f * h}, font, color, HAlign::kLeft, VAlign::kMiddle, false, true);
    return true;
  }
  return false;
}

bool NameTags::AddLineName(Painter& p, const std::string& text, Vec2f at, Rgba color,
                           const Theme& th) {
  const float k = p.k(), w = EstimateTextWidth(text, kFont * k, true);
  const float h = std::max(kMinFontSize, kFont * k), gap = 12 * k;
  return Place(p, text,
               {{at.x - 0.5f * w, at.y - gap - h}, {at.x - 0.5f * w, at.y + gap},
                {at.x + gap, at.y - 0.5f * h}, {at.x - gap - w, at.y - 0.5f * h}},
               color, th);
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

Vec2f PolylineMiddle(const std::vector<Vec2f>& pts) {
  if (pts.empty()) return {0, 0};
  float total = 0;
  for (std::size_t i = 1; i < pts.size(); ++i)
    total += std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
  float run = 0;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const float len = std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
    if (run + len >= 0.5f * total && len > 0) {
      const float f = (0.5f * total - run) / len;
      return {pts[i - 1].x + f * (pts[i].x - pts[i - 1].x),
              pts[i - 1].y + f * (pts[i].y - pts[i - 1].y)};
    }
    run += len;
  }
  return pts.back();
}

}  // namespace cablefilm
