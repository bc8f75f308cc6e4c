#pragma once
// The plan and the elevation of lines in space, beside their perspective view: every line now,
// the first's reference and its moving ends' paths projected onto a plane and drawn by the
// cable panel (cable_panel.h), to scale. The plan is seen from above (x across, z down, so that
// it turns as the perspective view does from the +z side); the elevation is the vertical
// plane through the first line's ends, where a line in that plane keeps its true shape, with
// the seabed and the water surface cut along it. The plan shows the current and the waves'
// heading as arrows.
#include <string>

#include "view/colormap.h"
#include "view/frame_layout.h"
#include "view/history.h"
#include "view/legend.h"
#include "view/painter.h"
#include "view/scene_view.h"
#include "view/snapshot.h"
#include "view/space_layout.h"
#include "view/theme.h"
#include "view/world_box.h"

namespace cablefilm {

// The vertical plane through the first line's ends (as its reference has them): distances
// along it from its start, in the horizontal direction of its end (+x when one end is above
// the other).
struct ElevationPlane {
  double x0 = 0, z0 = 0;  // the start [m]
  double ex = 1, ez = 0;  // the horizontal unit vector along it
  double Along(double x, double z) const { return (x - x0) * ex + (z - z0) * ez; }  // [m]
  double heading() const;  // of the direction [deg] from +x towards +z
};
ElevationPlane MakeElevationPlane(const SceneView& scene);

// The box's extent in plan (x, z) and along the plane (distance, y) into the request.
void SetPlaneBoxes(const WorldBox& box, const ElevationPlane& plane, SpaceLayoutRequest* request);

PanelHead PlanHead();
PanelHead ElevationHead(const ElevationPlane& plane);

// Borrowed for one call.
struct PlaneViewsInput {
  const SceneView* scene = nullptr;
  const History* history = nullptr;  // the moving ends' paths
  const Snapshot* now = nullptr;     // the lines, the waves and the current now
  ElevationPlane plane;
  double tension_min = 0, tension_max = 1;  // the colour range [N]
};

// The plan in layout.plan_panel and the elevation in layout.elevation_panel.
void DrawPlaneViews(Painter& p, const FrameLayout& layout, const PlaneViewsInput& in,
                    const Colormap& colormap, const Theme& th);

}  // namespace cablefilm
