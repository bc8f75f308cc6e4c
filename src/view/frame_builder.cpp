#include "view/frame_builder.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "core/error.h"
#include "view/cable_panel.h"
#include "view/colorbar_panel.h"
#include "view/header_panel.h"
#include "view/legend.h"
#include "view/painter.h"
#include "view/plot_axes.h"
#include "view/tension_panel.h"
#include "view/time_panel.h"

namespace cablefilm {
namespace {

constexpr double kN = kNewtonsPerKilonewton;

void CheckSpec(const FilmSpec& spec) {
  if (spec.arc_length.size() < 2)
    throw Error("film: the spec needs at least 2 stations, got " +
                std::to_string(spec.arc_length.size()));
  if (!(spec.tension_max > spec.tension_min))
    throw Error("film: tension range must be increasing, got [" +
                std::to_string(spec.tension_min) + ", " + std::to_string(spec.tension_max) + "] N");
  if (!(spec.x_max >= spec.x_min) || !(spec.y_max >= spec.y_min))
    throw Error("film: invalid world box x [" + std::to_string(spec.x_min) + ", " +
                std::to_string(spec.x_max) + "], y [" + std::to_string(spec.y_min) + ", " +
                std::to_string(spec.y_max) + "] m");
  if (!spec.section_names.empty() &&
      spec.section_names.size() != spec.section_boundaries.size() + 1)
    throw Error("film: " + std::to_string(spec.section_names.size()) + " section names for " +
                std::to_string(spec.section_boundaries.size() + 1) + " sections");
}

// The panels' titles and legends: the same for the layout (which makes room for them) and
// the frames. `companion`: the frame draws a companion cable.
struct FilmHeads {
  PanelHead cable, tension, time;
};
std::string MainLabel(const FilmSpec& spec) { return spec.label.empty() ? "main" : spec.label; }
std::string CompanionLabel(const FilmSpec& spec) {
  return spec.companion_label.empty() ? "companion" : spec.companion_label;
}
std::string ReferenceLabel(const FilmSpec& spec) {
  return spec.reference_label.empty() ? "equilibrium" : spec.reference_label;
}
// The spec names the companion and gives its equilibrium tensions: drawn dotted.
bool CompanionEquilibrium(const FilmSpec& spec) {
  return !spec.companion_label.empty() &&
         spec.companion_equilibrium.tension.size() + 1 == spec.arc_length.size();
}
FilmHeads MakeFilmHeads(const FilmSpec& spec, bool companion, Rgba swatch, const Theme& th) {
  // A companion the spec names gets the long labels and a second legend row; one that only
  // some snapshots carry (no name) the short ones on one row.
  const bool named = !spec.companion_label.empty();
  const CableMarks marks{spec.weight_stations, spec.fixed_ends, spec.moving_ends, spec.free_ends};
  FilmHeads h;
  h.cable = CablePanelHead(marks, companion, MainLabel(spec), CompanionLabel(spec), "its path",
                           swatch, th, ReferenceLabel(spec), spec.seabed,
                           spec.surface);
  h.tension = TensionPanelHead(companion, named, companion && CompanionEquilibrium(spec),
                               MainLabel(spec), CompanionLabel(spec), "min\u2013max so far", th,
                               ReferenceLabel(spec));
  h.time = TimePanelHead(companion, named, MainLabel(spec), CompanionLabel(spec), th);
  return h;
}

// The end paths' segments joined into polylines where one starts at the previous one's end
// (most do: the history stores them as the end moves), for the cable panel.
std::vector<std::vector<Vec2f>> JoinSegments(const std::vector<FilmHistory::PathSegment>& segs) {
  std::vector<std::vector<Vec2f>> lines;
  for (const auto& s : segs) {
    if (lines.empty() || lines.back().back().x != s.a.x || lines.back().back().y != s.a.y)
      lines.push_back({s.a});
    lines.back().push_back(s.b);
  }
  return lines;
}

// The companion's sizes: all three sized like the main cable, or (when not required) all empty.
void CheckCompanionSizes(std::size_t n, bool required, const CableSnapshot& s) {
  if (!required && !s.has_companion()) return;
  if (s.cx.size() != n || s.cy.size() != n || s.ctension.size() + 1 != n)
    throw Error("film: companion cable at t = " + std::to_string(s.t) + " s has " +
                std::to_string(s.cx.size()) + " x, " + std::to_string(s.cy.size()) + " y and " +
                std::to_string(s.ctension.size()) + " tensions; the film has " +
                std::to_string(n) + " stations and " + std::to_string(n - 1) + " links" +
                (required && !s.has_companion() ? " (the spec names a companion cable)" : ""));
}

}  // namespace

void CheckSnapshot(const FilmSpec& spec, const CableSnapshot& s) {
  const std::size_t n = spec.arc_length.size();
  if (s.x.size() != n || s.y.size() != n || s.tension.size() != n - 1)
    throw Error("film: snapshot at t = " + std::to_string(s.t) + " s has " +
                std::to_string(s.x.size()) + " x, " + std::to_string(s.y.size()) + " y and " +
                std::to_string(s.tension.size()) + " tensions; the film has " + std::to_string(n) +
                " stations and " + std::to_string(n - 1) + " links");
  for (std::size_t j = 0; j < n; ++j)
    if (!std::isfinite(s.x[j]) || !std::isfinite(s.y[j]))
      throw Error("film: station " + std::to_string(j) + " is not finite at t = " +
                  std::to_string(s.t) + " s");
  for (std::size_t j = 0; j + 1 < n; ++j)
    if (!std::isfinite(s.tension[j]))
      throw Error("film: tension of link " + std::to_string(j) + " is not finite at t = " +
                  std::to_string(s.t) + " s");
  CheckCompanionSizes(n, !spec.companion_label.empty(), s);
  if (!s.has_companion()) return;
  for (std::size_t j = 0; j < n; ++j)
    if (!std::isfinite(s.cx[j]) || !std::isfinite(s.cy[j]))
      throw Error("film: companion station " + std::to_string(j) + " is not finite at t = " +
                  std::to_string(s.t) + " s (" + std::to_string(s.cx[j]) + ", " +
                  std::to_string(s.cy[j]) + ")");
  for (std::size_t j = 0; j + 1 < n; ++j)
    if (!std::isfinite(s.ctension[j]))
      throw Error("film: companion tension of link " + std::to_string(j) +
                  " is not finite at t = " + std::to_string(s.t) + " s");
}

// ---------------------------------------------------------------------------------------------

FilmHistory::FilmHistory(const FilmSpec& spec)
    : moving_ends_(spec.moving_ends),
      stations_(spec.arc_length.size()),
      companion_required_(!spec.companion_label.empty()),
      trace_(2, spec.duration > 0 && std::isfinite(spec.duration)
                    ? spec.duration / kTimeTraceSpans
                    : 0),
      peak_(std::numeric_limits<double>::quiet_NaN()),
      peak_t_(std::numeric_limits<double>::quiet_NaN()) {
  CheckSpec(spec);
  x0_ = spec.x_min;
  y0_ = spec.y_min;
  cell_ = std::max({spec.x_max - spec.x_min, spec.y_max - spec.y_min, 1e-9}) / 1000;
  link_min_.assign(stations_ - 1, 0);
  link_max_.assign(stations_ - 1, 0);
  end_paths_.resize(moving_ends_.size());
  path_last_.resize(moving_ends_.size());
  path_seen_.resize(moving_ends_.size());
  for (int e : moving_ends_)
    if (e < 0 || static_cast<std::size_t>(e) >= stations_)
      throw Error("film: moving end " + std::to_string(e) + " is not a station (0.." +
                  std::to_string(stations_ - 1) + ")");
}

void FilmHistory::Add(const CableSnapshot& s) {
  if (s.x.size() != stations_ || s.y.size() != stations_ || s.tension.size() + 1 != stations_)
    throw Error("film: snapshot at t = " + std::to_string(s.t) + " s has " +
                std::to_string(s.x.size()) + " stations and " + std::to_string(s.tension.size()) +
                " links; the film has " + std::to_string(stations_) + " stations");
  CheckCompanionSizes(stations_, companion_required_, s);
  if (s.row_max.size() != s.row_t.size() || (!s.row_cmax.empty() && s.row_cmax.size() != s.row_t.size()))
    throw Error("film: snapshot at t = " + std::to_string(s.t) + " s carries " +
                std::to_string(s.row_t.size()) + " row times, " + std::to_string(s.row_max.size()) +
                " row maxima and " + std::to_string(s.row_cmax.size()) + " companion row maxima");
  const bool row_envelope = !s.row_link_min.empty() || !s.row_link_max.empty();
  if (row_envelope && (s.row_link_min.size() != s.tension.size() ||
                       s.row_link_max.size() != s.tension.size()))
    throw Error("film: snapshot at t = " + std::to_string(s.t) + " s carries a row envelope of " +
                std::to_string(s.row_link_min.size()) + " and " +
                std::to_string(s.row_link_max.size()) + " links; it has " +
                std::to_string(s.tension.size()) + " links");
  double peak = s.tension.empty() ? 0 : s.tension[0];
  for (std::size_t j = 0; j < s.tension.size(); ++j) {
    const double T = s.tension[j];
    const double lo = row_envelope ? std::min(T, s.row_link_min[j]) : T;
    const double hi = row_envelope ? std::max(T, s.row_link_max[j]) : T;
    if (count_ == 0) {
      link_min_[j] = lo;
      link_max_[j] = hi;
    } else {
      link_min_[j] = std::min(link_min_[j], lo);
      link_max_[j] = std::max(link_max_[j], hi);
    }
    peak = std::max(peak, T);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double cpeak = nan;
  if (s.has_companion()) {
    cpeak = s.ctension.empty() ? 0 : s.ctension[0];
    for (double T : s.ctension) cpeak = std::max(cpeak, T);
  }
  if (s.row_t.empty()) {
    AddSample(s.t, peak, cpeak);
  } else {  // every output row since the previous snapshot
    const bool rows_companion = !s.row_cmax.empty();
    for (std::size_t i = 0; i < s.row_t.size(); ++i)
      AddSample(s.row_t[i], s.row_max[i], rows_companion ? s.row_cmax[i] : nan);
  }
  auto cell = [&](Vec2f p) {
    const auto cx = static_cast<std::uint64_t>(std::clamp((p.x - x0_) / cell_, -1e4, 1e4) + 16384);
    const auto cy = static_cast<std::uint64_t>(std::clamp((p.y - y0_) / cell_, -1e4, 1e4) + 16384);
    return (cx << 16) | cy;  // 15 bits each
  };
  for (std::size_t e = 0; e < moving_ends_.size(); ++e) {
    const Vec2f p{static_cast<float>(s.x[moving_ends_[e]]), static_cast<float>(s.y[moving_ends_[e]])};
    if (count_ == 0) {
      path_last_[e] = p;
      continue;
    }
    const std::uint64_t from = cell(path_last_[e]), to = cell(p);
    if (from == to) continue;
    const std::uint64_t key = std::min(from, to) << 32 | std::max(from, to);
    if (path_seen_[e].insert(key).second) end_paths_[e].push_back({path_last_[e], p});
    path_last_[e] = p;
  }
  ++count_;
}

void FilmHistory::AddSample(double t, double max, double companion_max) {
  if (!std::isnan(companion_max)) companion_seen_ = true;
  const double values[2] = {max, companion_max};
  trace_.Add(t, values);
  if (!std::isnan(max) && !(max <= peak_)) {  // the first, or a larger one (NaN peak_: none yet)
    peak_ = max;
    peak_t_ = t;
  }
}

FrameLayout MakeFrameLayout(const FilmSpec& spec, int width, int height) {
  CheckSpec(spec);
  if (width < 16 || height < 16)
    throw Error("film: frame size " + std::to_string(width) + "x" + std::to_string(height) +
                " is too small");
  const FilmHeads heads = MakeFilmHeads(spec, !spec.companion_label.empty(), Rgba{}, Theme::Dark());
  LayoutRequest r;
  r.x_min = spec.x_min;
  r.x_max = spec.x_max;
  r.y_min = spec.y_min;
  r.y_max = spec.y_max;
  r.arc_length = spec.arc_length.back() > 0 ? spec.arc_length.back() : 1;
  r.t_lo = 0;
  r.t_hi = spec.duration > 0 ? spec.duration : 1;
  r.tension_min = spec.tension_min;
  r.tension_max = spec.tension_max;
  r.cable_head = heads.cable;
  r.tension_head = heads.tension;
  r.time_head = heads.time;
  return LayoutFrame(r, width, height);
}

Frame MakeFrame(const FilmSpec& spec, const FilmHistory& history, const CableSnapshot& snap,
                const FrameLayout& L, const Colormap& colormap, const Theme& th) {
  CheckSnapshot(spec, snap);
  Frame frame;
  frame.width = L.width;
  frame.height = L.height;
  frame.background = th.background;
  Painter p(&frame, L.scale);
  const std::size_t links = snap.tension.size();
  const double lo = spec.tension_min, hi = spec.tension_max;
  const bool comp = snap.has_companion(), named = !spec.companion_label.empty();
  const std::string main_label = MainLabel(spec), comp_label = CompanionLabel(spec);
  const FilmHeads heads = MakeFilmHeads(spec, comp, colormap.At(0.62), th);

  // Header: title, time, and a thin bar of the film's progress.
  HeaderInput header;
  header.title = spec.title;
  const std::string range =
      FormatValue("%.1f", lo / kN) + " \u2013 " + FormatValue("%.1f", hi / kN) + " kN";
  std::string both = main_label + " (thick) and " + comp_label + " (thin, dotted outline) cables";
  if (both[0] >= 'a' && both[0] <= 'z') both[0] = static_cast<char>(both[0] - 32);
  header.subtitle = comp ? both + "; link tension on one fixed colour range " + range
                         : "Link tension on a fixed colour range " + range;
  header.time = "t = " + FormatValue("%.2f", snap.t) + " s";
  if (spec.duration > 0) {
    header.note = "of " + FormatValue("%.1f", spec.duration) + " s";
    header.progress = std::clamp(snap.t / spec.duration, 0.0, 1.0);
  }
  DrawHeader(p, static_cast<float>(L.width), header, th);

  CablePanelInput cable;
  cable.panel = L.cable_panel;
  cable.world = L.cable;
  cable.cable_width = L.cable_width;
  cable.overlay_width = L.overlay_width;
  cable.head = heads.cable;
  cable.tension_min = lo;
  cable.tension_max = hi;
  cable.now = &snap;
  cable.equilibrium = &spec.equilibrium;
  cable.marks = {spec.weight_stations, spec.fixed_ends, spec.moving_ends, spec.free_ends};
  std::vector<std::vector<Vec2f>> paths;
  for (const auto& segs : history.end_paths()) {
    auto lines = JoinSegments(segs);
    paths.insert(paths.end(), std::make_move_iterator(lines.begin()),
                 std::make_move_iterator(lines.end()));
  }
  cable.end_paths = &paths;
  if (spec.seabed) cable.seabed_y = &spec.seabed_y;
  if (!snap.surface_x.empty()) {
    cable.surface_x = &snap.surface_x;
    cable.surface_y = &snap.surface_y;
  }
  DrawCablePanel(p, cable, colormap, th);

  // The colour bar, with a mark at the largest tension now (and the companion's).
  const double peak_now = links ? *std::max_element(snap.tension.begin(), snap.tension.end()) : 0;
  const double cpeak_now =
      comp && links ? *std::max_element(snap.ctension.begin(), snap.ctension.end()) : 0;
  ColorBarInput bar;
  bar.bar = L.colorbar;
  bar.caption_x = L.colorbar_caption_x;
  bar.tension_min = lo;
  bar.tension_max = hi;
  bar.now = peak_now;
  if (comp) bar.companion_now = cpeak_now;
  DrawColorBar(p, bar, colormap, th);

  TensionPanelInput tension;
  tension.panel = L.tension_panel;
  tension.plot = L.tension;
  tension.head = heads.tension;
  tension.arc_length = &spec.arc_length;
  tension.tension = &snap.tension;
  if (comp) tension.companion_tension = &snap.ctension;
  tension.equilibrium = &spec.equilibrium.tension;
  if (comp && CompanionEquilibrium(spec))
    tension.companion_equilibrium = &spec.companion_equilibrium.tension;
  if (history.count() > 0) {
    tension.envelope_min = &history.link_min();
    tension.envelope_max = &history.link_max();
  }
  tension.section_boundaries = &spec.section_boundaries;
  tension.section_names = &spec.section_names;
  DrawTensionPanel(p, tension, th);

  // Maximum tension against time (the paper's Figure 1, growing).
  TimePanelInput time;
  time.panel = L.max_panel;
  time.plot = L.max_tension;
  time.head = heads.time;
  // The peak so far is the data's (every output row the snapshots carried), not the frames'.
  const double peak_all = std::isfinite(history.peak()) ? history.peak() : peak_now;
  if (!comp) {
    time.note = "now " + FormatValue("%.2f", peak_now / kN) + " kN    peak " +
                FormatValue("%.2f", peak_all / kN) + " kN";
  } else if (named) {
    double cpeak_all = cpeak_now;  // NaN (no companion) compares false: skipped
    for (double v : history.companion_max_tension()) cpeak_all = std::max(cpeak_all, v);
    time.note = main_label + "  now " + FormatValue("%.2f", peak_now / kN) + ", peak " +
                FormatValue("%.2f", peak_all / kN) + " kN      " + comp_label + "  now " +
                FormatValue("%.2f", cpeak_now / kN) + ", peak " +
                FormatValue("%.2f", cpeak_all / kN) + " kN";
  }
  time.times = &history.times();
  time.max_tension = &history.max_tension();
  if (comp) time.companion_max = &history.companion_max_tension();
  time.equilibrium_label = ReferenceLabel(spec);
  if (spec.equilibrium.tension.size() == links && links > 0)
    time.equilibrium_max =
        *std::max_element(spec.equilibrium.tension.begin(), spec.equilibrium.tension.end());
  DrawTimePanel(p, time, th);
  return frame;
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
  PlotMapping pm;
  pm.rect = {panel.x0 + 100 * k, panel.y0 + 80 * k, panel.x1 - 40 * k, panel.y1 - 80 * k};
  pm.x_lo = 0;
  pm.x_hi = t_hi;
  pm.y_lo = v_lo;
  pm.y_hi = v_hi;
  DrawAxes(p, pm, "time [s]", "maximum tension along the cable [kN]", th, 10, 7);
  static const std::uint32_t kPalette[] = {0x1f6fb4, 0xd9480f, 0x2b8a3e, 0x862e9c, 0x495057};
  std::vector<LegendEntry> legend;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const Rgba c = Hex(kPalette[i % 5]);
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
    p.Polyline(pts, 2.4f * k, c);
    legend.push_back({LegendEntry::kLine, c, series[i].label});
  }
  DrawLegend(p, pm.rect.x1, panel.y0 + 44 * k, legend, th, th.panel);
  return frame;
}

}  // namespace cablefilm
