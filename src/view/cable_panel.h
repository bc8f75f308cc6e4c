#pragma once
// The cable's shape to scale, coloured link by link on the tension colour map: the cable now
// (over its companion, when the snapshot has one), the equilibrium shape dashed, the paths of
// the moving ends, markers at the weights and at the ends by their role (fixed, moving,
// free), and the seabed when there is one (its line, the ground below it shaded, so the part of
// the line resting on it shows as lying along the line). The colour bar is drawn
// separately (colorbar_panel.h) in the space the layout leaves at the panel's right.
#include <string>
#include <vector>

#include "view/colormap.h"
#include "view/frame.h"
#include "view/legend.h"
#include "view/plot_layout.h"
#include "view/theme.h"

namespace cablefilm {

struct CableMarks {              // stations drawn with a marker; indices outside are skipped
  std::vector<int> weights;      // suspended weights: diamonds
  std::vector<int> fixed_ends;   // prescribed ends that stay put ("fixed end"): squares
  std::vector<int> moving_ends;  // driven ends ("moving end"): rings in the accent colour
  std::vector<int> free_ends;    // free ends ("free end"): rings in the marker colour
};

// The panel's title and legend: an entry per kind of marker present, the two cables' names
// when a companion is drawn, the end path (named `path_label`) and the dashed initial shape
// (named `reference_label`: "equilibrium", or "initial state (straight)" for a straight start),
// the seabed when `seabed` and the water surface when `surface`. `swatch` colours the cables' entries (a mid colour of the map).
PanelHead CablePanelHead(const CableMarks& marks, bool companion, const std::string& main_label,
                         const std::string& companion_label, const std::string& path_label,
                         Rgba swatch, const Theme& th,
                         const std::string& reference_label = "equilibrium",
                         bool seabed = false, bool surface = false);

// Borrowed for one call: the pointers are not kept.
struct CablePanelInput {
  PixelRect panel;                  // the whole panel [px]
  PlotMapping world;                // its axes: world [m] -> pixels, equal scale in x and y
  float cable_width = 6;            // [px]
  float overlay_width = 3.6f;       // the companion's coloured line [px]
  PanelHead head;                   // CablePanelHead(...)
  double tension_min = 0, tension_max = 1;     // the colour range [N]
  const CableSnapshot* now = nullptr;          // required; with its companion when it has one
  const CableSnapshot* equilibrium = nullptr;  // dashed initial shape (x, y); null = none
  CableMarks marks;
  // Paths of the moving ends: polylines in world coordinates [m]; null = none.
  const std::vector<std::vector<Vec2f>>* end_paths = nullptr;
  const double* seabed_y = nullptr;  // the seabed's elevation [m]; null = no seabed
  // The water surface now (CableSnapshot::surface_x, surface_y, x increasing): its line within
  // the plot's x range, the water below it (down to the seabed or the box) a faint wash;
  // empty = none.
  const std::vector<double>* surface_x = nullptr;
  const std::vector<double>* surface_y = nullptr;
};

void DrawCablePanel(Painter& p, const CablePanelInput& in, const Colormap& colormap,
                    const Theme& th);

// How far below a seabed the world box reaches, for a box `height` tall [m]: a strip of ground
// (the film's and the live view's boxes are the cable's, whose anchor often lies on the bed).
inline double SeabedMargin(double height) { return 0.04 * height; }

}  // namespace cablefilm
