#pragma once
// The maximum tension along the cable against time (the paper's Figure 1, growing): the trace
// thinned to pixel columns with a dot at its newest point, the companion's trace, the largest
// equilibrium tension as a dashed reference, a readout (the note), and vertical markers at
// given times with short labels (the live view's control changes).
#include <limits>
#include <string>
#include <vector>

#include "view/legend.h"
#include "view/plot_layout.h"
#include "view/theme.h"

namespace cablefilm {

struct TimeMarker {
  double t = 0;       // [s]
  std::string label;  // short; longer labels are cut to kMaxMarkerLabel characters
};
constexpr std::size_t kMaxMarkerLabel = 28;

// Title and legend: the two traces' names when there is a companion. `note_row`: the note
// gets a row of its own under that legend (without a companion it sits beside the title).
PanelHead TimePanelHead(bool companion, bool note_row, const std::string& main_label,
                        const std::string& companion_label, const Theme& th);

// Borrowed for one call.
struct TimePanelInput {
  PixelRect panel;   // the whole panel [px]
  PlotMapping plot;  // time [s], tension [kN] -> pixels
  PanelHead head;    // TimePanelHead(...)
  std::string note;  // readout at the head's right, e.g. "now 7.21 kN    peak 7.73 kN"
  const std::vector<double>* times = nullptr;          // [s]; required
  const std::vector<double>* max_tension = nullptr;    // [N], one per time; required
  const std::vector<double>* companion_max = nullptr;  // [N], one per time (NaN = gap); null = none
  // The largest tension of the initial state [N]: a dashed line labelled `equilibrium_label`
  // at the plot's right end (or left: the live view's newest data are at the right); NaN = none.
  double equilibrium_max = std::numeric_limits<double>::quiet_NaN();
  std::string equilibrium_label = "equilibrium";  // or: initial state (straight)
  bool equilibrium_label_left = false;
  const std::vector<TimeMarker>* markers = nullptr;  // those inside the time axis are drawn
};

void DrawTimePanel(Painter& p, const TimePanelInput& in, const Theme& th);

}  // namespace cablefilm
