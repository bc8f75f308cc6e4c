#pragma once
// What the renderer draws, as plain C++ (no GL types): the abstract frame MakeFrame builds
// (frame_builder.h: shapes and text items in pixel coordinates, origin at the top left, y
// down, and 3D scenes in world coordinates, each in a rectangle of the frame), which
// Renderer::Draw rasterises.
#include <cstddef>
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

struct Vec3f {
  float x = 0, y = 0, z = 0;
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

// ---- 3D: world coordinates [m] (x, z horizontal, y up), drawn lit, with a depth buffer --------

// A polyline as a shaded tube of round section, a colour per segment (or one for all).
struct Tube {
  std::vector<Vec3f> points;  // at least 2
  std::vector<Rgba> colors;   // points.size() - 1, or 1 (the whole tube); a < 1: see-through
  float radius = 1;           // [m]
};

enum class SolidKind : std::uint8_t {
  kSphere,      // radius `size` about `centre`
  kBox,         // a cube of half side `size`, axis-aligned, about `centre`
  kOctahedron,  // tips `size` from `centre` along the axes (the 2D diamond's solid)
  kArrow,       // from `centre` (the tail) to centre + axis; shaft radius `size`, a cone head
};

struct Solid {
  SolidKind kind = SolidKind::kSphere;
  Vec3f centre;
  Vec3f axis;       // kArrow only [m]
  float size = 1;   // [m]
  Rgba color;
};

// A grid of nu x nv vertices origin + i du + j dv, each raised along y by height[i + nu j].
struct Sheet {
  Vec3f origin, du, dv;  // [m]
  int nu = 2, nv = 2;
  std::vector<float> height;  // [m], nu * nv; empty: flat
  Rgba color;                 // a < 1: see-through (drawn after the opaque parts)
  float grid = 0;             // lines every `grid` m along x and z drawn on it; 0: none
  float shine = 0.2f;         // strength of the specular highlight, 0..1
};

// A 3D scene in a rectangle of the frame: perspective, lit by a key light, see-through parts
// blended over the opaque ones.
struct Scene3 {
  Vec2f corner0, corner1;      // top left, bottom right of its rectangle [px], whole pixels
  float view_projection[16] = {};  // world [m] to clip space (OpenGL's), column-major
  Vec3f eye;                   // the camera [m]
  Vec3f light{0, 1, 0};        // towards the key light, unit
  Rgba background;
  std::size_t after_shapes = 0;  // drawn after shapes [0, after_shapes), before the others
  std::vector<Sheet> sheets;
  std::vector<Tube> tubes;
  std::vector<Solid> solids;
};

// One frame: drawn in order, shapes first (each 3D scene where it falls among them), then the
// text on top.
struct Frame {
  int width = 0, height = 0;
  Rgba background;
  std::vector<Shape> shapes;
  std::vector<Scene3> scenes;
  std::vector<TextItem> texts;
};

}  // namespace cablefilm
