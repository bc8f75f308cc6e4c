#include "view/frame_builder.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "view/body_fit.h"
#include "view/cable_panel.h"
#include "view/colorbar_panel.h"
#include "view/header_panel.h"
#include "view/legend.h"
#include "view/painter.h"
#include "view/plane_views.h"
#include "view/plot_axes.h"
#include "view/space_layout.h"
#include "view/space_view.h"
#include "view/tension_panel.h"
#include "view/time_panel.h"

namespace cablefilm {
namespace {

constexpr double kN = kNewtonsPerKilonewton;

// The panels' titles and legends: the same for the layout (which makes room for them) and the
// frames.
struct Heads {
  PanelHead cable, tension, time;
};
Heads MakeHeads(const SceneView& scene, const History& history, Rgba swatch, const Theme& th) {
  const bool named = OverlaysNamed(scene);
  // The film names its band from the start; the live view once it has one.
  const bool band = !history.following() || history.count() > 0;
  Heads h;
  const char* path = history.following() ? "recent path" : "its path";
  h.cable = scene.space ? SpaceViewHead(scene, path, swatch, th)
                        : CablePanelHead(scene, path, swatch, th);
  // Lines drawn alike have no band: one a line would hide the curves.
  const bool lines_band = band && !scene.lines_alike;
  h.tension = TensionPanelHead(scene, named, lines_band ? "min\u2013max so far" : "", th);
  h.time = TimePanelHead(scene, named, th);
  return h;
}

std::string Kilonewtons(double tension) { return FormatValue("%.2f", tension / kN); }  // [N]

double LargestTension(const LineSnapshot& line) {  // [N]
  return *std::max_element(line.tension.begin(), line.tension.end());
}

// "Link tension on ... colour range lo – hi kN", naming the lines first when there are several:
// "Elastic (thick) and inextensible (thin, dotted outline) cables; link tension on ...".
std::string Subtitle(const SceneView& scene, const History& history) {
  const std::string range = FormatValue("%.1f", history.range_min() / kN) + " \u2013 " +
                            FormatValue("%.1f", history.range_max() / kN) + " kN";
  const bool several = scene.lines.size() > 1;
  std::string on = history.following()
                       ? (several ? "one colour range " : "colour range ")
                       : (several ? "one fixed colour range " : "a fixed colour range ");
  on += range;
  if (history.range_locked()) on += " (locked)";
  if (!several) return "Link tension on " + on;
  if (scene.lines_alike)
    return std::to_string(scene.lines.size()) +
           " lines, each named in its colour; link tension on " + on;
  std::string names = LineName(scene, 0) + " (thick) and ";
  for (std::size_t i = 1; i < scene.lines.size(); ++i)
    names += (i > 1 ? ", " : "") + LineName(scene, i);
  names += " (thin, dotted outline) cables; link tension on " + on;
  if (names[0] >= 'a' && names[0] <= 'z') names[0] = static_cast<char>(names[0] - 32);
  return names;
}

// Under the time: the film's length and its progress, or the live view's peak so far.
void HeaderNote(const SceneView& scene, const History& history, double t, HeaderInput* header) {
  if (!history.following()) {
    const double start = history.start(), span = history.duration();
    if (span > 0) {
      header->note = start > 0 ? "window " + FormatValue("%.1f", start) + " to " +
                                     FormatValue("%.1f", start + span) + " s"
                               : "of " + FormatValue("%.1f", span) + " s";
      header->progress = std::clamp((t - start) / span, 0.0, 1.0);
    }
    return;
  }
  if (history.count() == 0) return;
  std::size_t top = 0;  // the line of the largest peak
  for (std::size_t i = 1; i < scene.lines.size(); ++i)
    if (history.has_peak(i) && !(history.peak(i) <= history.peak(top))) top = i;
  header->note = "peak " + Kilonewtons(history.peak(top)) + " kN at t = " +
                 FormatValue("%.2f", history.peak_t(top)) + " s";
  if (history.peak_link(top) >= 0)
    header->note += ", link " + std::to_string(history.peak_link(top));
  if (scene.lines.size() > 1) header->note += ", " + LineName(scene, top);
}

// The time plot's readout: each line's largest tension now, and in the film its peak so far
// (the data's: every output row the snapshots carried, not the frames'). With several lines
// each is named, when they all have names (no readout otherwise: the legend has no room).
std::string TimeNote(const SceneView& scene, const History& history, const Snapshot& snap) {
  const std::size_t lines = snap.lines.size();
  if (scene.lines_alike) {  // too many for a readout each: the largest now and the peak so far
    std::size_t top = 0, peak = 0;
    for (std::size_t i = 1; i < lines; ++i) {
      if (LargestTension(snap.lines[i]) > LargestTension(snap.lines[top])) top = i;
      if (history.has_peak(i) && !(history.peak(i) <= history.peak(peak))) peak = i;
    }
    std::string note = "largest now " + Kilonewtons(LargestTension(snap.lines[top])) + " kN (" +
                       LineName(scene, top) + ")";
    if (!history.following() && history.has_peak(peak))
      note += ", peak " + Kilonewtons(history.peak(peak)) + " kN (" + LineName(scene, peak) +
              ", t = " + FormatValue("%.2f", history.peak_t(peak)) + " s)";
    return note;
  }
  if (lines > 1 && !OverlaysNamed(scene)) return "";
  std::string note;
  for (std::size_t i = 0; i < lines; ++i) {
    const double now = LargestTension(snap.lines[i]);
    if (lines > 1) note += (i > 0 ? "      " : "") + LineName(scene, i) + "  ";
    note += "now " + Kilonewtons(now);
    if (history.following()) {
      note += " kN";
      continue;
    }
    // The first line's peak is its samples' alone (the rows'); an overlay's counts its state now.
    double peak = now;  // before any sample
    if (history.has_peak(i)) peak = i == 0 ? history.peak(0) : std::max(now, history.peak(i));
    note += (lines > 1 ? ", peak " : " kN    peak ") + Kilonewtons(peak) + " kN";
  }
  return note;
}

// The top row of a frame in space: the perspective view, the plan and the elevation.
void DrawSpaceRow(Painter& p, const SceneView& scene, const History& history, const Snapshot& snap,
                  const FrameLayout& L, const PanelHead& head, const OrbitCamera* camera,
                  const Colormap& colormap, const Theme& th) {
  SpaceViewInput space;
  space.panel = L.space_panel;
  space.view = L.space_view;
  space.head = head;
  space.camera = camera ? *camera : DefaultCamera(scene);
  space.box = history.view_box();
  space.cable_width = L.cable_width;
  space.overlay_width = L.overlay_width;
  space.tension_min = history.range_min();
  space.tension_max = history.range_max();
  space.scene = &scene;
  space.now = &snap;
  space.end_paths = &history.end_paths();
  DrawSpaceView(p, space, colormap, th);
  PlaneViewsInput planes;
  planes.scene = &scene;
  planes.history = &history;
  planes.now = &snap;
  planes.plane = MakeElevationPlane(scene);
  planes.tension_min = history.range_min();
  planes.tension_max = history.range_max();
  DrawPlaneViews(p, L, planes, colormap, th);
}

}  // namespace

FrameLayout MakeFrameLayout(const SceneView& scene, const History& history, int width,
                            int height) {
  CheckSceneView(scene);
  const WorldBox box = history.box();
  for (double v : {box.x_min, box.x_max, box.y_min, box.y_max})
    if (!std::isfinite(v))
      throw Error("frame: the world box is not finite: x [" + std::to_string(box.x_min) + ", " +
                  std::to_string(box.x_max) + "], y [" + std::to_string(box.y_min) + ", " +
                  std::to_string(box.y_max) + "] m");
  const Heads heads = MakeHeads(scene, history, Rgba{}, Theme::Dark());
  double length = 0;  // of the longest line [m]
  for (const LineView& line : scene.lines) length = std::max(length, line.arc_length.back());
  if (scene.space) {
    SpaceLayoutRequest s;
    SetPlaneBoxes(box, MakeElevationPlane(scene), &s);
    s.arc_length = length > 0 ? length : 1;
    s.t_lo = history.time_min();
    s.t_hi = history.time_max();
    s.tension_min = history.range_min();
    s.tension_max = history.range_max();
    s.space_head = heads.cable;
    s.plan_head = PlanHead();
    s.elevation_head = ElevationHead(MakeElevationPlane(scene));
    s.tension_head = heads.tension;
    s.time_head = heads.time;
    return LayoutSpaceFrame(s, width, height);
  }
  LayoutRequest r;
  r.x_min = box.x_min;
  r.x_max = box.x_max;
  r.y_min = box.y_min;
  r.y_max = box.y_max;
  r.fit_aspect = history.layout_aspect();
  r.arc_length = length > 0 ? length : 1;
  r.t_lo = history.time_min();
  r.t_hi = history.time_max();
  r.tension_min = history.range_min();
  r.tension_max = history.range_max();
  r.cable_head = heads.cable;
  r.tension_head = heads.tension;
  r.time_head = heads.time;
  return LayoutFrame(r, width, height);
}

Frame MakeFrame(const SceneView& scene, const History& history, const Snapshot& snap,
                const FrameLayout& L, const Colormap& colormap, const Theme& th,
                const std::string& status, const OrbitCamera* camera) {
  CheckSceneView(scene);
  CheckSnapshot(scene, snap);
  Frame frame;
  frame.width = L.width;
  frame.height = L.height;
  frame.background = th.background;
  Painter p(&frame, L.scale);
  const double lo = history.range_min(), hi = history.range_max();
  const Heads heads = MakeHeads(scene, history, colormap.At(0.62), th);

  HeaderInput header;
  header.title = scene.title;
  header.status = status;
  header.subtitle = Subtitle(scene, history);
  header.time = "t = " + FormatValue("%.2f", snap.t) + " s";
  HeaderNote(scene, history, snap.t, &header);
  DrawHeader(p, static_cast<float>(L.width), header, th);

  if (L.space) {
    DrawSpaceRow(p, scene, history, snap, L, heads.cable, camera, colormap, th);
  } else {
    CablePanelInput cable;
    cable.panel = L.cable_panel;
    cable.world = L.cable;
    cable.cable_width = L.cable_width;
    cable.overlay_width = L.overlay_width;
    cable.head = heads.cable;
    cable.tension_min = lo;
    cable.tension_max = hi;
    cable.lines = &scene.lines;
    cable.now = &snap.lines;
    cable.end_paths = &history.end_paths();
    cable.alike = scene.lines_alike;
    cable.points = &scene.points;
    cable.bodies = &scene.bodies;
    std::vector<std::vector<PanelEdge>> boxes;  // in the plane z = 0: (x, y)
    for (const auto& edges : BodyBoxesNow(scene, snap.lines, snap.t)) {
      boxes.emplace_back();
      for (const auto& e : edges) boxes.back().push_back({e[0].x(), e[0].y(), e[1].x(), e[1].y()});
    }
    cable.body_boxes = &boxes;
    if (scene.sea.seabed) cable.seabed_y = &scene.sea.seabed_y;
    if (scene.sea.surface && !snap.surface_x.empty()) {
      cable.surface_x = &snap.surface_x;
      cable.surface_y = &snap.surface_y;
    }
    DrawCablePanel(p, cable, colormap, th);
  }

  ColorBarInput bar;
  bar.bar = L.colorbar;
  bar.caption_x = L.colorbar_caption_x;
  bar.tension_min = lo;
  bar.tension_max = hi;
  if (history.range_locked()) bar.caption = "tension [kN], locked";
  bar.now = &snap.lines;
  bar.alike = scene.lines_alike;
  DrawColorBar(p, bar, colormap, th);

  TensionPanelInput tension;
  tension.panel = L.tension_panel;
  tension.plot = L.tension;
  tension.head = heads.tension;
  tension.lines = &scene.lines;
  tension.now = &snap.lines;
  tension.overlay_references = OverlaysNamed(scene);
  tension.alike = scene.lines_alike;
  if (history.count() > 0 && !scene.lines_alike) {
    tension.envelope_min = &history.link_min(0);
    tension.envelope_max = &history.link_max(0);
  }
  DrawTensionPanel(p, tension, th);

  // Maximum tension against time (the paper's Figure 1, growing).
  TimePanelInput time;
  time.panel = L.max_panel;
  time.plot = L.max_tension;
  time.head = heads.time;
  time.note = TimeNote(scene, history, snap);
  time.times = &history.times();
  time.max_tension = &history.max_tension();
  time.alike = scene.lines_alike;
  // The first line's largest reference tension; lines drawn alike: the largest of any line's.
  for (std::size_t i = 0; i < (scene.lines_alike ? scene.lines.size() : 1); ++i) {
    const std::vector<double>& reference = scene.lines[i].reference.tension;
    if (reference.empty()) continue;
    const double top = *std::max_element(reference.begin(), reference.end());
    if (!(top <= time.equilibrium_max)) time.equilibrium_max = top;
  }
  time.equilibrium_label = ReferenceName(scene);
  time.equilibrium_label_left = history.following();  // the newest samples are at the right
  time.markers = &history.markers();
  // The lines' one minimum breaking load: on the plot when within its tension axis, else
  // named in the readout with the peak's utilisation (the axis is not stretched to reach it).
  double mbl = scene.lines.front().breaking_load;
  for (const LineView& line : scene.lines)
    if (!(line.breaking_load == mbl)) mbl = NAN;
  double peak = NAN;  // [N], the largest so far of any line
  for (std::size_t i = 0; i < scene.lines.size(); ++i)
    if (history.has_peak(i) && !(history.peak(i) <= peak)) peak = history.peak(i);
  if (std::isfinite(mbl) && std::isfinite(peak)) {
    const std::string note = BreakingLoadNote(mbl, peak);
    const double lo = std::min(time.plot.y_lo, time.plot.y_hi), hi = std::max(time.plot.y_lo, time.plot.y_hi);
    if (mbl / kN >= lo && mbl / kN <= hi) {
      time.breaking_load = mbl;
      time.breaking_load_label = note;
    } else {
      time.note += (time.note.empty() ? "" : "    ") + note;
    }
  }
  DrawTimePanel(p, time, th);
  return frame;
}

std::string BreakingLoadNote(double breaking_load, double peak) {
  return "MBL " + FormatValue("%.4g", breaking_load / kN) + " kN, peak utilisation " +
         FormatValue("%.3g", 100 * peak / breaking_load) + " %";
}

Frame MakeMaxTensionFigure(const std::string& title, const std::vector<MaxTensionSeries>& series,
                           int width, int height, const Theme& th) {
  if (width < 16 || height < 16)
    throw Error("max tension figure: size " + std::to_string(width) + "x" +
                std::to_string(height) + " is too small");
  double t_hi = 0, v_lo = INFINITY, v_hi = -INFINITY;
  for (const auto& s : series) {
    if (s.t.size() != s.tension.size())
      throw Error("max tension figure: series '" + s.label + "' has " + std::to_string(s.t.size()) +
                  " times and " + std::to_string(s.tension.size()) + " tensions");
    for (std::size_t i = 0; i < s.t.size(); ++i) {
      if (!std::isfinite(s.t[i]) || !std::isfinite(s.tension[i])) continue;
      t_hi = std::max(t_hi, s.t[i]);
      v_lo = std::min(v_lo, s.tension[i] / kN);
      v_hi = std::max(v_hi, s.tension[i] / kN);
    }
  }
  // The series' one breaking load [kN], if they share one: on the axis when it is within a
  // quarter of the traces' span of them, else only named (the peak's utilisation with it).
  double mbl = series.empty() ? NAN : series.front().breaking_load / kN;
  for (const auto& s : series)
    if (!(s.breaking_load / kN == mbl)) mbl = NAN;
  const bool traced = v_hi >= v_lo;
  const double peak = v_hi * kN;  // [N]
  const double reach = 0.25 * std::max(v_hi - v_lo, 1e-3 * std::max(1.0, std::fabs(v_hi)));
  const bool mbl_line = traced && std::isfinite(mbl) && mbl >= v_lo - reach && mbl <= v_hi + reach;
  if (mbl_line) v_lo = std::min(v_lo, mbl), v_hi = std::max(v_hi, mbl);
  if (!(v_hi >= v_lo)) v_lo = 0, v_hi = 1;
  const double pad = 0.05 * std::max(v_hi - v_lo, 1e-3 * std::max(1.0, std::fabs(v_hi)));
  v_lo -= pad;
  v_hi += pad;
  NiceRange(&v_lo, &v_hi, 6);
  if (!(t_hi > 0)) t_hi = 1;

  Frame frame;
  frame.width = width;
  frame.height = height;
  frame.background = th.background;
  const float k = std::min(width / 1600.0f, height / 900.0f);
  Painter p(&frame, k);
  const float W = static_cast<float>(width), H = static_cast<float>(height), m = 24 * k;
  const PixelRect panel{m, m, W - m, H - m};
  p.Rect(panel, th.panel);
  p.Text(title, {panel.x0 + 24 * k, panel.y0 + 44 * k}, 28 * k, th.text, HAlign::kLeft,
         VAlign::kBaseline, false, true);
  std::vector<LegendEntry> legend;  // a colour a series: the lines' palette (8 apart)
  for (std::size_t i = 0; i < series.size(); ++i)
    legend.push_back({LegendEntry::kLine, LineColor(th, i), series[i].label});
  // The legend beside the title when both fit, else on a row of its own under it (a system's
  // names after a long title).
  const float right = panel.x1 - 40 * k;
  const bool own_row = panel.x0 + 24 * k + EstimateTextWidth(title, 28 * k, true) + 40 * k >
                       right - LegendWidth(legend, k);
  const float legend_baseline = panel.y0 + (own_row ? 80 : 44) * k;
  PlotMapping pm;
  pm.rect = {panel.x0 + 100 * k, panel.y0 + (own_row ? 110 : 80) * k, right,
             panel.y1 - 80 * k};
  pm.x_lo = 0;
  pm.x_hi = t_hi;
  pm.y_lo = v_lo;
  pm.y_hi = v_hi;
  DrawAxes(p, pm, "time [s]", "maximum tension along the cable [kN]", th, 10, 7);
  if (traced && std::isfinite(mbl)) {
    const std::string note = BreakingLoadNote(mbl * kN, peak);
    if (mbl_line) {  // dashed across the plot, labelled above it at the left
      const float y = PlotPoint(pm, 0, mbl).y;
      p.Dashed({{pm.rect.x0, y}, {pm.rect.x1, y}}, 1.6f * k, th.event, 8 * k, 6 * k);
      p.Text(note, {pm.rect.x0 + 8 * k, y - 6 * k}, 15 * k, th.event, HAlign::kLeft);
    } else {  // over the plot's top right corner
      p.Text(note, {pm.rect.x1, pm.rect.y0 - 10 * k}, 15 * k, th.text_dim, HAlign::kRight);
    }
  }
  for (std::size_t i = 0; i < series.size(); ++i) {
    const Rgba c = legend[i].color;
    std::vector<Vec2f> pts;
    int column = -1;
    for (std::size_t j = 0; j < series[i].t.size(); ++j) {
      if (!std::isfinite(series[i].t[j]) || !std::isfinite(series[i].tension[j])) continue;
      const Vec2f q = PlotPoint(pm, series[i].t[j], series[i].tension[j] / kN);
      // Keep every point but collapse runs inside one pixel to their extremes (bounded cost).
      const int col = static_cast<int>(std::floor(q.x));
      if (col == column && pts.size() >= 2 && std::fabs(pts.back().x - q.x) < 1 &&
          std::fabs(pts.back().y - q.y) < 0.5f)
        continue;
      column = col;
      pts.push_back(q);
    }
    // Each series thinner than the one before, on top: where they coincide each shows as an
    // edge of the one under it.
    p.Polyline(pts, NestedWidth(i, series.size()) * k, c);
  }
  DrawLegend(p, pm.rect.x1, legend_baseline, legend, th, th.panel);
  return frame;
}

}  // namespace cablefilm
