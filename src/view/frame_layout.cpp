#include "view/frame_layout.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "view/header_panel.h"
#include "view/layout_metrics.h"
#include "view/plot_axes.h"

namespace cablefilm {
namespace {

// Geometry in design pixels (times the frame's scale k), beyond layout_metrics.h.
using namespace layout;
constexpr float kMinCableAxes = 240, kMinTensionPanel = 560;
// Share of the height below the header the top row gets: side by side the time plot below is
// full width and needs less height; stacked, the two rows share it evenly.
constexpr float kTopShareSide = 0.56f, kTopShareStacked = 0.5f;
constexpr float kTopShareStackedMin = 0.32f;  // for a flat cable, stacked
// Side by side is chosen unless it shrinks the cable below this share of its stacked scale.
constexpr double kSideBySideMinScale = 0.85;
constexpr double kBoxPad = 0.04;  // around the world box, of its larger side

struct Placed {
  FrameLayout L;
  double ppm = 0;  // the cable's pixels per metre
};

// Plots and the cable's axes inside the given panels, plot tops aligned along each row.
Placed Place(const LayoutRequest& r, FrameLayout L, double wx, double wy) {
  const float k = L.scale;
  const int cable_rows = HeadRowCount(r.cable_head, L.cable_panel.width(), k);
  const int tension_rows = HeadRowCount(r.tension_head, L.tension_panel.width(), k);
  const int time_rows = HeadRowCount(r.time_head, L.max_panel.width(), k);
  int cable_top, tension_top, time_top;
  if (L.side_by_side) {
    cable_top = tension_top = std::max(cable_rows, tension_rows);
    time_top = time_rows;
  } else {
    cable_top = cable_rows;
    tension_top = time_top = std::max(tension_rows, time_rows);
  }
  L.legend_rows = tension_rows > 1 || time_rows > 1;

  // Cable: equal scale, the padded world box centred in the axes area.
  const PixelRect& cp = L.cable_panel;
  const PixelRect axes{cp.x0 + kCableLeft * k, cp.y0 + HeadHeight(cable_top, k),
                       cp.x1 - kCableRight * k, cp.y1 - kPlotBottom * k};
  L.colorbar = {cp.x1 - kColorBarLeft * k, axes.y0, cp.x1 - kColorBarRight * k, axes.y1};
  L.colorbar_caption_x = cp.x1 - kColorBarCaption * k;
  Placed out;
  out.ppm = std::min(axes.width() / wx, axes.height() / wy);
  const double cx = 0.5 * (r.x_min + r.x_max), cy = 0.5 * (r.y_min + r.y_max);
  L.cable.rect = axes;
  L.cable.x_lo = cx - axes.width() / out.ppm / 2;
  L.cable.x_hi = cx + axes.width() / out.ppm / 2;
  L.cable.y_lo = cy - axes.height() / out.ppm / 2;
  L.cable.y_hi = cy + axes.height() / out.ppm / 2;

  double t_lo = r.tension_min / kNewtonsPerKilonewton, t_hi = r.tension_max / kNewtonsPerKilonewton;
  NiceRange(&t_lo, &t_hi, 6);
  auto plot_area = [&](const PixelRect& p, int rows) {
    return PixelRect{p.x0 + kPlotLeft * k, p.y0 + HeadHeight(rows, k), p.x1 - kPlotRight * k,
                     p.y1 - kPlotBottom * k};
  };
  L.tension.rect = plot_area(L.tension_panel, tension_top);
  L.tension.x_lo = 0;
  L.tension.x_hi = r.arc_length;
  L.tension.y_lo = t_lo;
  L.tension.y_hi = t_hi;
  L.max_tension.rect = plot_area(L.max_panel, time_top);
  L.max_tension.x_lo = r.t_lo;
  L.max_tension.x_hi = r.t_hi;
  L.max_tension.y_lo = t_lo;
  L.max_tension.y_hi = t_hi;
  out.L = L;
  return out;
}

}  // namespace

FrameLayout StartFrameLayout(int width, int height, double tension_min, double tension_max,
                             double t_lo, double t_hi, double arc_length) {
  if (width < 16 || height < 16)
    throw Error("frame: size " + std::to_string(width) + "x" + std::to_string(height) +
                " is too small");
  if (!(tension_max > tension_min))
    throw Error("frame: tension range must be increasing, got [" + std::to_string(tension_min) +
                ", " + std::to_string(tension_max) + "] N");
  if (!(t_hi > t_lo) || !(arc_length > 0))
    throw Error("frame: time axis [" + std::to_string(t_lo) + ", " + std::to_string(t_hi) +
                "] s and cable length " + std::to_string(arc_length) +
                " m must be increasing and positive");
  FrameLayout L;
  L.width = width;
  L.height = height;
  const float k = std::min(width / 1920.0f, height / 1080.0f);
  L.scale = k;
  L.cable_width = std::max(1.5f, 6 * k);
  L.overlay_width = std::max(2.0f, 0.6f * L.cable_width);
  return L;
}

FrameLayout LayoutFrame(const LayoutRequest& r, int width, int height) {
  FrameLayout L = StartFrameLayout(width, height, r.tension_min, r.tension_max, r.t_lo, r.t_hi,
                                   r.arc_length);
  if (!(r.x_max >= r.x_min) || !(r.y_max >= r.y_min))
    throw Error("frame: invalid world box x [" + std::to_string(r.x_min) + ", " +
                std::to_string(r.x_max) + "], y [" + std::to_string(r.y_min) + ", " +
                std::to_string(r.y_max) + "] m");
  const float k = L.scale;
  const float W = static_cast<float>(width), H = static_cast<float>(height);
  const float m = kMargin * k, gap = kGap * k, header = HeaderHeight(k);
  const float avail = H - header - m, content = W - 2 * m;
  const double dx = r.x_max - r.x_min, dy = r.y_max - r.y_min;
  const double pad = kBoxPad * std::max({dx, dy, 1e-6});
  const double wx = dx + 2 * pad, wy = dy + 2 * pad;
  const double aspect = r.fit_aspect > 0 ? r.fit_aspect : wx / wy;

  // Stacked: the cable across the top, the two plots side by side below. A flat cable, whose
  // scale the width limits, gets a top row only as high as it needs (in steps of 1/48 of the
  // height): the plots below take the rest.
  FrameLayout stacked = L;
  {
    const float axes_w = content - (kCableLeft + kCableRight) * k;
    const float want = HeadHeight(HeadRowCount(r.cable_head, content, k), k) + kPlotBottom * k +
                       static_cast<float>(axes_w / aspect);
    const float step = avail / 48;
    const float top_h = std::round(std::clamp(std::ceil(want / step) * step,
                                              kTopShareStackedMin * avail, kTopShareStacked * avail));
    const float half = (content - gap) / 2;
    stacked.cable_panel = {m, header, W - m, header + top_h};
    const float y0 = header + top_h + gap;
    stacked.tension_panel = {m, y0, m + half, H - m};
    stacked.max_panel = {m + half + gap, y0, W - m, H - m};
  }
  const Placed best_stacked = Place(r, stacked, wx, wy);

  // Side by side: the cable panel as wide as the box needs at the top row's height (in steps
  // of 1/64 of the width, so that a box that changes a little leaves the panels in place),
  // within what its legend and the tension panel beside it need.
  const float min_cable = std::max(HeadMinWidth(r.cable_head, k),
                                   (kCableLeft + kMinCableAxes + kCableRight) * k);
  const float max_cable =
      content - gap - std::max(HeadMinWidth(r.tension_head, k), kMinTensionPanel * k);
  if (max_cable < min_cable) return best_stacked.L;
  const float top_h = std::round(kTopShareSide * avail);
  const float step = content / 64;
  float cable_w = min_cable;
  int rows = 1;
  for (int iteration = 0; iteration < 3; ++iteration) {  // the head rows depend on the width
    const float axes_h = top_h - HeadHeight(rows, k) - kPlotBottom * k;
    const float want = (kCableLeft + kCableRight) * k + static_cast<float>(aspect) * axes_h;
    cable_w = std::clamp(std::ceil(want / step) * step, min_cable, max_cable);
    cable_w = std::round(cable_w);
    const int now = std::max(HeadRowCount(r.cable_head, cable_w, k),
                             HeadRowCount(r.tension_head, content - gap - cable_w, k));
    if (now == rows) break;
    rows = now;
  }
  FrameLayout side = L;
  side.side_by_side = true;
  side.cable_panel = {m, header, m + cable_w, header + top_h};
  side.tension_panel = {m + cable_w + gap, header, W - m, header + top_h};
  side.max_panel = {m, header + top_h + gap, W - m, H - m};
  const Placed best_side = Place(r, side, wx, wy);
  return best_side.ppm >= kSideBySideMinScale * best_stacked.ppm ? best_side.L : best_stacked.L;
}

}  // namespace cablefilm
