#pragma once
// The tension along the cable against unstretched arc length: now, the equilibrium (dashed),
// the min-max envelope of each link so far (a band), the companion's curves when there is
// one, and the sections: a dashed line at each boundary and each section's name in its span.
#include <string>
#include <vector>

#include "view/legend.h"
#include "view/plot_layout.h"
#include "view/theme.h"

namespace cablefilm {

// Title and legend. With a companion, `two_rows` names the curves "<label> now" and the
// references "<label> equilibrium" etc. (room for a second legend row); without, the short
// names. `envelope_label` names the band ("" = no band); `reference_label` the dashed initial
// state ("equilibrium", or "initial state (straight)" for a straight start).
PanelHead TensionPanelHead(bool companion, bool two_rows, bool companion_equilibrium,
                           const std::string& main_label, const std::string& companion_label,
                           const std::string& envelope_label, const Theme& th,
                           const std::string& reference_label = "equilibrium");

// Borrowed for one call. A series of the wrong size (not one value per link) is not drawn.
struct TensionPanelInput {
  PixelRect panel;      // the whole panel [px]
  PlotMapping plot;     // unstretched arc length [m], tension [kN] -> pixels
  PanelHead head;       // TensionPanelHead(...)
  const std::vector<double>* arc_length = nullptr;  // of each station [m], s+1; required
  const std::vector<double>* tension = nullptr;     // of each link now [N], s; required
  const std::vector<double>* companion_tension = nullptr;      // [N], s; null = none
  const std::vector<double>* equilibrium = nullptr;            // [N], s; null = none
  const std::vector<double>* companion_equilibrium = nullptr;  // [N], s; null = none
  const std::vector<double>* envelope_min = nullptr;           // [N], s; null = no band
  const std::vector<double>* envelope_max = nullptr;           // [N], s
  const std::vector<double>* section_boundaries = nullptr;     // interior section ends [m]
  // One name per section (boundaries + 1), drawn centred in its span near the plot's top
  // where it fits; null or empty = unnamed.
  const std::vector<std::string>* section_names = nullptr;
};

void DrawTensionPanel(Painter& p, const TensionPanelInput& in, const Theme& th);

}  // namespace cablefilm
