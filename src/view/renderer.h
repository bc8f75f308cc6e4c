#pragma once
// Draws a Frame into an Image with OpenGL 3.3 core in its own off-screen context: the shapes
// from one buffer (anti-aliased in the fragment shader, no MSAA) in runs around the frame's 3D
// scenes (space_renderer.h: lit, depth-tested, multisampled), then all glyphs in one draw call
// (an atlas texture), then one glReadPixels. Use a Renderer on the thread that created it.
#include <memory>
#include <string>

#include "encode/image.h"
#include "view/frame.h"

namespace cablefilm {

struct RenderOptions {
  int width = 1920, height = 1080;
  std::string shader_dir;  // empty: ResolveShaderDir("") ($CABLEFILM_SHADERS, else compiled in)
  std::string font_path;   // empty: DejaVu Sans through fontconfig
};

class Renderer {
 public:
  explicit Renderer(const RenderOptions& options);  // throws Error (context, shaders, font)
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Draws `frame` (its size must be the renderer's) into `out` (resized as needed).
  void Draw(const Frame& frame, Image* out);
  Image Draw(const Frame& frame);

  int width() const;
  int height() const;
  std::string Describe() const;  // GL version and renderer

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cablefilm
