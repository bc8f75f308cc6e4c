#pragma once
// Where the header and the four panels of a frame go (the film's and the live view's alike),
// with the data-to-pixel maps of their plots. The cable is drawn to scale (equal x and y), so
// the cable panel is given the width its box needs: when that leaves room, the cable sits at
// the left of the top row beside the tension along the cable, above a full-width time plot;
// when the cable is too wide for that, it takes the whole top row above the two plots.
#include <string>

#include "view/legend.h"
#include "view/plot_layout.h"

namespace cablefilm {

struct FrameLayout {
  int width = 0, height = 0;
  float scale = 1;         // size of a "design pixel" of the 1920x1080 layout [px]
  // true: cable | tension along the cable on top, tension against time below (full width);
  // false: cable on top (full width), tension along the cable | tension against time below.
  bool side_by_side = false;
  PixelRect cable_panel, tension_panel, max_panel;  // max_panel: tension against time
  PlotMapping cable;       // world [m] -> pixels, equal scale in x and y
  PlotMapping tension;     // unstretched arc length [m], tension [kN]
  PlotMapping max_tension; // time [s], tension [kN]
  PixelRect colorbar;      // the colour bar: bottom = tension_min, top = tension_max
  float colorbar_caption_x = 0;  // where the colour bar's vertical caption goes [px]
  float cable_width = 6;   // [px]
  float overlay_width = 3.6f;  // each line's after the first (drawn under the first's) [px]
  // A plot's head (title and legend) takes a second row: its plot starts lower.
  bool legend_rows = false;
  // In space (space_layout.h): the perspective view and its colour bar at the left of the top
  // row, the plan over the elevation at its right, the two plots below; cable_panel and cable
  // are then unused.
  bool space = false;
  PixelRect space_panel;      // the perspective view's panel (its head, its colour bar)
  PixelRect space_view;       // where the 3D scene is drawn [px], whole pixels
  PixelRect plan_panel, elevation_panel;
  PlotMapping plan;           // x [m] across, z [m] down: seen from above (y towards the eye)
  PlotMapping elevation;      // distance along the ends' vertical plane [m] across, y [m] up
};

struct LayoutRequest {
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;  // world box the cable panel shows [m]
  // Width / height of the world box the cable panel's width is fitted to; 0 = the box's own.
  // (A live view whose box follows the cable can pass a steady value so panels stay put.)
  double fit_aspect = 0;
  double arc_length = 1;                   // of the whole cable [m], > 0
  double t_lo = 0, t_hi = 1;               // time axis [s], increasing
  double tension_min = 0, tension_max = 1; // [N], increasing; the plots widen it to nice ticks
  PanelHead cable_head, tension_head, time_head;  // titles and legends (sizes matter only)
};

// Throws Error on a frame smaller than 16x16 or an invalid range.
FrameLayout LayoutFrame(const LayoutRequest& request, int width, int height);

// What every layout starts from: the frame's size, scale and line widths, after checking the
// size, the tension range [N] and the time axis [s] and cable length [m] (throws Error naming
// the bad one). Used by LayoutFrame and LayoutSpaceFrame (space_layout.h).
FrameLayout StartFrameLayout(int width, int height, double tension_min, double tension_max,
                             double t_lo, double t_hi, double arc_length);

}  // namespace cablefilm
