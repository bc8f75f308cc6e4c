#pragma once
// The lines' shapes to scale, coloured link by link on the tension colour map: the first line
// now over the ones after it (overlays: thinner, in a dotted rim), the first line's reference
// dashed and its moving ends' paths, markers at the weights (of every line) and at the first
// line's ends by their role (fixed, moving, free), and the seabed when there is one (its line,
// the ground below it shaded, so the part of a line resting on it shows as lying along the
// line). The colour bar is drawn separately (colorbar_panel.h) in the space the layout leaves at
// the panel's right. Lines drawn alike (a system: SceneView::lines_alike) are each drawn as the
// first is, with their marks, references and paths, and named beside their shapes.
#include <string>
#include <vector>

#include "view/colormap.h"
#include "view/end_path.h"
#include "view/frame.h"
#include "view/legend.h"
#include "view/plot_layout.h"
#include "view/scene_view.h"
#include "view/snapshot.h"
#include "view/theme.h"

namespace cablefilm {

// How legends name the ends: "fixed end", ...; a system's line ends are its points ("fixed
// point", "moved point", "free point").
struct EndNames {
  const char* fixed;
  const char* moving;
  const char* free;
};
EndNames EndLabels(const SceneView& scene);
// The marks the legends name: the first line's, or every line's when they are drawn alike.
StationMarks LegendMarks(const SceneView& scene);

// The panel's title and legend: the lines' names when there are several, an entry per kind of
// marker drawn (weights of any line, the first line's ends by role), the end path (named
// `path_label`) and the dashed reference (ReferenceName), the seabed and the water surface when
// the scene's sea has them. `swatch` colours the lines' entries (a mid colour of the map).
// Lines drawn alike are named on the picture, not in the legend; their ends are points.
PanelHead CablePanelHead(const SceneView& scene, const std::string& path_label, Rgba swatch,
                         const Theme& th);

// Borrowed for one call: the pointers are not kept.
struct PanelEdge {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // its ends in a panel's world coordinates [m]
};

struct CablePanelInput {
  PixelRect panel;                  // the whole panel [px]
  PlotMapping world;                // its axes: world [m] -> pixels, equal scale in x and y
  float cable_width = 6;            // the first line's [px]
  float overlay_width = 3.6f;       // the coloured line of each line after the first [px]
  PanelHead head;                   // CablePanelHead(...)
  double tension_min = 0, tension_max = 1;         // the colour range [N]
  const std::vector<LineView>* lines = nullptr;    // required: marks and reference of each line
  const std::vector<LineSnapshot>* now = nullptr;  // required: each line now, in that order
  // Paths of the moving ends (those of the first line are drawn) [m]; null = none.
  const std::vector<EndPath>* end_paths = nullptr;
  const double* seabed_y = nullptr;  // the seabed's elevation [m]; null = no seabed
  // The water surface now (Snapshot::surface_x, surface_y, x increasing): its line within
  // the plot's x range, the water below it (down to the seabed or the box) a faint wash;
  // empty = none.
  const std::vector<double>* surface_x = nullptr;
  const std::vector<double>* surface_y = nullptr;
  // Every line drawn alike (SceneView::lines_alike): each in full, with its marks, reference and
  // paths, and its label beside it in LineColor; false: the lines after the first as overlays.
  bool alike = false;
  const std::vector<PointView>* points = nullptr;  // named by their markers; null = none
  // Outlined through their points (which `points` must be given with); null = none.
  const std::vector<BodyView>* bodies = nullptr;
  // As `bodies`: each body's box edges in the panel's (x, y) [m] (body_fit.h's, projected),
  // drawn instead of its outline; empty for a body without a box; null = none. A body with a
  // box is drawn without `points` too (the elevation).
  const std::vector<std::vector<PanelEdge>>* body_boxes = nullptr;
  // The axes' titles: the plane's (the plan and the elevation of lines in space have others).
  std::string x_label = "x [m]", y_label = "y [m]";
};

void DrawCablePanel(Painter& p, const CablePanelInput& in, const Colormap& colormap,
                    const Theme& th);

// The colour of a moving end's path (and of its legend entry).
Rgba EndPathColor(const Theme& th);

}  // namespace cablefilm
