#include "view/header_panel.h"

#include <algorithm>

namespace cablefilm {

float HeaderHeight(float k) { return 86 * k; }

void DrawHeader(Painter& p, float width, const HeaderInput& in, const Theme& th) {
  const float k = p.k(), m = 24 * k;  // m: the frame's margin
  p.Text(in.title, {m, 44 * k}, 30 * k, th.text, HAlign::kLeft, VAlign::kBaseline, false, true);
  float x = m;
  if (!in.status.empty()) {
    p.Disc({x + 5 * k, 64.5f * k}, 5 * k, th.accent);
    x += 16 * k;
    p.Text(in.status, {x, 70 * k}, 16 * k, th.accent, HAlign::kLeft, VAlign::kBaseline, false,
           true);
    x += EstimateTextWidth(in.status, 16 * k, true) + 18 * k;
  }
  p.Text(in.subtitle, {x, 70 * k}, 16 * k, th.text_dim);
  p.Text(in.time, {width - m, 44 * k}, 30 * k, th.text, HAlign::kRight, VAlign::kBaseline, false,
         true);
  p.Text(in.note, {width - m, 70 * k}, 16 * k, th.text_dim, HAlign::kRight);
  if (in.progress >= 0) {
    // The bar ends clear of the note (whose font may be raised to kMinFontSize).
    const float x1 = width - m - std::max(90 * k, EstimateTextWidth(in.note, 16 * k) + 14 * k);
    const float x0 = x1 - 170 * k, y = 64 * k;
    const float f = static_cast<float>(std::clamp(in.progress, 0.0, 1.0));
    p.Rect({x0, y - 2 * k, x1, y + 2 * k}, th.grid);
    p.Rect({x0, y - 2 * k, x0 + f * (x1 - x0), y + 2 * k}, th.accent);
  }
}

}  // namespace cablefilm
