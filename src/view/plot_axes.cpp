#include "view/plot_axes.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {

Vec2f PlotPoint(const PlotMapping& m, double x, double y) {
  Vec2f p = m.ToPixel(x, y);
  p.x = std::clamp(p.x, m.rect.x0, m.rect.x1);
  p.y = std::clamp(p.y, m.rect.y0, m.rect.y1);
  return p;
}

void DrawAxes(Painter& p, const PlotMapping& m, const std::string& x_label,
              const std::string& y_label, const Theme& th, int x_target, int y_target) {
  const float k = p.k();
  const PixelRect& r = m.rect;
  const Ticks xt = NiceTicks(m.x_lo, m.x_hi, x_target);
  const Ticks yt = NiceTicks(m.y_lo, m.y_hi, y_target);
  const float tick_font = 15 * k, label_font = 16 * k;
  for (double x : xt.values) {
    const float px = m.PixelX(x);
    p.Line({px, r.y0}, {px, r.y1}, 1 * k, th.grid);
    p.Line({px, r.y1}, {px, r.y1 + 5 * k}, 1.2f * k, th.axis);
    p.Text(FormatTick(x, xt.decimals), {px, r.y1 + 8 * k}, tick_font, th.text_dim, HAlign::kCenter,
           VAlign::kTop);
  }
  for (double y : yt.values) {
    const float py = m.PixelY(y);
    p.Line({r.x0, py}, {r.x1, py}, 1 * k, th.grid);
    p.Line({r.x0 - 5 * k, py}, {r.x0, py}, 1.2f * k, th.axis);
    p.Text(FormatTick(y, yt.decimals), {r.x0 - 9 * k, py}, tick_font, th.text_dim, HAlign::kRight,
           VAlign::kMiddle);
  }
  p.Line({r.x0, r.y1}, {r.x1, r.y1}, 1.2f * k, th.axis);
  p.Line({r.x0, r.y0}, {r.x0, r.y1}, 1.2f * k, th.axis);
  p.Text(x_label, {(r.x0 + r.x1) / 2, r.y1 + 30 * k}, label_font, th.text_dim, HAlign::kCenter,
         VAlign::kTop);
  p.Text(y_label, {r.x0 - 58 * k, (r.y0 + r.y1) / 2}, label_font, th.text_dim, HAlign::kCenter,
         VAlign::kBottom, true);
}

std::vector<Vec2f> DecimatedTrace(const PlotMapping& m, const std::vector<double>& ts,
                                  const std::vector<double>& vs, double unit) {
  std::vector<Vec2f> trace;
  // Columns outside the plot are clamped to one just beyond each side.
  const int first = static_cast<int>(std::floor(m.rect.x0)) - 1;
  const int last = static_cast<int>(std::ceil(m.rect.x1)) + 1;
  int column = first - 1;  // none yet
  std::size_t lo_i = 0, hi_i = 0;
  auto flush = [&]() {
    if (column < first) return;
    const std::size_t a = std::min(lo_i, hi_i), b = std::max(lo_i, hi_i);
    trace.push_back(PlotPoint(m, ts[a], vs[a] / unit));
    if (b != a) trace.push_back(PlotPoint(m, ts[b], vs[b] / unit));
  };
  for (std::size_t i = 0; i < std::min(ts.size(), vs.size()); ++i) {
    if (std::isnan(vs[i]) || !std::isfinite(ts[i])) continue;
    const double x = m.PixelX(ts[i]);  // double: a far-off time must not overflow an int
    const int col = static_cast<int>(std::floor(std::clamp<double>(x, first, last)));
    if (col != column) {
      flush();
      column = col;
      lo_i = hi_i = i;
    } else {
      if (vs[i] < vs[lo_i]) lo_i = i;
      if (vs[i] > vs[hi_i]) hi_i = i;
    }
  }
  flush();
  return trace;
}

}  // namespace cablefilm
