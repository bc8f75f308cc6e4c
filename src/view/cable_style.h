#pragma once
// How a line after the first (an overlay) is drawn, shared by the cable panel and its legend
// swatch: a thinner line of the tension colour inside a dotted light rim, so that it still shows
// where the first line (drawn on top) covers it.
#include <vector>

#include "view/painter.h"
#include "view/theme.h"

namespace cablefilm {

// The polyline moved sideways by d pixels (along the bisector of its segments' normals).
std::vector<Vec2f> OffsetPolyline(const std::vector<Vec2f>& p, float d);

// The dotted rim: a dotted outline on both sides of pts, rim_width apart [px].
void DrawOverlayRim(Painter& p, const std::vector<Vec2f>& pts, float rim_width, const Theme& th);
// Rim and line in one colour (the legend's swatch; the panel colours the line link by link).
void DrawOverlayLine(Painter& p, const std::vector<Vec2f>& pts, float width, float rim_width,
                     Rgba color, const Theme& th);

}  // namespace cablefilm
