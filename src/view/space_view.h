#pragma once
// The perspective view of lines in space, the main panel of the 3D layout: each line now as a
// tube lit by a key light and coloured link by link on the tension colour map (the lines after
// the first thinner), the first line's reference as a faint ghost, its moving ends' paths,
// markers at its ends and at the weights, the seabed as a plane with a grid and the lines'
// shadows on it, the water surface now as a see-through sheet, the current as an arrow with
// its speed, and a triad of the axes. Widths and markers are set in pixels at the distance of
// the middle of the box, so the picture reads the same at any size; nearer parts look larger.
// Lines drawn alike (a system) are each drawn as the first, with their ghosts, paths and ends,
// and named beside their tubes; the points by their markers.
#include <string>
#include <vector>

#include "view/camera.h"
#include "view/colormap.h"
#include "view/end_path.h"
#include "view/legend.h"
#include "view/painter.h"
#include "view/scene_view.h"
#include "view/snapshot.h"
#include "view/theme.h"
#include "view/world_box.h"

namespace cablefilm {

// The panel's title and legend (an entry per kind of thing drawn), as CablePanelHead's.
PanelHead SpaceViewHead(const SceneView& scene, const std::string& path_label, Rgba swatch,
                        const Theme& th);

// Borrowed for one call.
struct SpaceViewInput {
  PixelRect panel;      // the whole panel [px]
  PixelRect view;       // the 3D scene's rectangle [px], whole pixels
  PanelHead head;       // SpaceViewHead(...)
  OrbitCamera camera;
  WorldBox box;         // kept in view at zoom 1; the seabed and the water span it, and more [m]
  float cable_width = 6, overlay_width = 3.6f;  // the lines' widths in the plane views [px]
  double tension_min = 0, tension_max = 1;      // the colour range [N]
  const SceneView* scene = nullptr;             // required
  const Snapshot* now = nullptr;                // required: the lines, waves and current now
  const std::vector<EndPath>* end_paths = nullptr;  // null: none
};

// Draws the panel; returns the projection the scene is drawn with.
ViewProjection DrawSpaceView(Painter& p, const SpaceViewInput& in, const Colormap& colormap,
                             const Theme& th);

}  // namespace cablefilm
