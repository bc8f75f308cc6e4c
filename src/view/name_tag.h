#pragma once
// Names written on the picture of a system of lines: each line's name beside its shape, in the
// line's colour, and each point's name beside its marker, on a veil of the panel's colour so
// that they read over the seabed and the water. A name never covers another, nor a line: each
// goes in the first free place of a few around its anchor, or is left out (points crowded
// together at this scale: their lines' names and markers still show them). Points are named
// first (fewer places suit them), then lines.
#include <string>
#include <vector>

#include "view/painter.h"
#include "view/theme.h"

namespace cablefilm {

class NameTags {
 public:
  // Names kept inside `bounds` [px].
  explicit NameTags(const PixelRect& bounds) : bounds_(bounds) {}
  // A line drawn `width` px wide along `pts` [px]: no name goes over it.
  void Avoid(const std::vector<Vec2f>& pts, float width);
  // A line's name by the polyline `pts` [px]: beside its middle (by length), on the side up
  // the frame, else the other, else the same about a third of the way from either end; false
  // when none is free.
  bool AddLineName(Painter& p, const std::string& text, const std::vector<Vec2f>& pts,
                   Rgba color, const Theme& th);
  // `text` beside a marker at `at` [px], on the side towards `middle` first, then the other,
  // above, below; false when none is free.
  bool AddPointName(Painter& p, const std::string& text, Vec2f at, float middle_x, Rgba color,
                    const Theme& th);

 private:
  // The first of `boxes` (text boxes, top left corners) inside the bounds and clear of the
  // names so far: drawn there.
  bool Place(Painter& p, const std::string& text, const std::vector<Vec2f>& corners, Rgba color,
             const Theme& th);
  bool Clear(const PixelRect& box) const;
  PixelRect bounds_;
  std::vector<PixelRect> taken_;
  struct Segment {
    Vec2f a, b;
    float half;  // half the line's width [px]
  };
  std::vector<Segment> lines_;
};

// The point a fraction `f` of the way along the polyline `pts` [px] by length.
Vec2f PolylineAt(const std::vector<Vec2f>& pts, float f);

}  // namespace cablefilm
