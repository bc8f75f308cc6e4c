#pragma once
// An 8-bit RGBA image in memory, rows from the top, no padding between rows. Plain data shared
// by the renderer (which fills it) and the encoders (which write it out).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace cablefilm {

// A rectangle of an image's pixels: [x0, x1) x [y0, y1), rows from the top.
struct ImageRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes, row 0 = top row

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0) {}

  std::size_t stride() const { return static_cast<std::size_t>(width) * 4; }
  std::uint8_t* row(int y) { return rgba.data() + stride() * y; }
  const std::uint8_t* row(int y) const { return rgba.data() + stride() * y; }
  // Pointer to the 4 bytes (r, g, b, a) of pixel (x, y); no bounds check.
  const std::uint8_t* at(int x, int y) const { return row(y) + 4 * x; }
};

}  // namespace cablefilm
