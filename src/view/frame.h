#pragma once
// What the renderer draws, as plain C++ (no GL types): the simulation's snapshots, the
// film-wide specification, and the abstract frame MakeFrame builds from them (shapes and text
// items in pixel coordinates, origin at the top left, y down), which Renderer::Draw rasterises.
#include <cstdint>
#include <string>
#include <vector>

#include "view/scene_view.h"  // kStraightStateLabel

namespace cablefilm {

struct CableSnapshot {            // one output time of the simulation
  double t = 0;                   // simulated time [s]
  std::vector<double> x, y;       // station positions x_j, y_j [m], size s+1 (0 = start, s = end)
  std::vector<double> tension;    // link tensions T_{j+1/2} [N], size s (link j joins j and j+1)
  // An optional companion cable overlaid on this one (e.g. the same scene computed with the
  // inextensible model): its station positions [m], size s+1, and link tensions [N], size s.
  // All three empty = no companion.
  std::vector<double> cx, cy, ctension;
  bool has_companion() const { return !cx.empty() || !cy.empty() || !ctension.empty(); }
  // The output rows (timeseries.csv) since the previous snapshot, up to this one's time: their
  // times [s] and largest link tensions [N] (and the companion's, same times, when it has one).
  // The time plot then shows every row rather than one sample a snapshot, so a peak between
  // film frames is drawn; empty: the snapshot's own largest tension is the plot's sample.
  std::vector<double> row_t, row_max, row_cmax;
  // Optional, size s: each link's smallest and largest tension over those rows [N], so that
  // the min-max envelope of the tension plot covers every row too, not only the frames.
  std::vector<double> row_link_min, row_link_max;
  // Optional: the water surface at this time, a polyline (x increasing, y) [m] reaching beyond
  // the world box on both sides (the plot shows what falls in its x range); empty: none (no
  // waves).
  std::vector<double> surface_x, surface_y;
};

struct FilmSpec {                          // fixed for the whole film
  std::string title;
  std::vector<double> arc_length;          // unstretched arc length of each station [m], size s+1
  std::vector<double> section_boundaries;  // arc lengths where a section ends, interior only [m]
  // Name of each section (e.g. its material), size section_boundaries.size() + 1, shown in the
  // tension-along-the-cable plot; empty = unnamed.
  std::vector<std::string> section_names;
  std::vector<int> weight_stations;        // stations carrying a suspended weight (prism)
  std::vector<int> moving_ends;            // driven ends among {0, s}: their path is drawn
  std::vector<int> fixed_ends;             // prescribed ends that stay put
  std::vector<int> free_ends;              // free ends (a dangling or towed end)
  CableSnapshot equilibrium;               // the initial state (t = 0), drawn dashed
  // What `equilibrium` is, as the legends name it: "equilibrium" (the static equilibrium) or,
  // for a run started from the straight chord, "initial state (straight)".
  std::string reference_label = "equilibrium";
  double duration = 0;                     // simulated seconds the film covers
  double tension_min = 0, tension_max = 1; // colour and plot range [N], fixed for the film
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;  // world box of the cable over the run [m]
  bool seabed = false;                     // a flat seabed, drawn in the cable panel
  double seabed_y = 0;                     // its elevation [m]
  bool surface = false;                    // waves: each snapshot carries the water surface
  // Companion cable (see CableSnapshot::cx): drawn on the same tension scale. `label` names the
  // main cable (e.g. "elastic"), `companion_label` the companion (e.g. "inextensible"); a
  // non-empty companion_label means every snapshot carries a companion. The box above must
  // then hold both cables.
  std::string label = "";
  std::string companion_label = "";
  CableSnapshot companion_equilibrium;     // optional: its tension is drawn (empty = not)
};

// Colours are sRGB, 0..1, with straight (not premultiplied) alpha.
struct Rgba {
  float r = 0, g = 0, b = 0, a = 1;
};

struct Vec2f {
  float x = 0, y = 0;
};

enum class ShapeKind : std::uint8_t {
  kSegment,   // a line from a to b, `size` wide, round caps, anti-aliased edges
  kDisc,      // a filled circle of centre a, radius `size`
  kRect,      // a filled axis-aligned rectangle with corners a and b (a = top left)
  kDiamond,   // a filled square turned 45 degrees, centre a, `size` from centre to tip
  kTriangle,  // a filled triangle a, b, c (no edge anti-aliasing: for area fills)
};

struct Shape {
  ShapeKind kind = ShapeKind::kSegment;
  Vec2f a, b, c;
  float size = 1;  // line width, or radius [px]
  Rgba color;
};

enum class HAlign : std::uint8_t { kLeft, kCenter, kRight };
enum class VAlign : std::uint8_t { kTop, kMiddle, kBaseline, kBottom };

struct TextItem {
  std::string text;  // UTF-8
  Vec2f pos;         // anchor point [px]
  float size = 14;   // nominal font size [px] (em height)
  Rgba color;
  HAlign halign = HAlign::kLeft;
  VAlign valign = VAlign::kBaseline;
  bool vertical = false;  // rotated 90 degrees counter-clockwise (reads bottom to top)
  bool bold = false;
};

// One frame: drawn in order, shapes first, then the text on top.
struct Frame {
  int width = 0, height = 0;
  Rgba background;
  std::vector<Shape> shapes;
  std::vector<TextItem> texts;
};

}  // namespace cablefilm
