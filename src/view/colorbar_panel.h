#pragma once
// The colour bar of the cable's tension: the colour map from bottom (tension_min) to top
// (tension_max) with kN ticks on its right, a vertical caption, and marks at the current
// largest tension of the cable (and of its companion).
#include <limits>
#include <string>

#include "view/colormap.h"
#include "view/painter.h"
#include "view/theme.h"

namespace cablefilm {

struct ColorBarInput {
  PixelRect bar;          // the bar itself [px]
  float caption_x = 0;    // where the vertical caption's bottom edge goes [px]
  double tension_min = 0, tension_max = 1;  // the colour range [N], increasing
  std::string caption = "tension [kN]";
  // The largest tension now [N]: a mark left of the bar (NaN = none); the companion's, in its
  // curve colour, just left of it.
  double now = std::numeric_limits<double>::quiet_NaN();
  double companion_now = std::numeric_limits<double>::quiet_NaN();
};

void DrawColorBar(Painter& p, const ColorBarInput& in, const Colormap& colormap, const Theme& th);

}  // namespace cablefilm
