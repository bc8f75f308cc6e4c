#pragma once
// Builds the abstract frame (no GL) of the film and of the live view alike from the panels
// (header_panel, cable_panel, colorbar_panel, tension_panel, time_panel; for a scene in space
// space_view and plane_views in place of cable_panel): the lines to scale
// coloured by link tension with a colour bar, the tension along each line (now, the reference,
// the first line's min-max envelope so far, the sections named), the maximum tension against
// time, the title and the simulated time. What a film's frame and a live frame differ in
// follows the history's policy (history.h): the film's header shows its progress ("of D s"),
// the live one the status and the peak so far, its colour bar whether the range is locked, its
// time plot a rolling window with markers at the control changes. Also the still of the
// maximum tension against time (the paper's Figure 1). Pure functions of their inputs.
#include <limits>
#include <string>
#include <vector>

#include "view/camera.h"
#include "view/colormap.h"
#include "view/frame.h"
#include "view/frame_layout.h"
#include "view/history.h"
#include "view/scene_view.h"
#include "view/snapshot.h"
#include "view/theme.h"

namespace cablefilm {

// Where everything goes (FrameLayout, frame_layout.h; space_layout.h for a scene in space) for
// the scene and the history as it is now: its box, time axis and range, the lines' lengths, the
// legends. A film's is the same for every frame; a live view's follows its box. Throws Error on
// an invalid scene, a box that is not finite or a frame under 16x16.
FrameLayout MakeFrameLayout(const SceneView& scene, const History& history, int width,
                            int height);

// The frame of `snapshot` (checked against the scene: CheckSnapshot, throws Error) on the
// history's range and time axis, laid out by MakeFrameLayout for it. `status` is the live
// view's state shown before the subtitle (e.g. "live · 1× real time"); "" = none (the film).
// A scene in space is seen by `camera` (null: DefaultCamera(scene)).
Frame MakeFrame(const SceneView& scene, const History& history, const Snapshot& snapshot,
                const FrameLayout& layout, const Colormap& colormap,
                const Theme& theme = Theme::Dark(), const std::string& status = "",
                const OrbitCamera* camera = nullptr);

// One labelled curve of maximum tension along the cable against time.
struct MaxTensionSeries {
  std::string label;            // e.g. "elastic", "inextensible"
  std::vector<double> t;        // [s]
  std::vector<double> tension;  // [N], same size as t
  // The line's one minimum breaking load [N] (SingleBreakingLoad), NaN = none. When every
  // series has the same, the figure shows it: a dashed line "MBL x kN" when it lies within a
  // quarter of the plotted range above the peak (the axis then reaches it), else a note "MBL x
  // kN, peak utilisation y %" over the plot (the axis is not stretched to a far MBL).
  double breaking_load = std::numeric_limits<double>::quiet_NaN();
};

// The text of the MBL's note or label: "MBL 12.5 kN, peak utilisation 61.2 %".
std::string BreakingLoadNote(double breaking_load, double peak);
// The still: every series on one pair of axes with a legend. Throws Error on mismatched sizes.
Frame MakeMaxTensionFigure(const std::string& title, const std::vector<MaxTensionSeries>& series,
                           int width, int height, const Theme& theme = Theme::Light());

}  // namespace cablefilm
