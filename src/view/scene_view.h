#pragma once
// What a picture of a scene shows that stays fixed while it runs (a film, a live session): the
// title, its lines (each with its stations' arc lengths, its sections, its marked stations and
// its reference state), the reference's name, the seabed and whether waves draw a surface.
// Plain data: the film pass and the live session build it (scene_view_builder.h), the history
// and the frame builder read it. A scene of several lines is just `lines` of several (e.g. the
// compare command's elastic and inextensible runs of one cable): the first is drawn in full,
// every line after it as an overlay (thinner, on the same colour range, with its own curves in
// the plots, named by its label). A system of lines (several lines joined at points) sets
// `lines_alike`: every line is then drawn in full, alike, each with a colour of its own in the
// plots, and its points are named where they are.
#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace cablefilm {

// One line at one time. Positions by axis, so a line in space adds z without another case.
struct LineState {
  std::vector<double> x, y;     // station positions [m], s+1 (station 0 = start, s = end)
  std::vector<double> z;        // [m], s+1; empty for a line in the x-y plane (the paper's)
  std::vector<double> tension;  // link tensions [N], s (link j joins stations j and j+1)
};

struct StationMarks {            // stations drawn with a marker (indices into the line's)
  std::vector<int> weights;      // suspended weights
  std::vector<int> fixed_ends;   // prescribed ends that stay put
  std::vector<int> moving_ends;  // driven ends: their path is drawn
  std::vector<int> free_ends;    // free ends (a dangling or towed end)
};

struct LineView {
  std::string label;                       // e.g. "elastic": names the line among several
  std::vector<double> arc_length;          // unstretched arc length of each station [m], s+1
  std::vector<double> section_boundaries;  // arc lengths where a section ends, interior [m]
  // Name of each section (e.g. its material), section_boundaries.size() + 1, shown in the
  // tension-along-the-cable plot; empty = unnamed.
  std::vector<std::string> section_names;
  StationMarks marks;
  // The initial state (t = 0), drawn dashed: empty = none; its tensions may be empty alone.
  LineState reference;
  // The line's one minimum breaking load [N] (every link's, SingleBreakingLoad); NaN = none:
  // the time plot's dashed "MBL" line, or its note when the MBL is off the plot.
  double breaking_load = std::numeric_limits<double>::quiet_NaN();
};

// The name of the reference when a run starts from the straight chord at rest (not an
// equilibrium: its tensions are those of the evenly stretched chord, zero when slack).
inline constexpr char kStraightStateLabel[] = "initial state (straight)";

// A point of a system of lines (an anchor, a fairlead, a clump weight, a buoy): it is where
// line `line`'s station `station` is (a line end attached to it), and is named there.
struct PointView {
  std::string name;
  int line = 0, station = 0;
};

// A rigid body of a system: drawn as the outline through its points (its fairleads), named;
// or, with a box, as the box's 12 edges at its pose, which its points' places give (body_fit.h).
struct BodyView {
  std::string name;
  std::vector<int> points;  // indices into SceneView::points
  // Each point's position in the body's axes [m] (as `points`; empty: none known) and the
  // body's rest angles [rad] (about x, then y, then z): its pose from where its points are.
  std::vector<std::array<double, 3>> local;
  std::array<double, 3> rest_angles{};
  // A driven body that turns: its angles at time t [s] in rad (as its motion gives them), the
  // turn of a box whose points are too few to give it; empty: its rest angles.
  std::function<std::array<double, 3>(double t)> angles_at;
  bool has_box = false;                // drawn as a box, not the outline
  std::array<double, 3> box{};         // its sizes along the body's x, y, z [m]
  std::array<double, 3> box_center{};  // in the body's axes from its reference point [m]
};

struct SeaView {
  bool seabed = false;   // a flat seabed, drawn in the cable panel
  double seabed_y = 0;   // its elevation [m]
  bool surface = false;  // waves: each snapshot carries the water surface
  // The scene's current at the top of the water (the still water level, else the top of its
  // profile) [m/s], along x, y, z: what a snapshot shows before it says otherwise.
  std::array<double, 3> current{};
  bool current_profile = false;  // the current varies with depth
};

struct SceneView {
  std::string title;
  std::vector<LineView> lines;  // at least one
  // What every line's `reference` is, as the legends name it: "equilibrium" (the static
  // equilibrium) or, for a run started from the straight chord, kStraightStateLabel.
  std::string reference_label = "equilibrium";
  SeaView sea;
  // Drawn in space: a perspective view of the lines as lit tubes beside their plan and
  // elevation (scene/film_view.h says when); else in the plane z = 0, the paper's picture.
  bool space = false;
  // Every line drawn alike (a system of lines): each in full on the one colour range, its ends
  // marked by role, its reference and its moving ends' paths drawn, its name beside its shape
  // and a curve of its own colour (LineColor) in each plot. false: the first line in full and
  // the others as overlays (compare).
  bool lines_alike = false;
  std::vector<PointView> points;  // named on the picture (lines_alike); may be empty
  std::vector<BodyView> bodies;   // outlined through their points; may be empty
};

// Throws Error (naming the line and the sizes or the value) unless the scene has a line and
// every line at least 2 stations, a name per section or none, marked stations among its
// stations, a reference that is empty or of its sizes (tensions alone may be empty), points
// at stations of its lines, and bodies through its points.
void CheckSceneView(const SceneView& scene);

// How legends and messages name line i: its label, else "line <i + 1>".
std::string LineName(const SceneView& scene, std::size_t line);
// The reference's name: reference_label, else "equilibrium".
std::string ReferenceName(const SceneView& scene);
// Every line after the first has a label: the legends then name each curve after its line
// (with a row of their own), else they use short names on one row.
bool OverlaysNamed(const SceneView& scene);

}  // namespace cablefilm
