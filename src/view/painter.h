#pragma once
// Appends shapes and text to a Frame in pixel coordinates, with the frame's "design pixel"
// scale k (1 at 1920x1080) that every panel multiplies its sizes by. Plus the two text helpers
// the panels share: a printf of one number, and an estimate of a label's width.
#include <string>
#include <vector>

#include "view/frame.h"
#include "view/plot_layout.h"

namespace cablefilm {

// Smallest font size a text item gets [px]: smaller glyphs are unreadable blurs.
constexpr float kMinFontSize = 6;

class Painter {
 public:
  Painter(Frame* frame, float scale) : f_(*frame), k_(scale) {}
  float k() const { return k_; }

  void Rect(const PixelRect& r, Rgba c) { Add(ShapeKind::kRect, {r.x0, r.y0}, {r.x1, r.y1}, 0, c); }
  void Line(Vec2f a, Vec2f b, float width, Rgba c) { Add(ShapeKind::kSegment, a, b, width, c); }
  void Disc(Vec2f centre, float radius, Rgba c) { Add(ShapeKind::kDisc, centre, centre, radius, c); }
  void Diamond(Vec2f centre, float radius, Rgba c) {
    Add(ShapeKind::kDiamond, centre, centre, radius, c);
  }
  void Square(Vec2f centre, float half, Rgba c) {
    Rect({centre.x - half, centre.y - half, centre.x + half, centre.y + half}, c);
  }
  void Triangle(Vec2f a, Vec2f b, Vec2f c, Rgba color);
  // One segment per pair of points; a single point is a dot.
  void Polyline(const std::vector<Vec2f>& p, float width, Rgba c);
  // Dashes continue across the polyline's vertices. dash, gap [px].
  void Dashed(const std::vector<Vec2f>& p, float width, Rgba c, float dash, float gap);
  // A 3D scene drawn over the shapes added so far and under those added after it: filled in
  // by the caller (valid until the next Scene3 call).
  Scene3& Scene3D() {
    f_.scenes.emplace_back();
    f_.scenes.back().after_shapes = f_.shapes.size();
    return f_.scenes.back();
  }
  // size is raised to kMinFontSize.
  void Text(std::string text, Vec2f pos, float size, Rgba c, HAlign h = HAlign::kLeft,
            VAlign v = VAlign::kBaseline, bool vertical = false, bool bold = false);

 private:
  void Add(ShapeKind kind, Vec2f a, Vec2f b, float size, Rgba c);
  Frame& f_;
  float k_;
};

// Width of a string in DejaVu Sans [px], estimated at 0.6 em per character (about its average
// advance; bold about 0.65) at the size Painter::Text draws it: frame building has no font, so
// this only spaces legends and decides what fits, always with generous gaps.
float EstimateTextWidth(const std::string& s, float size, bool bold = false);

// printf of one number, e.g. FormatValue("%.2f", 7.2) = "7.20".
std::string FormatValue(const char* fmt, double v);

}  // namespace cablefilm
