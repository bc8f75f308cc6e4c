#pragma once
// The tension along each line against unstretched arc length: now, the reference (dashed), the
// first line's min-max envelope of each link so far (a band), the curves of the lines after the
// first (overlays: thinner, on top), and the first line's sections: a dashed line at each
// boundary and each section's name in its span. Lines drawn alike (a system) are each a curve of
// its own colour (LineColor), each thinner than the one before (NestedWidth), with its
// reference dashed in a paler shade, and no band.
#include <string>
#include <vector>

#include "view/legend.h"
#include "view/plot_layout.h"
#include "view/scene_view.h"
#include "view/snapshot.h"
#include "view/theme.h"

namespace cablefilm {

// Title and legend. With several lines, `named` (OverlaysNamed) names the curves "<line> now"
// and the references "<line> <reference>" etc. (room for a second legend row); otherwise the
// short names. `envelope_label` names the band ("" = no band); the dashed reference is named
// ReferenceName(scene). Lines drawn alike: each line's name in its colour.
PanelHead TensionPanelHead(const SceneView& scene, bool named, const std::string& envelope_label,
                           const Theme& th);

// Borrowed for one call. A series of the wrong size (not one value per link) is not drawn.
struct TensionPanelInput {
  PixelRect panel;      // the whole panel [px]
  PlotMapping plot;     // unstretched arc length [m], tension [kN] -> pixels
  PanelHead head;       // TensionPanelHead(...)
  // Required: each line's arc lengths [m] and reference tensions [N] (the first's dashed), the
  // first line's sections (a name per section, drawn centred in its span near the plot's top
  // where it fits, or none).
  const std::vector<LineView>* lines = nullptr;
  const std::vector<LineSnapshot>* now = nullptr;  // required: each line's tensions now [N]
  bool overlay_references = false;  // the references of the lines after the first, dotted
  const std::vector<double>* envelope_min = nullptr;  // the first line's [N], s; null = no band
  const std::vector<double>* envelope_max = nullptr;  // [N], s
  bool alike = false;  // every line drawn alike (SceneView::lines_alike)
};

void DrawTensionPanel(Painter& p, const TensionPanelInput& in, const Theme& th);

}  // namespace cablefilm
