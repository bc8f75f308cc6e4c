#include "view/space_layout.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "view/header_panel.h"
#include "view/layout_metrics.h"
#include "view/plot_axes.h"

namespace cablefilm {
namespace {

using namespace layout;
// Shares of the height below the header (the top row) and of the width (the plan and elevation
// column): the perspective view is the picture, the plots below as high as a stacked 2D frame's
// at its flattest.
constexpr float kTopShare = 0.6f, kSideShare = 0.38f;
constexpr float kViewInset = 12;  // the 3D scene inside its panel, left and bottom
constexpr double kBoxPad = 0.04;  // around the plan's and elevation's boxes, of the larger side

// `rect` showing [c - half_w, c + half_w] across at `ppm` pixels per metre, centred on (cx, cy);
// `down`: the vertical value grows downwards.
PlotMapping ToScale(const PixelRect& rect, double cx, double cy, double ppm, bool down) {
  PlotMapping m;
  m.rect = rect;
  const double hw = rect.width() / ppm / 2, hh = rect.height() / ppm / 2;
  m.x_lo = cx - hw;
  m.x_hi = cx + hw;
  m.y_lo = down ? cy + hh : cy - hh;
  m.y_hi = down ? cy - hh : cy + hh;
  return m;
}

PixelRect WholePixels(const PixelRect& r) {
  PixelRect w{std::round(r.x0), std::round(r.y0), std::round(r.x1), std::round(r.y1)};
  w.x1 = std::max(w.x1, w.x0 + 1);
  w.y1 = std::max(w.y1, w.y0 + 1);
  return w;
}

}  // namespace

FrameLayout LayoutSpaceFrame(const SpaceLayoutRequest& r, int width, int height) {
  FrameLayout L = StartFrameLayout(width, height, r.tension_min, r.tension_max, r.t_lo, r.t_hi,
                                   r.arc_length);
  for (double v : {r.x_min, r.x_max, r.z_min, r.z_max, r.s_min, r.s_max, r.y_min, r.y_max})
    if (!std::isfinite(v)) throw Error("frame: the world box is not finite");
  if (!(r.x_max >= r.x_min) || !(r.z_max >= r.z_min) || !(r.s_max >= r.s_min) ||
      !(r.y_max >= r.y_min))
    throw Error("frame: invalid world box x [" + std::to_string(r.x_min) + ", " +
                std::to_string(r.x_max) + "], y [" + std::to_string(r.y_min) + ", " +
                std::to_string(r.y_max) + "], z [" + std::to_string(r.z_min) + ", " +
                std::to_string(r.z_max) + "] m");
  L.space = true;
  const float k = L.scale;
  const float W = static_cast<float>(width), H = static_cast<float>(height);
  const float m = kMargin * k, gap = kGap * k, header = HeaderHeight(k);
  const float avail = H - header - m, content = W - 2 * m;
  const float top_h = std::round(kTopShare * avail);
  const float side_w = std::round(kSideShare * (content - gap));

  // The top row: the perspective view, then the plan over the elevation.
  L.space_panel = {m, header, W - m - side_w - gap, header + top_h};
  L.cable_panel = L.space_panel;
  const int space_rows = HeadRowCount(r.space_head, L.space_panel.width(), k);
  const PixelRect& sp = L.space_panel;
  L.space_view = WholePixels({sp.x0 + kViewInset * k, sp.y0 + HeadHeight(space_rows, k),
                              sp.x1 - kCableRight * k, sp.y1 - kViewInset * k});
  L.colorbar = {sp.x1 - kColorBarLeft * k, L.space_view.y0, sp.x1 - kColorBarRight * k,
                L.space_view.y1};
  L.colorbar_caption_x = sp.x1 - kColorBarCaption * k;

  // Plan and elevation to one scale: the largest that fits both in the column's width and,
  // one over the other, in its height; height to spare goes to both alike.
  const float x0 = W - m - side_w, x1 = W - m;
  const int plan_rows = HeadRowCount(r.plan_head, side_w, k);
  const int elevation_rows = HeadRowCount(r.elevation_head, side_w, k);
  const double pad = kBoxPad * std::max({r.x_max - r.x_min, r.z_max - r.z_min,
                                         r.s_max - r.s_min, r.y_max - r.y_min, 1e-6});
  const double plan_w = r.x_max - r.x_min + 2 * pad, plan_h = r.z_max - r.z_min + 2 * pad;
  const double elev_w = r.s_max - r.s_min + 2 * pad, elev_h = r.y_max - r.y_min + 2 * pad;
  const float axes_w = std::max(1.0f, side_w - (kCableLeft + kPlotRight) * k);
  const float fixed_h = HeadHeight(plan_rows, k) + HeadHeight(elevation_rows, k) +
                        2 * kPlotBottom * k + gap;
  const float axes_h = std::max(2.0f, top_h - fixed_h);
  const double ppm = std::min(axes_w / std::max(plan_w, elev_w), axes_h / (plan_h + elev_h));
  const float spare = std::max(0.0f, axes_h - static_cast<float>(ppm * (plan_h + elev_h)));
  const float plan_axes_h = static_cast<float>(ppm * plan_h) + spare / 2;
  L.plan_panel = {x0, header, x1,
                  std::round(header + HeadHeight(plan_rows, k) + plan_axes_h + kPlotBottom * k)};
  L.elevation_panel = {x0, L.plan_panel.y1 + gap, x1, header + top_h};
  auto axes = [&](const PixelRect& p, int rows) {
    return PixelRect{p.x0 + kCableLeft * k, p.y0 + HeadHeight(rows, k), p.x1 - kPlotRight * k,
                     std::max(p.y0 + HeadHeight(rows, k) + 1, p.y1 - kPlotBottom * k)};
  };
  L.plan = ToScale(axes(L.plan_panel, plan_rows), 0.5 * (r.x_min + r.x_max),
                   0.5 * (r.z_min + r.z_max), ppm, true);
  L.elevation = ToScale(axes(L.elevation_panel, elevation_rows), 0.5 * (r.s_min + r.s_max),
                        0.5 * (r.y_min + r.y_max), ppm, false);

  // The plots below, their tops aligned.
  const float y0 = header + top_h + gap, half = (content - gap) / 2;
  L.tension_panel = {m, y0, m + half, H - m};
  L.max_panel = {m + half + gap, y0, W - m, H - m};
  const int tension_rows = HeadRowCount(r.tension_head, L.tension_panel.width(), k);
  const int time_rows = HeadRowCount(r.time_head, L.max_panel.width(), k);
  const int rows = std::max(tension_rows, time_rows);
  L.legend_rows = tension_rows > 1 || time_rows > 1;
  double t_lo = r.tension_min / kNewtonsPerKilonewton, t_hi = r.tension_max / kNewtonsPerKilonewton;
  NiceRange(&t_lo, &t_hi, 6);
  auto plot_area = [&](const PixelRect& p) {
    return PixelRect{p.x0 + kPlotLeft * k, p.y0 + HeadHeight(rows, k), p.x1 - kPlotRight * k,
                     p.y1 - kPlotBottom * k};
  };
  L.tension.rect = plot_area(L.tension_panel);
  L.tension.x_lo = 0;
  L.tension.x_hi = r.arc_length;
  L.tension.y_lo = t_lo;
  L.tension.y_hi = t_hi;
  L.max_tension.rect = plot_area(L.max_panel);
  L.max_tension.x_lo = r.t_lo;
  L.max_tension.x_hi = r.t_hi;
  L.max_tension.y_lo = t_lo;
  L.max_tension.y_hi = t_hi;
  return L;
}

}  // namespace cablefilm
