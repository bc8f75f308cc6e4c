#include "view/colorbar_panel.h"

#include <algorithm>
#include <cmath>

#include "view/plot_axes.h"

namespace cablefilm {

void DrawColorBar(Painter& p, const ColorBarInput& in, const Colormap& colormap, const Theme& th) {
  const float k = p.k();
  const PixelRect& cb = in.bar;
  constexpr int kBands = 128;  // finer than a table entry's step is invisible
  for (int i = 0; i < kBands; ++i) {
    const float y1 = cb.y1 - cb.height() * i / kBands, y0 = cb.y1 - cb.height() * (i + 1) / kBands;
    p.Rect({cb.x0, std::floor(y0), cb.x1, std::ceil(y1)}, colormap.At((i + 0.5) / kBands));
  }
  p.Line({cb.x0, cb.y0}, {cb.x1, cb.y0}, 1 * k, th.axis);
  p.Line({cb.x0, cb.y1}, {cb.x1, cb.y1}, 1 * k, th.axis);
  p.Line({cb.x0, cb.y0}, {cb.x0, cb.y1}, 1 * k, th.axis);
  p.Line({cb.x1, cb.y0}, {cb.x1, cb.y1}, 1 * k, th.axis);
  const double lo = in.tension_min / kNewtonsPerKilonewton, hi = in.tension_max / kNewtonsPerKilonewton;
  const Ticks ct = NiceTicks(lo, hi, 6);
  auto bar_y = [&](double kn) {  // clamped: a tension beyond the range marks the bar's end
    return std::clamp(static_cast<float>(cb.y1 - (kn - lo) / (hi - lo) * cb.height()), cb.y0, cb.y1);
  };
  for (double v : ct.values) {
    const float y = bar_y(v);
    p.Line({cb.x1, y}, {cb.x1 + 5 * k, y}, 1.2f * k, th.axis);
    p.Text(FormatTick(v, ct.decimals), {cb.x1 + 9 * k, y}, 15 * k, th.text_dim, HAlign::kLeft,
           VAlign::kMiddle);
  }
  p.Text(in.caption, {in.caption_x, (cb.y0 + cb.y1) / 2}, 16 * k, th.text_dim, HAlign::kCenter,
         VAlign::kBottom, true);
  for (std::size_t i = 0; in.now && i < in.now->size(); ++i) {
    const std::vector<double>& T = (*in.now)[i].tension;
    if (T.empty()) continue;
    const double now = *std::max_element(T.begin(), T.end());
    if (!std::isfinite(now)) continue;
    const float y = bar_y(now / kNewtonsPerKilonewton);
    const float step = static_cast<float>(10 * i);  // [design px]: each line's further left
    const float x0 = cb.x0 - (step + 10) * k, x1 = cb.x0 - (step + 1) * k;
    const Rgba c = in.alike ? LineColor(th, i) : i == 0 ? th.text : th.overlay;
    p.Triangle({x0, y - 6 * k}, {x0, y + 6 * k}, {x1, y}, c);
  }
}

}  // namespace cablefilm
