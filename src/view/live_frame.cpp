#include "view/live_frame.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "view/cable_panel.h"
#include "view/colorbar_panel.h"
#include "view/header_panel.h"
#include "view/plot_axes.h"
#include "view/tension_panel.h"
#include "view/time_panel.h"

namespace cablefilm {
namespace {

constexpr double kN = kNewtonsPerKilonewton;

struct LiveHeads {
  PanelHead cable, tension, time;
};
LiveHeads MakeLiveHeads(const LiveFrameInput& in, Rgba swatch, const Theme& th) {
  LiveHeads h;
  const CableMarks marks{in.weight_stations, in.fixed_ends, in.moving_ends, in.free_ends};
  h.cable = CablePanelHead(marks, false, "", "", "recent path", swatch, th, in.reference_label,
                           in.seabed, in.surface);
  h.tension = TensionPanelHead(false, false, false, "", "",
                               in.link_min.empty() ? "" : "min\u2013max so far", th,
                               in.reference_label);
  h.time = TimePanelHead(false, false, "", "", th);
  return h;
}

void CheckSize(const char* what, std::size_t got, std::size_t want) {
  if (got != want)
    throw Error(std::string("live frame: ") + what + " has " + std::to_string(got) +
                " values, expected " + std::to_string(want));
}

void CheckStations(const char* what, const std::vector<int>& stations, std::size_t n) {
  for (int j : stations)
    if (j < 0 || static_cast<std::size_t>(j) >= n)
      throw Error(std::string("live frame: ") + what + " " + std::to_string(j) +
                  " is not a station (0.." + std::to_string(n - 1) + ")");
}

std::string Range(double lo, double hi) {  // [N] -> "0.0 – 8.1 kN"
  return FormatValue("%.1f", lo / kN) + " \u2013 " + FormatValue("%.1f", hi / kN) + " kN";
}

}  // namespace

void CheckLiveFrameInput(const LiveFrameInput& in) {
  const std::size_t n = in.arc_length.size();
  if (n < 2) throw Error("live frame: needs at least 2 stations, got " + std::to_string(n));
  const CableSnapshot& s = in.snapshot;
  CheckSize("snapshot x", s.x.size(), n);
  CheckSize("snapshot y", s.y.size(), n);
  CheckSize("snapshot tension", s.tension.size(), n - 1);
  if (s.has_companion())
    throw Error("live frame: the snapshot carries a companion cable; the live view shows one");
  for (std::size_t j = 0; j < n; ++j)
    if (!std::isfinite(s.x[j]) || !std::isfinite(s.y[j]))
      throw Error("live frame: station " + std::to_string(j) + " is not finite at t = " +
                  std::to_string(s.t) + " s");
  for (std::size_t j = 0; j + 1 < n; ++j)
    if (!std::isfinite(s.tension[j]))
      throw Error("live frame: tension of link " + std::to_string(j) + " is not finite at t = " +
                  std::to_string(s.t) + " s");
  const CableSnapshot& eq = in.equilibrium;
  if (!eq.x.empty() || !eq.y.empty() || !eq.tension.empty()) {
    CheckSize("equilibrium x", eq.x.size(), n);
    CheckSize("equilibrium y", eq.y.size(), n);
    if (!eq.tension.empty()) CheckSize("equilibrium tension", eq.tension.size(), n - 1);
  }
  if (!in.section_names.empty())
    CheckSize("section_names", in.section_names.size(), in.section_boundaries.size() + 1);
  CheckStations("weight station", in.weight_stations, n);
  CheckStations("moving end", in.moving_ends, n);
  CheckStations("fixed end", in.fixed_ends, n);
  CheckStations("free end", in.free_ends, n);
  CheckSize("max_tension", in.max_tension.size(), in.times.size());
  if (!in.link_min.empty() || !in.link_max.empty()) {
    CheckSize("link_min", in.link_min.size(), n - 1);
    CheckSize("link_max", in.link_max.size(), n - 1);
  }
  if (in.peak_link < 0 || static_cast<std::size_t>(in.peak_link) >= n - 1)
    throw Error("live frame: peak_link " + std::to_string(in.peak_link) + " is not a link (0.." +
                std::to_string(n - 2) + ")");
  if (!(in.tension_max > in.tension_min) || !std::isfinite(in.tension_min) ||
      !std::isfinite(in.tension_max))
    throw Error("live frame: tension range must be finite and increasing, got [" +
                std::to_string(in.tension_min) + ", " + std::to_string(in.tension_max) + "] N");
  if (!(in.window_end > in.window_start) || !std::isfinite(in.window_start) ||
      !std::isfinite(in.window_end))
    throw Error("live frame: time window must be finite and increasing, got [" +
                std::to_string(in.window_start) + ", " + std::to_string(in.window_end) + "] s");
  for (double v : {in.x_min, in.x_max, in.y_min, in.y_max})
    if (!std::isfinite(v))
      throw Error("live frame: the world box is not finite: x [" + std::to_string(in.x_min) +
                  ", " + std::to_string(in.x_max) + "], y [" + std::to_string(in.y_min) + ", " +
                  std::to_string(in.y_max) + "] m");
}

FrameLayout MakeLiveFrameLayout(const LiveFrameInput& in, int width, int height) {
  CheckLiveFrameInput(in);
  const LiveHeads heads = MakeLiveHeads(in, Rgba{}, Theme::Dark());
  LayoutRequest r;
  r.x_min = in.x_min;
  r.x_max = in.x_max;
  r.y_min = in.y_min;
  r.y_max = in.y_max;
  r.fit_aspect = in.layout_aspect;
  r.arc_length = in.arc_length.back() > 0 ? in.arc_length.back() : 1;
  r.t_lo = in.window_start;
  r.t_hi = in.window_end;
  r.tension_min = in.tension_min;
  r.tension_max = in.tension_max;
  r.cable_head = heads.cable;
  r.tension_head = heads.tension;
  r.time_head = heads.time;
  return LayoutFrame(r, width, height);
}

Frame MakeLiveFrame(const LiveFrameInput& in, int width, int height, const Colormap& colormap,
                    const Theme& th) {
  const FrameLayout L = MakeLiveFrameLayout(in, width, height);  // checks the input
  const LiveHeads heads = MakeLiveHeads(in, colormap.At(0.62), th);
  Frame frame;
  frame.width = width;
  frame.height = height;
  frame.background = th.background;
  Painter p(&frame, L.scale);
  const CableSnapshot& snap = in.snapshot;
  const double now = *std::max_element(snap.tension.begin(), snap.tension.end());

  HeaderInput header;
  header.title = in.title;
  header.status = in.status;
  header.subtitle = "Link tension on colour range " + Range(in.tension_min, in.tension_max) +
                    (in.range_locked ? " (locked)" : "");
  header.time = "t = " + FormatValue("%.2f", snap.t) + " s";
  if (!in.times.empty() || in.peak > 0)
    header.note = "peak " + FormatValue("%.2f", in.peak / kN) + " kN at t = " +
                  FormatValue("%.2f", in.peak_t) + " s, link " + std::to_string(in.peak_link);
  DrawHeader(p, static_cast<float>(width), header, th);

  CablePanelInput cable;
  cable.panel = L.cable_panel;
  cable.world = L.cable;
  cable.cable_width = L.cable_width;
  cable.overlay_width = L.overlay_width;
  cable.head = heads.cable;
  cable.tension_min = in.tension_min;
  cable.tension_max = in.tension_max;
  cable.now = &snap;
  cable.equilibrium = &in.equilibrium;
  cable.marks = {in.weight_stations, in.fixed_ends, in.moving_ends, in.free_ends};
  cable.end_paths = &in.end_paths;
  if (in.seabed) cable.seabed_y = &in.seabed_y;
  if (in.surface && !snap.surface_x.empty()) {
    cable.surface_x = &snap.surface_x;
    cable.surface_y = &snap.surface_y;
  }
  DrawCablePanel(p, cable, colormap, th);

  ColorBarInput bar;
  bar.bar = L.colorbar;
  bar.caption_x = L.colorbar_caption_x;
  bar.tension_min = in.tension_min;
  bar.tension_max = in.tension_max;
  bar.caption = in.range_locked ? "tension [kN], locked" : "tension [kN]";
  bar.now = now;
  DrawColorBar(p, bar, colormap, th);

  TensionPanelInput tension;
  tension.panel = L.tension_panel;
  tension.plot = L.tension;
  tension.head = heads.tension;
  tension.arc_length = &in.arc_length;
  tension.tension = &snap.tension;
  tension.equilibrium = &in.equilibrium.tension;
  if (!in.link_min.empty()) {
    tension.envelope_min = &in.link_min;
    tension.envelope_max = &in.link_max;
  }
  tension.section_boundaries = &in.section_boundaries;
  tension.section_names = &in.section_names;
  DrawTensionPanel(p, tension, th);

  std::vector<TimeMarker> markers;
  markers.reserve(in.markers.size());
  for (const LiveMarker& m : in.markers) markers.push_back({m.t, m.label});
  TimePanelInput time;
  time.panel = L.max_panel;
  time.plot = L.max_tension;
  time.head = heads.time;
  time.note = "now " + FormatValue("%.2f", now / kN) + " kN";
  time.times = &in.times;
  time.max_tension = &in.max_tension;
  if (!in.equilibrium.tension.empty())
    time.equilibrium_max =
        *std::max_element(in.equilibrium.tension.begin(), in.equilibrium.tension.end());
  time.equilibrium_label = in.reference_label;
  time.equilibrium_label_left = true;  // the newest samples and markers are at the right
  time.markers = &markers;
  DrawTimePanel(p, time, th);
  return frame;
}

}  // namespace cablefilm
