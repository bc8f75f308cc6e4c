#pragma once
// What the renderer draws, as plain C++ (no GL types): the abstract frame MakeFrame builds
// (frame_builder.h: shapes and text items in pixel coordinates, origin at the top left, y
// down), which Renderer::Draw rasterises.
#include <cstdint>
#include <string>
#include <vector>

namespace cablefilm {

// Colours are sRGB, 0..1, with straight (not premultiplied) alpha.
struct Rgba {
  float r = 0, g = 0, b = 0, a = 1;
};

struct Vec2f {
  float x = 0, y = 0;
};

enum class ShapeKind : std::uint8_t {
  kSegment,   // a line from a to b, `size` wide, round caps, anti-aliased edges
  kDisc,      // a filled circle of centre a, radius `size`
  kRect,      // a filled axis-aligned rectangle with corners a and b (a = top left)
  kDiamond,   // a filled square turned 45 degrees, centre a, `size` from centre to tip
  kTriangle,  // a filled triangle a, b, c (no edge anti-aliasing: for area fills)
};

struct Shape {
  ShapeKind kind = ShapeKind::kSegment;
  Vec2f a, b, c;
  float size = 1;  // line width, or radius [px]
  Rgba color;
};

enum class HAlign : std::uint8_t { kLeft, kCenter, kRight };
enum class VAlign : std::uint8_t { kTop, kMiddle, kBaseline, kBottom };

struct TextItem {
  std::string text;  // UTF-8
  Vec2f pos;         // anchor point [px]
  float size = 14;   // nominal font size [px] (em height)
  Rgba color;
  HAlign halign = HAlign::kLeft;
  VAlign valign = VAlign::kBaseline;
  bool vertical = false;  // rotated 90 degrees counter-clockwise (reads bottom to top)
  bool bold = false;
};

// One frame: drawn in order, shapes first, then the text on top.
struct Frame {
  int width = 0, height = 0;
  Rgba background;
  std::vector<Shape> shapes;
  std::vector<TextItem> texts;
};

}  // namespace cablefilm
