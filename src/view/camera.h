#pragma once
// The 3D view's camera: it orbits the box it shows and looks at its middle (as the view sees
// it), from a distance at which the box just fits its viewport (zoom 1) or closer; and the projection of
// the world [m] to the viewport's pixels, the same for the labels the frame builder places and
// the scene the renderer draws.
#include <Eigen/Core>

#include "core/vec.h"
#include "view/frame.h"
#include "view/plot_layout.h"
#include "view/scene_view.h"
#include "view/world_box.h"

namespace cablefilm {

struct OrbitCamera {
  double azimuth = 90;    // [deg]: where the eye is seen from the target, from +x towards +z
  double elevation = 20;  // [deg] above the horizontal
  double zoom = 1;        // 1: the box fits the view; 2: twice as close
};
constexpr double kMinZoom = 0.2, kMaxZoom = 20;  // [1]
constexpr double kMaxElevation = 89;             // [deg] either way: never straight down

// Azimuth into (-180, 180], elevation and zoom into their ranges; non-finite values become the
// default's.
OrbitCamera ClampCamera(const OrbitCamera& camera);

// The first line's reference seen a little from above and three-quarters on: its start to the
// left of its end, turned towards its end, so that the line runs into the picture.
OrbitCamera DefaultCamera(const SceneView& scene);

struct ViewProjection {
  Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();  // world [m] to clip space
  Vec eye = Vec::Zero(), target = Vec::Zero();  // [m]
  Vec right = Vec::UnitX(), up = Vec::UnitY();  // the view's axes in the world
  double pixels_per_metre = 1;  // at the target's distance [px/m]
  PixelRect viewport;           // frame pixels, y down

  // The pixel of a world point [m] (frame pixels, y down); false when it is not in front of the
  // eye.
  bool ToPixel(const Vec& p, Vec2f* pixel) const;
  // The matrix, the eye and the rectangle into a frame's 3D scene.
  void Fill(Scene3* scene) const;
};

// The camera's view of `fit` (the box kept in view at zoom 1) in `viewport`, with a vertical
// field of view of fov_y degrees; near and far planes hold `extent` (what is drawn).
ViewProjection MakeViewProjection(const OrbitCamera& camera, const WorldBox& fit,
                                  const WorldBox& extent, const PixelRect& viewport,
                                  double fov_y = 30);

}  // namespace cablefilm
