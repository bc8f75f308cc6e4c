#pragma once
// The colour bar of the cable's tension: the colour map from bottom (tension_min) to top
// (tension_max) with kN ticks on its right, a vertical caption, and marks at each line's
// largest tension now.
#include <string>

#include "view/colormap.h"
#include "view/painter.h"
#include "view/snapshot.h"
#include "view/theme.h"

namespace cablefilm {

struct ColorBarInput {
  PixelRect bar;          // the bar itself [px]
  float caption_x = 0;    // where the vertical caption's bottom edge goes [px]
  double tension_min = 0, tension_max = 1;  // the colour range [N], increasing
  std::string caption = "tension [kN]";
  // The lines now: a mark left of the bar at each one's largest tension (the first's in the
  // text colour, each after it in the overlay colour, further left); null = none.
  const std::vector<LineSnapshot>* now = nullptr;
  bool alike = false;  // lines drawn alike: each mark in its line's colour (LineColor)
};

void DrawColorBar(Painter& p, const ColorBarInput& in, const Colormap& colormap, const Theme& th);

}  // namespace cablefilm
