#pragma once
// The live view's frame: the film's panels (header, cable, colour bar, tension along the cable,
// tension against time) fed from what a live run knows, which has no fixed duration, range or
// box: the world box follows the cable, the colour range may be locked or follow the run, the
// time plot is a rolling window with markers at the control changes. Plain C++, no GL.
#include <string>
#include <vector>

#include "view/colormap.h"
#include "view/frame.h"
#include "view/frame_layout.h"
#include "view/theme.h"

namespace cablefilm {

struct LiveMarker {   // a control change at time t [s]
  double t = 0;
  std::string label;  // short, e.g. "speed 2x"; cut at kMaxMarkerLabel characters
};

struct LiveFrameInput {
  std::string title;                        // scene title
  std::string status;                       // e.g. "live · 1.0x" or "paused"
  CableSnapshot snapshot;                   // now (no companion)
  std::vector<double> arc_length;           // unstretched arc length of each station [m], s+1
  std::vector<double> section_boundaries;   // interior section ends [m]
  std::vector<std::string> section_names;   // one per section, or empty
  std::vector<int> weight_stations, moving_ends, fixed_ends, free_ends;
  CableSnapshot equilibrium;                // the scene's initial state (t = 0); may be empty
  std::string reference_label = "equilibrium";  // its name: or "initial state (straight)"
  double tension_min = 0, tension_max = 1;  // colour and plot range [N]
  bool range_locked = false;                // shown in the colour bar's caption ("locked")
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;  // world box to show [m] (follows the cable)
  bool seabed = false;                      // a flat seabed at seabed_y [m], in the cable panel
  double seabed_y = 0;
  bool surface = false;                     // waves: the snapshot's water surface is drawn
  // Width / height the cable panel's width is fitted to; 0 = the box's. The panels move when
  // the box's shape changes by more than a step of 1/64 of the frame's width; a steady value
  // here (e.g. the box's over the run so far) keeps them still.
  double layout_aspect = 0;
  double window_start = 0, window_end = 60; // time axis of the time plot [s] (rolling window)
  std::vector<double> times, max_tension;   // the max tension along the cable [N] at each time [s] in the window
  std::vector<double> link_min, link_max;   // envelope per link since the start/restart [N], size s (may be empty)
  std::vector<std::vector<Vec2f>> end_paths;// recent path of each moving end, polyline in metres
  std::vector<LiveMarker> markers;          // control changes inside the window: vertical marker + short label on the time plot
  double peak = 0, peak_t = 0; int peak_link = 0;  // largest tension so far [N], when [s], which link
};

// Throws Error naming the sizes or values unless the input is consistent: s+1 stations (s >= 1)
// with finite positions and tensions, optional series empty or of their size, stations in
// range, increasing ranges and window, finite box.
void CheckLiveFrameInput(const LiveFrameInput& in);

// Where the panels go for this input (the film's arrangement rules; see frame_layout.h).
FrameLayout MakeLiveFrameLayout(const LiveFrameInput& in, int width, int height);

// Same look as the film (dark theme) and the same panels; throws Error on inconsistent sizes.
// The header shows the title, the status, t and the peak so far (its time and link); the time
// plot the window with the trace (at most two points per pixel column) and the markers.
Frame MakeLiveFrame(const LiveFrameInput& in, int width, int height, const Colormap& colormap,
                    const Theme& theme = Theme::Dark());

}  // namespace cablefilm
