#pragma once
// The maximum tension along each line against time (the paper's Figure 1, growing): each
// line's trace thinned to pixel columns with a dot at its newest point (the lines after the
// first thinner, on top), the first line's largest reference tension as a dashed reference, a
// readout (the note), and vertical markers at given times with short labels (the live view's
// control changes). Lines drawn alike (a system) are each a trace of its own colour
// (LineColor), each thinner than the one before (NestedWidth).
#include <limits>
#include <string>
#include <vector>

#include "view/legend.h"
#include "view/plot_layout.h"
#include "view/scene_view.h"
#include "view/theme.h"

namespace cablefilm {

struct TimeMarker {
  double t = 0;       // [s]
  std::string label;  // short; longer labels are cut to kMaxMarkerLabel characters
};
constexpr std::size_t kMaxMarkerLabel = 28;

// Title and legend: the lines' names when there are several. `note_row`: the note then gets a
// row of its own under that legend (with one line it sits beside the title).
PanelHead TimePanelHead(const SceneView& scene, bool note_row, const Theme& th);

// Borrowed for one call.
struct TimePanelInput {
  PixelRect panel;   // the whole panel [px]
  PlotMapping plot;  // time [s], tension [kN] -> pixels
  PanelHead head;    // TimePanelHead(...)
  std::string note;  // readout at the head's right, e.g. "now 7.21 kN    peak 7.73 kN"
  const std::vector<double>* times = nullptr;  // [s]; required
  // Required: per line (at least one), the largest tension [N] at each time (NaN = a gap); a
  // line's series of another size is not drawn (the first's is an error).
  const std::vector<std::vector<double>>* max_tension = nullptr;
  // The largest tension of the initial state [N]: a dashed line labelled `equilibrium_label`
  // at the plot's right end (or left: the live view's newest data are at the right); NaN = none.
  double equilibrium_max = std::numeric_limits<double>::quiet_NaN();
  std::string equilibrium_label = "equilibrium";  // or: initial state (straight)
  bool equilibrium_label_left = false;
  const std::vector<TimeMarker>* markers = nullptr;  // those inside the time axis are drawn
  bool alike = false;  // every line drawn alike (SceneView::lines_alike)
  // A minimum breaking load [N] within the tension axis: a dashed line labelled
  // `breaking_load_label` (NaN = none; one off the axis is the caller's note).
  double breaking_load = std::numeric_limits<double>::quiet_NaN();
  std::string breaking_load_label;
};

void DrawTimePanel(Painter& p, const TimePanelInput& in, const Theme& th);

}  // namespace cablefilm
