#pragma once
// Names written on the picture of a system of lines: each line's name beside its shape, in the
// line's colour, and each point's name beside its marker, on a veil of the panel's colour so
// that they read over the lines, the seabed and the water. A name never covers another: each
// goes in the first free place of a few around its anchor, or is left out (points crowded
// together at this scale: their lines' names and markers still show them).
#include <string>
#include <vector>

#include "view/painter.h"
#include "view/theme.h"

namespace cablefilm {

class NameTags {
 public:
  // Names kept inside `bounds` [px].
  explicit NameTags(const PixelRect& bounds) : bounds_(bounds) {}
  // `text` centred above `at` [px] (a line's name), else below, right or left of it; false
  // when none is free.
  bool AddLineName(Painter& p, const std::string& text, Vec2f at, Rgba color, const Theme& th);
  // `text` beside a marker at `at` [px], on the side towards `middle` first, then the other,
  // above, below; false when none is free.
  bool AddPointName(Painter& p, const std::string& text, Vec2f at, float middle_x, Rgba color,
                    const Theme& th);

 private:
  // The first of `boxes` (text boxes, top left corners) inside the bounds and clear of the
  // names so far: drawn there.
  bool Place(Painter& p, const std::string& text, const std::vector<Vec2f>& corners, Rgba color,
             const Theme& th);
  PixelRect bounds_;
  std::vector<PixelRect> taken_;
};

// Where a line's name goes: the middle of the polyline `pts` [px] by length.
Vec2f PolylineMiddle(const std::vector<Vec2f>& pts);

}  // namespace cablefilm
