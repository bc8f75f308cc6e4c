#pragma once
// Where the panels of a frame of lines in space go (FrameLayout with space = true): the header;
// on the top row the perspective view with its colour bar, and beside it the plan (from above)
// over the elevation (the vertical plane through the ends), both to one scale so that their
// lengths compare; below, the tension along the lines beside the tension against time.
#include "view/frame_layout.h"
#include "view/legend.h"

namespace cablefilm {

struct SpaceLayoutRequest {
  double x_min = 0, x_max = 1, z_min = 0, z_max = 1;  // the plan's box [m]
  double s_min = 0, s_max = 1, y_min = 0, y_max = 1;  // the elevation's box: along the plane, up [m]
  double arc_length = 1;                              // of the longest line [m], > 0
  double t_lo = 0, t_hi = 1;                          // time axis [s], increasing
  double tension_min = 0, tension_max = 1;            // [N], increasing
  PanelHead space_head, plan_head, elevation_head, tension_head, time_head;
};

// Throws Error on a frame smaller than 16x16 or an invalid range or box.
FrameLayout LayoutSpaceFrame(const SpaceLayoutRequest& request, int width, int height);

}  // namespace cablefilm
