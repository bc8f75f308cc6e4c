#pragma once
// Colours of the frames: the film and the live view use the dark theme, the still of the
// maximum tension the light one (print). Plus the two colour helpers the panels use.
#include <cstddef>
#include <cstdint>

#include "view/frame.h"

namespace cablefilm {

struct Theme {
  Rgba background, panel, grid, axis, text, text_dim, current, equilibrium, envelope, accent,
      halo, marker_fill, marker_edge;
  Rgba overlay, overlay_rim;  // lines after the first: their curves; their shape's dotted rim
  Rgba event;  // control changes marked on the live view's time plot (apart from the accent)
  Rgba water;   // the water surface's line (the water below it a faint wash)
  Rgba seabed;  // the seabed's line in the cable panel (the ground below it a faint mix)
  // The lines of a system drawn alike (SceneView::lines_alike): a colour each in the plots and
  // for its name (LineColor), apart from one another and from the panels' other colours.
  static constexpr int kLineColors = 8;
  Rgba line_colors[kLineColors];
  static Theme Dark();
  static Theme Light();
};

// The colour of line i of lines drawn alike (the palette repeats after kLineColors lines).
Rgba LineColor(const Theme& th, std::size_t line);

// The width of curve i of n drawn over each other in one plot [design px]: one is 2.4 wide;
// several go from 4.2 (the first, at the bottom) to 1.8 (the last, on top), so that where
// curves coincide (a symmetric mooring's legs) each still shows as an edge of the one under it.
float NestedWidth(std::size_t i, std::size_t n);

// 0xRRGGBB with alpha a.
Rgba Hex(std::uint32_t rgb, float a = 1);
// Opaque blend of a over b (t = weight of a): faint lines stay opaque, so joints of a
// polyline do not double-blend.
Rgba Mix(Rgba a, Rgba b, float t);

}  // namespace cablefilm
