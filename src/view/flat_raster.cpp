#include "view/flat_raster.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.h"

namespace cablefilm {
namespace {

// A colour as the renderer hands it to GL: 8 bits a channel (renderer.cpp's PackColor).
struct Color8 {
  float r, g, b, a;  // q / 255
};

float Quantise(float v) { return std::lround(std::fmin(1.0f, std::fmax(0.0f, v)) * 255) / 255.0f; }
Color8 Pack(const Rgba& c) { return {Quantise(c.r), Quantise(c.g), Quantise(c.b), Quantise(c.a)}; }

// Comparisons, not fmin/fmax: those are calls into libm here, in the innermost loop.
inline float Clamp01(float v) { return v > 0 ? (v < 1 ? v : 1.0f) : 0.0f; }

inline std::uint8_t ToByte(float v) { return static_cast<std::uint8_t>(Clamp01(v) * 255 + 0.5f); }

// GL's blend (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) into an 8-bit target; alpha stays opaque. An
// opaque fragment is the colour itself (most pixels of a flat figure: a fast path).
inline void Blend(std::uint8_t* px, const Color8& c, float alpha) {
  if (!(alpha > 0)) return;  // the shaders discard
  if (alpha >= 1) {
    px[0] = ToByte(c.r), px[1] = ToByte(c.g), px[2] = ToByte(c.b);
    return;
  }
  const float keep = (1 - alpha) / 255.0f;
  px[0] = ToByte(c.r * alpha + px[0] * keep);
  px[1] = ToByte(c.g * alpha + px[1] * keep);
  px[2] = ToByte(c.b * alpha + px[2] * keep);
}

// The rows of the frame being drawn: band->height of them from frame row y0 (the whole
// frame: y0 0 and a band of its height).
struct Rows {
  Image* band;
  int y0;
  int frame_height;
  std::uint8_t* row(int y) const { return band->row(y - y0); }
};

// The pixels whose centres fall in [x0, x1] x [y0, y1] [px], clipped to the frame's rows
// being drawn.
struct PixelSpan {
  int ix0, ix1, iy0, iy1;  // inclusive
};
// Clamped to the frame before any conversion, so that a huge or non-finite coordinate
// (a blown-up value drawn) gives an empty or clipped span, never an out-of-range cast.
PixelSpan Span(float x0, float x1, float y0, float y1, const Rows& im) {
  if (!(x0 <= x1) || !(y0 <= y1)) return {0, -1, 0, -1};
  auto lo = [](float v, int n) { return static_cast<int>(std::ceil(std::fmax(-1.0f, std::fmin(v - 0.5f, n + 1.0f)))); };
  auto hi = [](float v, int n) { return static_cast<int>(std::floor(std::fmax(-1.0f, std::fmin(v - 0.5f, n + 1.0f)))); };
  const int w = im.band->width, h = im.frame_height;
  return {std::max(0, lo(x0, w)), std::min(w - 1, hi(x1, w)),
          std::max({0, lo(y0, h), im.y0}),
          std::min({h - 1, hi(y1, h), im.y0 + im.band->height - 1})};
}

float SegmentDistance(float px, float py, Vec2f a, Vec2f b) {
  const float abx = b.x - a.x, aby = b.y - a.y;
  const float len2 = abx * abx + aby * aby;
  const float h = len2 > 0 ? Clamp01(((px - a.x) * abx + (py - a.y) * aby) / len2) : 0;
  const float dx = px - a.x - h * abx, dy = py - a.y - h * aby;
  return std::sqrt(dx * dx + dy * dy);
}

// shape.frag's coverage of the pixel centred at (px, py).
float Coverage(const Shape& s, float px, float py) {
  switch (s.kind) {
    case ShapeKind::kSegment:
      return Clamp01((s.size > 1 ? s.size : 1.0f) * 0.5f + 0.5f - SegmentDistance(px, py, s.a, s.b));
    case ShapeKind::kDisc:
      return Clamp01(s.size + 0.5f - std::sqrt((px - s.a.x) * (px - s.a.x) + (py - s.a.y) * (py - s.a.y)));
    case ShapeKind::kRect: {
      const float dx = std::fabs(px - 0.5f * (s.a.x + s.b.x)) - 0.5f * std::fabs(s.b.x - s.a.x);
      const float dy = std::fabs(py - 0.5f * (s.a.y + s.b.y)) - 0.5f * std::fabs(s.b.y - s.a.y);
      return Clamp01(0.5f - (dx > dy ? dx : dy));
    }
    case ShapeKind::kDiamond:
      return Clamp01(0.5f - (std::fabs(px - s.a.x) + std::fabs(py - s.a.y) - s.size) * 0.70710678f);
    case ShapeKind::kTriangle:
      return 1;
  }
  return 0;
}

float Edge(Vec2f a, Vec2f b, float px, float py) {
  return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

void DrawTriangle(const Shape& s, const Rows& im) {
  const Color8 c = Pack(s.color);
  const float area = Edge(s.a, s.b, s.c.x, s.c.y);
  if (area == 0) return;
  const float sign = area > 0 ? 1.0f : -1.0f;
  const PixelSpan p = Span(std::fmin(s.a.x, std::fmin(s.b.x, s.c.x)), std::fmax(s.a.x, std::fmax(s.b.x, s.c.x)),
                           std::fmin(s.a.y, std::fmin(s.b.y, s.c.y)), std::fmax(s.a.y, std::fmax(s.b.y, s.c.y)), im);
  for (int y = p.iy0; y <= p.iy1; ++y)
    for (int x = p.ix0; x <= p.ix1; ++x) {
      const float px = x + 0.5f, py = y + 0.5f;
      if (sign * Edge(s.a, s.b, px, py) >= 0 && sign * Edge(s.b, s.c, px, py) >= 0 &&
          sign * Edge(s.c, s.a, px, py) >= 0)
        Blend(im.row(y) + 4 * x, c, c.a);
    }
}

// shape.frag's rectangle, 0.5 - max(dx, dy) with dx of the column alone and dy of the row
// alone: dx hoisted out of the rows, the same float operations as Coverage at every pixel, and
// an opaque pixel written as the colour's bytes. The figures' panels are most of their pixels
// (max_tension.png: 9 in 10), which Coverage's switch made the rasteriser's largest cost. In a
// row within the rectangle (dy <= -0.5, where 0.5 - dy >= 1) the clamp takes max(dx, dy) to
// the column's max(dx, -0.5) alone: those alphas are computed once.
void DrawRect(const Shape& s, const Rows& im) {
  const Color8 c = Pack(s.color);
  const PixelSpan p = Span(std::fmin(s.a.x, s.b.x) - 1, std::fmax(s.a.x, s.b.x) + 1,
                           std::fmin(s.a.y, s.b.y) - 1, std::fmax(s.a.y, s.b.y) + 1, im);
  if (p.ix0 > p.ix1 || p.iy0 > p.iy1) return;
  std::vector<float> dx(static_cast<std::size_t>(p.ix1 - p.ix0 + 1));
  for (int x = p.ix0; x <= p.ix1; ++x)
    dx[static_cast<std::size_t>(x - p.ix0)] =
        std::fabs(x + 0.5f - 0.5f * (s.a.x + s.b.x)) - 0.5f * std::fabs(s.b.x - s.a.x);
  std::vector<float> inside(dx.size());  // a column's alpha in the rows within
  for (std::size_t i = 0; i < dx.size(); ++i)
    inside[i] = c.a * Clamp01(0.5f - (dx[i] > -0.5f ? dx[i] : -0.5f));
  const std::uint8_t solid[3] = {ToByte(c.r), ToByte(c.g), ToByte(c.b)};
  for (int y = p.iy0; y <= p.iy1; ++y) {
    const float dy = std::fabs(y + 0.5f - 0.5f * (s.a.y + s.b.y)) - 0.5f * std::fabs(s.b.y - s.a.y);
    const bool within = dy <= -0.5f;
    std::uint8_t* px = im.row(y) + 4 * p.ix0;
    for (std::size_t i = 0; i < dx.size(); ++i, px += 4) {
      const float alpha = within ? inside[i] : c.a * Clamp01(0.5f - (dx[i] > dy ? dx[i] : dy));
      if (alpha >= 1)
        px[0] = solid[0], px[1] = solid[1], px[2] = solid[2];
      else
        Blend(px, c, alpha);
    }
  }
}

void DrawShape(const Shape& s, const Rows& im) {
  if (s.kind == ShapeKind::kTriangle) return DrawTriangle(s, im);
  if (s.kind == ShapeKind::kRect) return DrawRect(s, im);
  const Color8 c = Pack(s.color);
  float alpha = c.a;
  float margin;  // how far the shape's coverage reaches beyond a and b [px]
  switch (s.kind) {
    case ShapeKind::kSegment:
      alpha *= std::fmin(s.size, 1.0f);  // thinner than a pixel: drawn one wide, faint
      margin = std::fmax(s.size, 1.0f) * 0.5f + 1;
      break;
    default:
      margin = s.size + 1;
      break;
  }
  const PixelSpan p = Span(std::fmin(s.a.x, s.b.x) - margin, std::fmax(s.a.x, s.b.x) + margin,
                           std::fmin(s.a.y, s.b.y) - margin, std::fmax(s.a.y, s.b.y) + margin, im);
  for (int y = p.iy0; y <= p.iy1; ++y)
    for (int x = p.ix0; x <= p.ix1; ++x)
      Blend(im.row(y) + 4 * x, c, alpha * Coverage(s, x + 0.5f, y + 0.5f));
}

// text.frag over one glyph quad: the atlas sampled nearest at each pixel centre.
// `lift` holds text.frag's pow(coverage / 255, gamma) for each of the atlas's 256 values.
void DrawGlyph(const GlyphQuad& q, const FontAtlas& font, const Color8& c, const float* lift,
               const Rows& im) {
  const Vec2f o = q.corner[0];
  const Vec2f du{q.corner[1].x - o.x, q.corner[1].y - o.y};  // along the bitmap's rows
  const Vec2f dv{q.corner[3].x - o.x, q.corner[3].y - o.y};  // down its columns
  const float det = du.x * dv.y - du.y * dv.x;
  if (det == 0) return;
  const int n = font.atlas_size();
  const std::uint8_t* atlas = font.pixels();
  float x0 = o.x, x1 = o.x, y0 = o.y, y1 = o.y;
  for (const Vec2f& k : q.corner) {
    x0 = std::fmin(x0, k.x), x1 = std::fmax(x1, k.x);
    y0 = std::fmin(y0, k.y), y1 = std::fmax(y1, k.y);
  }
  const PixelSpan p = Span(x0, x1, y0, y1, im);
  for (int y = p.iy0; y <= p.iy1; ++y)
    for (int x = p.ix0; x <= p.ix1; ++x) {
      const float rx = x + 0.5f - o.x, ry = y + 0.5f - o.y;
      const float s = (rx * dv.y - ry * dv.x) / det, t = (du.x * ry - du.y * rx) / det;
      if (s < 0 || s > 1 || t < 0 || t > 1) continue;
      const float u = q.uv0.x + s * (q.uv1.x - q.uv0.x), v = q.uv0.y + t * (q.uv1.y - q.uv0.y);
      const int tx = std::min(n - 1, std::max(0, static_cast<int>(std::floor(u * n))));
      const int ty = std::min(n - 1, std::max(0, static_cast<int>(std::floor(v * n))));
      const std::uint8_t cov = atlas[static_cast<std::size_t>(ty) * n + tx];
      if (cov == 0) continue;
      Blend(im.row(y) + 4 * x, c, c.a * lift[cov]);
    }
}

}  // namespace

FlatFrameRaster::FlatFrameRaster(const Frame& frame, FontAtlas* font)
    : frame_(frame), font_(*font) {
  if (!frame.scenes.empty())
    throw Error("DrawFlatFrame: the frame has " + std::to_string(frame.scenes.size()) +
                " 3D scenes; only the GL renderer draws them");
  const int w = frame.width, h = frame.height;
  if (w <= 0 || h <= 0)
    throw Error("DrawFlatFrame: frame is " + std::to_string(w) + "x" + std::to_string(h));
  // Light text on a dark ground needs its coverage lifted (text.frag).
  const Rgba& b = frame.background;
  const float luma = 0.2126f * b.r + 0.7152f * b.g + 0.0722f * b.b;
  const float gamma = luma < 0.5f ? 0.8f : 1.0f;
  for (int v = 0; v < 256; ++v) lift_[v] = std::pow(v / 255.0f, gamma);  // not a pow() a pixel
  // Laid out once, for every band.
  for (const TextItem& t : frame.texts) {
    quads_.emplace_back();
    font->Layout(t, &quads_.back(), static_cast<float>(w), static_cast<float>(h));
  }
}

void FlatFrameRaster::DrawRows(int y0, Image* band) const {
  if (band->width != frame_.width || y0 < 0 || y0 + band->height > frame_.height)
    throw Error("DrawFlatFrame: rows " + std::to_string(y0) + " to " +
                std::to_string(y0 + band->height) + " of " + std::to_string(band->width) +
                " pixels are not within the frame");
  const Rows rows{band, y0, frame_.height};
  const std::uint8_t bg[4] = {ToByte(frame_.background.r), ToByte(frame_.background.g),
                              ToByte(frame_.background.b), 255};
  // The ground: the first row pixel by pixel, the others copies of it.
  for (int x = 0; x < band->width; ++x) std::copy(bg, bg + 4, band->row(0) + 4 * x);
  for (int y = 1; y < band->height; ++y)
    std::copy(band->row(0), band->row(0) + band->stride(), band->row(y));
  for (const Shape& s : frame_.shapes) DrawShape(s, rows);
  for (std::size_t i = 0; i < frame_.texts.size(); ++i) {
    const Color8 c = Pack(frame_.texts[i].color);
    for (const GlyphQuad& q : quads_[i]) DrawGlyph(q, font_, c, lift_, rows);
  }
}

void DrawFlatFrame(const Frame& frame, FontAtlas* font, Image* out) {
  const FlatFrameRaster raster(frame, font);
  if (out->width != frame.width || out->height != frame.height)
    *out = Image(frame.width, frame.height);
  raster.DrawRows(0, out);
}

}  // namespace cablefilm
