#pragma once
// Draws a flat Frame (shapes and text, no 3D scene) into an Image on the CPU, pixel for pixel
// as Renderer::Draw does on the GPU: the same coverage formulas as shaders/shape.frag and
// text.frag at each pixel centre, blended in 8 bits in the same order. For the pictures a run
// writes (max_tension.png), so that writing them needs no GL context: no OSMesa to load, no
// shader to compile.
#include "encode/image.h"
#include "view/frame.h"
#include "view/text.h"

namespace cablefilm {

// `out` is resized to the frame. Throws Error if the frame has a 3D scene.
void DrawFlatFrame(const Frame& frame, FontAtlas* font, Image* out);

}  // namespace cablefilm
