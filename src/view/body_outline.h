#pragma once
// A body's outline through its points: the points in turn about their centre (by their angle
// in the picture's plane, or in the horizontal plane in space), closed, so that three or more
// fairleads draw the hull's shape at their level; two draw a segment, one nothing.
#include <vector>

#include "view/frame.h"

namespace cablefilm {

// The closed loop through `points` (the first repeated at the end); empty below two points.
std::vector<Vec2f> BodyOutline(std::vector<Vec2f> points);
// The same in space, turning about the vertical (y) through their centre.
std::vector<Vec3f> BodyOutline(std::vector<Vec3f> points);

}  // namespace cablefilm
