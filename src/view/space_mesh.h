#pragma once
// The triangles of a frame's 3D scene (frame.h: Scene3), as the renderer uploads them: tubes
// with a ring of kTubeSides vertices at each point (normals smooth around and along, each ring
// in the plane halving the bend, the tube's ends closed), solids from unit shapes, sheets from
// their grids with normals across their heights. Opaque triangles and see-through ones apart,
// the latter in the scene's order (tubes, then sheets: the water last). Plain C++ (no GL); its
// storage is kept from scene to scene, so a steady scene allocates nothing once sized.
#include <cstdint>
#include <vector>

#include "view/frame.h"

namespace cablefilm {

constexpr int kTubeSides = 10;  // around a tube: round enough at a few pixels across

struct LitVertex {
  float pos[3];            // [m]
  float normal[3];         // unit
  std::uint8_t color[4];   // sRGB, straight alpha
  float material[2];       // grid spacing [m] (0: none), specular strength
};

class SpaceMesh {
 public:
  void Build(const Scene3& scene);
  const std::vector<LitVertex>& opaque() const { return opaque_; }
  const std::vector<LitVertex>& see_through() const { return clear_; }

 private:
  void AddTube(const Tube& tube);
  void AddSolid(const Solid& solid);
  void AddSheet(const Sheet& sheet);

  std::vector<LitVertex> opaque_, clear_;
  std::vector<Vec3f> tangents_, ring_;  // scratch: a tube's tangents, its rings' unit normals
  std::vector<float> ring_scale_;       // scratch: each ring's radius over the tube's
  std::vector<Vec3f> grid_;             // scratch: a sheet's vertices
};

}  // namespace cablefilm
