#pragma once
// Draws a flat Frame (shapes and text, no 3D scene) into an Image on the CPU, pixel for pixel
// as Renderer::Draw does on the GPU: the same coverage formulas as shaders/shape.frag and
// text.frag at each pixel centre, blended in 8 bits in the same order. For the pictures a run
// writes (max_tension.png), so that writing them needs no GL context: no OSMesa to load, no
// shader to compile.
#include <vector>

#include "encode/image.h"
#include "view/frame.h"
#include "view/text.h"

namespace cablefilm {

// `out` is resized to the frame. Throws Error if the frame has a 3D scene.
void DrawFlatFrame(const Frame& frame, FontAtlas* font, Image* out);

// The same a band of rows at a time, pixel for pixel: a picture drawn and written in bands
// (max_tension.png) never holds all its pixels (1600x900: 5.8 MB, 1400 pages faulted in).
// Keeps references to the frame and the font.
class FlatFrameRaster {
 public:
  FlatFrameRaster(const Frame& frame, FontAtlas* font);  // throws Error as DrawFlatFrame
  // Frame rows y0 .. y0 + band->height - 1 into `band`, as wide as the frame. Throws Error.
  void DrawRows(int y0, Image* band) const;

 private:
  const Frame& frame_;
  const FontAtlas& font_;
  std::vector<std::vector<GlyphQuad>> quads_;  // of each text item
  float lift_[256];  // text.frag's pow(coverage / 255, gamma) of each atlas value
};

}  // namespace cablefilm
