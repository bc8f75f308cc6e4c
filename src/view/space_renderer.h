#pragma once
// Draws the 3D scenes of a frame (frame.h: Scene3) for the Renderer, in its context: the
// scene's triangles (space_mesh.h) with the lit shaders (shaders/lit.*) into an off-screen
// framebuffer of the scene's rectangle with a depth buffer and 4x multisampling (as many
// samples as the context allows), opaque parts first, the see-through ones blended over them
// without writing depth; then resolved and copied into the frame's framebuffer at the
// rectangle. Buffers are sized once and reused while the rectangle keeps its size.
#include <memory>
#include <string>

#include "view/frame.h"

namespace cablefilm {

class SpaceRenderer {
 public:
  // Needs the renderer's context current. Throws Error (shaders, framebuffer).
  explicit SpaceRenderer(const std::string& shader_dir);
  ~SpaceRenderer();
  SpaceRenderer(const SpaceRenderer&) = delete;
  SpaceRenderer& operator=(const SpaceRenderer&) = delete;

  // Draws `scene` into the bound default framebuffer, `frame_height` rows tall, whose GL row 0
  // is the frame's top row (see shape.vert); leaves blending on and depth testing off, as the
  // 2D drawing has them, and the framebuffer bound again.
  void Draw(const Scene3& scene, int frame_width, int frame_height);

  int samples() const;  // per pixel of the off-screen framebuffer (0: none)

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cablefilm
