#pragma once
// Draws a Frame into an Image with OpenGL 3.3 core in its own off-screen context: the shapes
// from one buffer (anti-aliased in the fragment shader, no MSAA) in runs around the frame's 3D
// scenes (space_renderer.h: lit, depth-tested, multisampled), then all glyphs in one draw call
// (an atlas texture), then one glReadPixels; or, with redraw_changes, only the rectangles
// where the frame differs from the last (and with DrawOnto only they are read back). Use a
// Renderer on the thread that created it.
#include <memory>
#include <string>
#include <vector>

#include "encode/image.h"
#include "view/frame.h"

namespace cablefilm {

struct RenderOptions {
  int width = 1920, height = 1080;
  std::string shader_dir;  // empty: ResolveShaderDir("") ($CABLEFILM_SHADERS, else compiled in)
  std::string font_path;   // empty: DejaVu Sans through fontconfig
  // Redraw only where this frame differs from the last (damage.h): the same pixels, less
  // work when little changes (the live view). Off: every frame drawn whole.
  bool redraw_changes = false;
};

class Renderer {
 public:
  explicit Renderer(const RenderOptions& options);  // throws Error (context, shaders, font)
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Draws `frame` (its size must be the renderer's) into `out` (resized as needed).
  void Draw(const Frame& frame, Image* out);
  // The same into `picture`, which holds the last frame this renderer drew (by Draw or
  // DrawOnto, unchanged since): only what was drawn again is read back into it, not the whole
  // frame (8 MB at 1080p). Any other picture must go through Draw.
  void DrawOnto(const Frame& frame, Image* picture);
  Image Draw(const Frame& frame);

  // The share of the frame's pixels the last Draw drew again: 1 for a whole frame, 0 when
  // nothing had changed (redraw_changes).
  double redrawn() const;
  // Where the last Draw drew again when it drew less than the whole frame (redrawn() < 1):
  // elsewhere the picture is the one before.
  const std::vector<ImageRect>& redrawn_rects() const;

  int width() const;
  int height() const;
  std::string Describe() const;  // GL version and renderer

 private:
  void Render(const Frame& frame);  // into the framebuffer only
  void ReadBack(Image* out, bool changes_only);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cablefilm
