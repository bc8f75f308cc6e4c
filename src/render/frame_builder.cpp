#include "render/frame_builder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/error.h"

namespace cablefilm {
namespace {

constexpr double kN = 1000.0;  // tensions are shown in kN

Rgba Hex(std::uint32_t rgb, float a = 1) {
  return {((rgb >> 16) & 0xff) / 255.0f, ((rgb >> 8) & 0xff) / 255.0f, (rgb & 0xff) / 255.0f, a};
}
// Opaque blend of a over b (t = weight of a): faint lines stay opaque, so joints of a
// polyline do not double-blend.
Rgba Mix(Rgba a, Rgba b, float t) {
  return {a.r * t + b.r * (1 - t), a.g * t + b.g * (1 - t), a.b * t + b.b * (1 - t), 1};
}

std::string Format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

// Width of a string in DejaVu Sans, estimated at 0.6 em per character (about its average
// advance): only used to space legend entries, which have generous gaps.
float EstimateTextWidth(const std::string& s, float size) {
  int chars = 0;
  for (unsigned char c : s)
    if ((c & 0xC0) != 0x80) ++chars;
  return 0.6f * size * chars;
}

class Painter {
 public:
  Painter(Frame* frame, float scale) : f_(*frame), k_(scale) {}
  float k() const { return k_; }

  void Rect(const PixelRect& r, Rgba c) { Add(ShapeKind::kRect, {r.x0, r.y0}, {r.x1, r.y1}, 0, c); }
  void Line(Vec2f a, Vec2f b, float width, Rgba c) { Add(ShapeKind::kSegment, a, b, width, c); }
  void Disc(Vec2f centre, float radius, Rgba c) { Add(ShapeKind::kDisc, centre, centre, radius, c); }
  void Diamond(Vec2f centre, float radius, Rgba c) {
    Add(ShapeKind::kDiamond, centre, centre, radius, c);
  }
  void Square(Vec2f centre, float half, Rgba c) {
    Rect({centre.x - half, centre.y - half, centre.x + half, centre.y + half}, c);
  }
  void Triangle(Vec2f a, Vec2f b, Vec2f c, Rgba color) {
    Shape s;
    s.kind = ShapeKind::kTriangle;
    s.a = a;
    s.b = b;
    s.c = c;
    s.color = color;
    f_.shapes.push_back(s);
  }
  void Polyline(const std::vector<Vec2f>& p, float width, Rgba c) {
    for (std::size_t i = 1; i < p.size(); ++i) Line(p[i - 1], p[i], width, c);
    if (p.size() == 1) Disc(p[0], width / 2, c);
  }
  // Dashes continue across the polyline's vertices.
  void Dashed(const std::vector<Vec2f>& p, float width, Rgba c, float dash, float gap) {
    float phase = 0;  // distance into the current dash+gap period
    const float period = dash + gap;
    for (std::size_t i = 1; i < p.size(); ++i) {
      const float dx = p[i].x - p[i - 1].x, dy = p[i].y - p[i - 1].y;
      const float len = std::sqrt(dx * dx + dy * dy);
      float s = 0;
      while (s < len) {
        const bool on = phase < dash;
        const float run = std::min(len - s, on ? dash - phase : period - phase);
        if (on && run > 0.01f)
          Line({p[i - 1].x + dx * s / len, p[i - 1].y + dy * s / len},
               {p[i - 1].x + dx * (s + run) / len, p[i - 1].y + dy * (s + run) / len}, width, c);
        s += run;
        phase = std::fmod(phase + run, period);
      }
    }
  }
  void Text(std::string text, Vec2f pos, float size, Rgba c, HAlign h = HAlign::kLeft,
            VAlign v = VAlign::kBaseline, bool vertical = false, bool bold = false) {
    TextItem t;
    t.text = std::move(text);
    t.pos = pos;
    t.size = std::max(6.0f, size);
    t.color = c;
    t.halign = h;
    t.valign = v;
    t.vertical = vertical;
    t.bold = bold;
    f_.texts.push_back(std::move(t));
  }

 private:
  void Add(ShapeKind kind, Vec2f a, Vec2f b, float size, Rgba c) {
    Shape s;
    s.kind = kind;
    s.a = a;
    s.b = b;
    s.size = size;
    s.color = c;
    f_.shapes.push_back(s);
  }
  Frame& f_;
  float k_;
};

// Clamped to the plot area, so a value outside the film's fixed ranges stays on its plot.
Vec2f PlotPoint(const PlotMapping& m, double x, double y) {
  Vec2f p = m.ToPixel(x, y);
  p.x = std::clamp(p.x, m.rect.x0, m.rect.x1);
  p.y = std::clamp(p.y, m.rect.y0, m.rect.y1);
  return p;
}

// Grid, axis lines, tick labels and axis titles of a plot area.
void DrawAxes(Painter& p, const PlotMapping& m, const std::string& x_label,
              const std::string& y_label, const Theme& th, int x_target = 8, int y_target = 6) {
  const float k = p.k();
  const PixelRect& r = m.rect;
  const Ticks xt = NiceTicks(m.x_lo, m.x_hi, x_target);
  const Ticks yt = NiceTicks(m.y_lo, m.y_hi, y_target);
  const float tick_font = 15 * k, label_font = 16 * k;
  for (double x : xt.values) {
    const float px = m.PixelX(x);
    p.Line({px, r.y0}, {px, r.y1}, 1 * k, th.grid);
    p.Line({px, r.y1}, {px, r.y1 + 5 * k}, 1.2f * k, th.axis);
    p.Text(FormatTick(x, xt.decimals), {px, r.y1 + 8 * k}, tick_font, th.text_dim, HAlign::kCenter,
           VAlign::kTop);
  }
  for (double y : yt.values) {
    const float py = m.PixelY(y);
    p.Line({r.x0, py}, {r.x1, py}, 1 * k, th.grid);
    p.Line({r.x0 - 5 * k, py}, {r.x0, py}, 1.2f * k, th.axis);
    p.Text(FormatTick(y, yt.decimals), {r.x0 - 9 * k, py}, tick_font, th.text_dim, HAlign::kRight,
           VAlign::kMiddle);
  }
  p.Line({r.x0, r.y1}, {r.x1, r.y1}, 1.2f * k, th.axis);
  p.Line({r.x0, r.y0}, {r.x0, r.y1}, 1.2f * k, th.axis);
  p.Text(x_label, {(r.x0 + r.x1) / 2, r.y1 + 30 * k}, label_font, th.text_dim, HAlign::kCenter,
         VAlign::kTop);
  p.Text(y_label, {r.x0 - 58 * k, (r.y0 + r.y1) / 2}, label_font, th.text_dim, HAlign::kCenter,
         VAlign::kBottom, true);
}

// The polyline moved sideways by `d` pixels (along the bisector of its segments' normals).
std::vector<Vec2f> Offset(const std::vector<Vec2f>& p, float d) {
  std::vector<Vec2f> out(p.size());
  auto normal = [&](std::size_t i) {  // of segment i -> i+1; zero if degenerate
    const float dx = p[i + 1].x - p[i].x, dy = p[i + 1].y - p[i].y;
    const float len = std::sqrt(dx * dx + dy * dy);
    return len > 1e-6f ? Vec2f{-dy / len, dx / len} : Vec2f{0, 0};
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    Vec2f n{0, 0};
    if (i > 0) n = normal(i - 1);
    if (i + 1 < p.size()) {
      const Vec2f m = normal(i);
      n = {n.x + m.x, n.y + m.y};
    }
    const float len = std::sqrt(n.x * n.x + n.y * n.y);
    if (len > 1e-6f) n = {n.x / len, n.y / len};
    out[i] = {p[i].x + d * n.x, p[i].y + d * n.y};
  }
  return out;
}

// The companion cable's look: a dotted light outline on both sides, `rim_width` apart (wider
// than the main cable with its rim, so it still shows where the main cable, drawn on top,
// covers the companion), around a thinner line of the tension colour (per link, by the caller).
void DrawCompanionRim(Painter& p, const std::vector<Vec2f>& pts, float rim_width,
                      const Theme& th) {
  const float k = p.k(), dot = std::max(1.0f, 1.6f * k);
  for (float side : {-1.0f, 1.0f})  // round caps lengthen each dash by the dot width
    p.Dashed(Offset(pts, side * (rim_width - dot) / 2), dot, th.companion_rim, 2.5f * k, 6.5f * k);
}
void DrawCompanionLine(Painter& p, const std::vector<Vec2f>& pts, float width, float rim_width,
                       Rgba color, const Theme& th) {
  DrawCompanionRim(p, pts, rim_width, th);
  p.Polyline(pts, width, color);
}

// A horizontal legend ending near `right`: each swatch followed by its label, left-aligned, so
// a label never runs into its own swatch; the estimated widths only set where the row starts.
struct LegendEntry {
  enum Kind { kLine, kDash, kDot, kBand, kDiamond, kSquare, kRing, kCable, kCompanion } kind;
  Rgba color;
  std::string label;
};
void DrawLegend(Painter& p, float right, float baseline, const std::vector<LegendEntry>& entries,
                const Theme& th, Rgba panel) {
  const float k = p.k(), font = 15 * k, swatch = 24 * k, gap = 22 * k, pad = 7 * k;
  float total = 0;
  for (const auto& e : entries) total += swatch + pad + EstimateTextWidth(e.label, font) + gap;
  float x = right - (total - gap);
  for (const auto& e : entries) {
    const Vec2f c{x + swatch / 2, baseline - 5 * k};
    switch (e.kind) {
      case LegendEntry::kLine:
        p.Line({x, c.y}, {x + swatch, c.y}, 2.5f * k, e.color);
        break;
      case LegendEntry::kDash:
        p.Dashed({{x, c.y}, {x + swatch, c.y}}, 2 * k, e.color, 6 * k, 4 * k);
        break;
      case LegendEntry::kDot:
        p.Dashed({{x, c.y}, {x + swatch, c.y}}, 2 * k, e.color, 2 * k, 3 * k);
        break;
      case LegendEntry::kCable:  // as drawn: the tension colour in its thin grey rim
        p.Line({x + 3 * k, c.y}, {x + swatch - 3 * k, c.y}, 8.5f * k, th.halo);
        p.Line({x + 3 * k, c.y}, {x + swatch - 3 * k, c.y}, 6 * k, e.color);
        break;
      case LegendEntry::kCompanion:  // as drawn: a thinner line in a dotted light rim
        DrawCompanionLine(p, {{x + 1 * k, c.y}, {x + swatch - 1 * k, c.y}}, 3.6f * k, 12 * k,
                          e.color, th);
        break;
      case LegendEntry::kBand:
        p.Rect({x, c.y - 6 * k, x + swatch, c.y + 6 * k}, e.color);
        break;
      case LegendEntry::kDiamond:
        p.Diamond(c, 8 * k, th.marker_edge);
        p.Diamond(c, 5.5f * k, e.color);
        break;
      case LegendEntry::kSquare:
        p.Square(c, 6.5f * k, th.marker_edge);
        p.Square(c, 4.5f * k, e.color);
        break;
      case LegendEntry::kRing:
        p.Disc(c, 7 * k, e.color);
        p.Disc(c, 3.5f * k, panel);
        break;
    }
    x += swatch + pad;
    p.Text(e.label, {x, baseline}, font, th.text_dim, HAlign::kLeft);
    x += EstimateTextWidth(e.label, font) + gap;
  }
}

// A trace of vs against ts with at most two points (min and max, in time order) per pixel
// column: the cost of a frame stays bounded however long the film is. NaN values are skipped.
std::vector<Vec2f> DecimatedTrace(const PlotMapping& mm, const std::vector<double>& ts,
                                  const std::vector<double>& vs) {
  std::vector<Vec2f> trace;
  int column = -1;
  std::size_t lo_i = 0, hi_i = 0;
  auto flush = [&]() {
    if (column < 0) return;
    const std::size_t a = std::min(lo_i, hi_i), b = std::max(lo_i, hi_i);
    trace.push_back(PlotPoint(mm, ts[a], vs[a] / kN));
    if (b != a) trace.push_back(PlotPoint(mm, ts[b], vs[b] / kN));
  };
  for (std::size_t i = 0; i < std::min(ts.size(), vs.size()); ++i) {
    if (std::isnan(vs[i])) continue;
    const int col = static_cast<int>(std::floor(mm.PixelX(ts[i])));
    if (col != column) {
      flush();
      column = col;
      lo_i = hi_i = i;
    } else {
      if (vs[i] < vs[lo_i]) lo_i = i;
      if (vs[i] > vs[hi_i]) hi_i = i;
    }
  }
  flush();
  return trace;
}

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
      companion_required_(!spec.companion_label.empty()) {
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
  double peak = s.tension.empty() ? 0 : s.tension[0];
  for (std::size_t j = 0; j < s.tension.size(); ++j) {
    const double T = s.tension[j];
    if (count_ == 0) {
      link_min_[j] = link_max_[j] = T;
    } else {
      link_min_[j] = std::min(link_min_[j], T);
      link_max_[j] = std::max(link_max_[j], T);
    }
    peak = std::max(peak, T);
  }
  if (s.has_companion()) {
    double cpeak = s.ctension.empty() ? 0 : s.ctension[0];
    for (double T : s.ctension) cpeak = std::max(cpeak, T);
    // NaN for earlier snapshots without a companion (only possible when none is required).
    companion_max_tension_.resize(times_.size(), std::numeric_limits<double>::quiet_NaN());
    companion_max_tension_.push_back(cpeak);
  } else if (!companion_max_tension_.empty()) {
    companion_max_tension_.push_back(std::numeric_limits<double>::quiet_NaN());
  }
  times_.push_back(s.t);
  max_tension_.push_back(peak);
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

Theme Theme::Dark() {
  Theme t;
  t.background = Hex(0x0e1217);
  t.panel = Hex(0x161b22);
  t.grid = Hex(0x242b35);
  t.axis = Hex(0x5d6876);
  t.text = Hex(0xe8ecf1);
  t.text_dim = Hex(0x9ba6b5);
  t.current = Hex(0xf3f5f8);
  t.equilibrium = Hex(0x8792a2);
  t.envelope = Hex(0x3d8bd9, 0.38f);
  t.accent = Hex(0xff9f43);
  t.halo = Hex(0x9aa4b2);
  t.marker_fill = Hex(0x161b22);
  t.marker_edge = Hex(0xe8ecf1);
  t.companion = Hex(0xf783ac);
  t.companion_rim = Hex(0xd0d7e1);
  return t;
}

Theme Theme::Light() {
  Theme t;
  t.background = Hex(0xf4f6f8);
  t.panel = Hex(0xffffff);
  t.grid = Hex(0xe4e8ed);
  t.axis = Hex(0x6b7684);
  t.text = Hex(0x1b2129);
  t.text_dim = Hex(0x56616f);
  t.current = Hex(0x1b2129);
  t.equilibrium = Hex(0x8a94a3);
  t.envelope = Hex(0x3d8bd9, 0.3f);
  t.accent = Hex(0xd9480f);
  t.halo = Hex(0x1b2129);
  t.marker_fill = Hex(0xffffff);
  t.marker_edge = Hex(0x1b2129);
  t.companion = Hex(0xc2255c);
  t.companion_rim = Hex(0x56616f);
  return t;
}

FrameLayout MakeFrameLayout(const FilmSpec& spec, int width, int height) {
  CheckSpec(spec);
  if (width < 16 || height < 16)
    throw Error("film: frame size " + std::to_string(width) + "x" + std::to_string(height) +
                " is too small");
  FrameLayout L;
  L.width = width;
  L.height = height;
  const float k = std::min(width / 1920.0f, height / 1080.0f);
  L.scale = k;
  const float W = static_cast<float>(width), H = static_cast<float>(height);
  const float m = 24 * k, header = 86 * k, gap = 16 * k;
  const float avail = H - header - m;
  const float top_h = std::round(0.5f * avail);
  L.cable_panel = {m, header, W - m, header + top_h};
  const float bottom_y0 = L.cable_panel.y1 + gap;
  const float half = (W - 2 * m - gap) / 2;
  L.tension_panel = {m, bottom_y0, m + half, H - m};
  L.max_panel = {m + half + gap, bottom_y0, W - m, H - m};

  // Cable: equal scale, the world box (padded by 4 %) centred in the axes area.
  const PixelRect& cp = L.cable_panel;
  L.colorbar = {cp.x1 - 128 * k, cp.y0 + 50 * k, cp.x1 - 106 * k, cp.y1 - 58 * k};
  const PixelRect axes{cp.x0 + 80 * k, cp.y0 + 50 * k, L.colorbar.x0 - 44 * k, cp.y1 - 58 * k};
  const double dx = spec.x_max - spec.x_min, dy = spec.y_max - spec.y_min;
  const double pad = 0.04 * std::max({dx, dy, 1e-6});
  const double wx = dx + 2 * pad, wy = dy + 2 * pad;
  const double ppm = std::min(axes.width() / wx, axes.height() / wy);  // pixels per metre
  const double cx = 0.5 * (spec.x_min + spec.x_max), cy = 0.5 * (spec.y_min + spec.y_max);
  L.cable.rect = axes;
  L.cable.x_lo = cx - axes.width() / ppm / 2;
  L.cable.x_hi = cx + axes.width() / ppm / 2;
  L.cable.y_lo = cy - axes.height() / ppm / 2;
  L.cable.y_hi = cy + axes.height() / ppm / 2;
  L.cable_width = std::max(1.5f, 6 * k);
  L.companion_width = std::max(2.0f, 0.6f * L.cable_width);
  const bool companion = !spec.companion_label.empty();
  L.legend_rows = companion;

  double t_lo = spec.tension_min / kN, t_hi = spec.tension_max / kN;
  NiceRange(&t_lo, &t_hi, 6);
  auto plot_axes = [&](const PixelRect& p) {
    // With a companion the legends take a second row above the plot.
    return PixelRect{p.x0 + 86 * k, p.y0 + (companion ? 70 : 50) * k, p.x1 - 26 * k,
                     p.y1 - 62 * k};
  };
  L.tension.rect = plot_axes(L.tension_panel);
  L.tension.x_lo = 0;
  L.tension.x_hi = spec.arc_length.back() > 0 ? spec.arc_length.back() : 1;
  L.tension.y_lo = t_lo;
  L.tension.y_hi = t_hi;
  L.max_tension.rect = plot_axes(L.max_panel);
  L.max_tension.x_lo = 0;
  L.max_tension.x_hi = spec.duration > 0 ? spec.duration : 1;
  L.max_tension.y_lo = t_lo;
  L.max_tension.y_hi = t_hi;
  return L;
}

Frame MakeFrame(const FilmSpec& spec, const FilmHistory& history, const CableSnapshot& snap,
                const FrameLayout& L, const Colormap& colormap, const Theme& th) {
  CheckSnapshot(spec, snap);
  Frame frame;
  frame.width = L.width;
  frame.height = L.height;
  frame.background = th.background;
  Painter p(&frame, L.scale);
  const float k = L.scale;
  const std::size_t links = snap.tension.size();
  const double lo = spec.tension_min, hi = spec.tension_max;

  // Header: title, time, and a thin bar of the film's progress.
  const float m = 24 * k;
  p.Text(spec.title, {m, 44 * k}, 30 * k, th.text, HAlign::kLeft, VAlign::kBaseline, false, true);
  const bool comp = snap.has_companion();
  const std::string main_label = spec.label.empty() ? "main" : spec.label;
  const std::string comp_label = spec.companion_label.empty() ? "companion" : spec.companion_label;
  const std::string range = Format("%.1f", lo / kN) + " \u2013 " + Format("%.1f", hi / kN) + " kN";
  std::string both = main_label + " (thick) and " + comp_label + " (thin, dotted outline) cables";
  if (!both.empty() && both[0] >= 'a' && both[0] <= 'z') both[0] = static_cast<char>(both[0] - 32);
  p.Text(comp ? both + "; link tension on one fixed colour range " + range
              : "Link tension on a fixed colour range " + range,
         {m, 70 * k}, 16 * k, th.text_dim);
  const float W = static_cast<float>(L.width);
  p.Text("t = " + Format("%.2f", snap.t) + " s", {W - m, 44 * k}, 30 * k, th.text, HAlign::kRight,
         VAlign::kBaseline, false, true);
  if (spec.duration > 0) {
    p.Text("of " + Format("%.1f", spec.duration) + " s", {W - m, 70 * k}, 16 * k, th.text_dim,
           HAlign::kRight);
    const float x0 = W - m - 260 * k, x1 = W - m - 90 * k, y = 64 * k;
    const float f = static_cast<float>(std::clamp(snap.t / spec.duration, 0.0, 1.0));
    p.Rect({x0, y - 2 * k, x1, y + 2 * k}, th.grid);
    p.Rect({x0, y - 2 * k, x0 + f * (x1 - x0), y + 2 * k}, th.accent);
  }

  // ---- Cable panel ---------------------------------------------------------------------
  const PixelRect& cp = L.cable_panel;
  p.Rect(cp, th.panel);
  p.Text("Cable shape (to scale)", {cp.x0 + 18 * k, cp.y0 + 30 * k}, 19 * k, th.text,
         HAlign::kLeft, VAlign::kBaseline, false, true);
  std::vector<LegendEntry> legend;
  if (comp) {
    legend.push_back({LegendEntry::kCable, colormap.At(0.62), main_label});
    legend.push_back({LegendEntry::kCompanion, colormap.At(0.62), comp_label});
  }
  if (!spec.weight_stations.empty())
    legend.push_back({LegendEntry::kDiamond, th.marker_fill, "weight"});
  if (!spec.fixed_ends.empty()) legend.push_back({LegendEntry::kSquare, th.marker_fill, "anchor"});
  if (!spec.moving_ends.empty()) {
    legend.push_back({LegendEntry::kRing, th.accent, "moving end"});
    legend.push_back({LegendEntry::kLine, Mix(th.accent, th.panel, 0.45f), "its path"});
  }
  legend.push_back({LegendEntry::kDash, th.equilibrium, "equilibrium"});
  DrawLegend(p, L.colorbar.x0 - 44 * k, cp.y0 + 30 * k, legend, th, th.panel);
  DrawAxes(p, L.cable, "x [m]", "y [m]", th, 10, 5);

  auto world = [&](double x, double y) { return L.cable.ToPixel(x, y); };
  if (spec.equilibrium.x.size() == spec.arc_length.size() &&
      spec.equilibrium.y.size() == spec.arc_length.size()) {
    std::vector<Vec2f> eq;
    for (std::size_t j = 0; j < spec.equilibrium.x.size(); ++j)
      eq.push_back(world(spec.equilibrium.x[j], spec.equilibrium.y[j]));
    p.Dashed(eq, 1.6f * k, th.equilibrium, 8 * k, 6 * k);
  }
  for (const auto& path : history.end_paths())
    for (const auto& seg : path)
      p.Line(world(seg.a.x, seg.a.y), world(seg.b.x, seg.b.y), 2 * k, Mix(th.accent, th.panel, 0.45f));
  const float cw = L.cable_width;
  if (comp) {  // beneath the main cable; its dotted rim shows where the two coincide
    std::vector<Vec2f> c;
    for (std::size_t j = 0; j < snap.cx.size(); ++j) c.push_back(world(snap.cx[j], snap.cy[j]));
    DrawCompanionRim(p, c, cw + 7 * k, th);
    for (std::size_t j = 0; j < links; ++j)
      p.Line(c[j], c[j + 1], L.companion_width, colormap.Map(snap.ctension[j], lo, hi));
  }
  for (std::size_t j = 0; j < links; ++j)  // a thin rim keeps the dark end of the map visible
    p.Line(world(snap.x[j], snap.y[j]), world(snap.x[j + 1], snap.y[j + 1]), cw + 2.5f * k,
           th.halo);
  for (std::size_t j = 0; j < links; ++j)
    p.Line(world(snap.x[j], snap.y[j]), world(snap.x[j + 1], snap.y[j + 1]), cw,
           colormap.Map(snap.tension[j], lo, hi));
  if (comp)  // the companion's weights, smaller: hidden by the main's where the two coincide
    for (int w : spec.weight_stations) {
      if (w < 0 || static_cast<std::size_t>(w) >= snap.cx.size()) continue;
      const Vec2f c = world(snap.cx[w], snap.cy[w]);
      p.Diamond(c, 8.5f * k, th.companion_rim);
      p.Diamond(c, 6 * k, th.marker_fill);
    }
  for (int w : spec.weight_stations) {
    if (w < 0 || static_cast<std::size_t>(w) >= snap.x.size()) continue;
    const Vec2f c = world(snap.x[w], snap.y[w]);
    p.Diamond(c, 11 * k, th.marker_edge);
    p.Diamond(c, 8 * k, th.marker_fill);
  }
  for (int e : spec.fixed_ends) {
    if (e < 0 || static_cast<std::size_t>(e) >= snap.x.size()) continue;
    const Vec2f c = world(snap.x[e], snap.y[e]);
    p.Square(c, 8 * k, th.marker_edge);
    p.Square(c, 5.5f * k, th.marker_fill);
  }
  for (int e : spec.moving_ends) {
    if (e < 0 || static_cast<std::size_t>(e) >= snap.x.size()) continue;
    const Vec2f c = world(snap.x[e], snap.y[e]);
    p.Disc(c, 9 * k, th.accent);
    p.Disc(c, 4.5f * k, th.panel);
  }

  // Colour bar with its kN ticks; a mark at the current largest tension.
  const PixelRect& cb = L.colorbar;
  constexpr int kBands = 128;
  for (int i = 0; i < kBands; ++i) {
    const float y1 = cb.y1 - cb.height() * i / kBands, y0 = cb.y1 - cb.height() * (i + 1) / kBands;
    p.Rect({cb.x0, std::floor(y0), cb.x1, std::ceil(y1)}, colormap.At((i + 0.5) / kBands));
  }
  p.Line({cb.x0, cb.y0}, {cb.x1, cb.y0}, 1 * k, th.axis);
  p.Line({cb.x0, cb.y1}, {cb.x1, cb.y1}, 1 * k, th.axis);
  p.Line({cb.x0, cb.y0}, {cb.x0, cb.y1}, 1 * k, th.axis);
  p.Line({cb.x1, cb.y0}, {cb.x1, cb.y1}, 1 * k, th.axis);
  const Ticks ct = NiceTicks(lo / kN, hi / kN, 6);
  auto bar_y = [&](double kn) {
    return static_cast<float>(cb.y1 - (kn - lo / kN) / ((hi - lo) / kN) * cb.height());
  };
  for (double v : ct.values) {
    const float y = bar_y(v);
    p.Line({cb.x1, y}, {cb.x1 + 5 * k, y}, 1.2f * k, th.axis);
    p.Text(FormatTick(v, ct.decimals), {cb.x1 + 9 * k, y}, 15 * k, th.text_dim, HAlign::kLeft,
           VAlign::kMiddle);
  }
  p.Text("tension [kN]", {cp.x1 - 20 * k, (cb.y0 + cb.y1) / 2}, 16 * k, th.text_dim,
         HAlign::kCenter, VAlign::kBottom, true);
  const double peak_now = links ? *std::max_element(snap.tension.begin(), snap.tension.end()) : 0;
  {
    const float y = std::clamp(bar_y(peak_now / kN), cb.y0, cb.y1);
    p.Triangle({cb.x0 - 10 * k, y - 6 * k}, {cb.x0 - 10 * k, y + 6 * k}, {cb.x0 - 1 * k, y},
               th.text);
  }
  const double cpeak_now =
      comp && links ? *std::max_element(snap.ctension.begin(), snap.ctension.end()) : 0;
  if (comp) {  // the companion's just left of the main one, in its curve colour
    const float y = std::clamp(bar_y(cpeak_now / kN), cb.y0, cb.y1);
    p.Triangle({cb.x0 - 20 * k, y - 6 * k}, {cb.x0 - 20 * k, y + 6 * k}, {cb.x0 - 11 * k, y},
               th.companion);
  }

  // ---- Tension along the cable ---------------------------------------------------------
  const PixelRect& tp = L.tension_panel;
  p.Rect(tp, th.panel);
  p.Text("Tension along the cable", {tp.x0 + 18 * k, tp.y0 + 30 * k}, 19 * k, th.text,
         HAlign::kLeft, VAlign::kBaseline, false, true);
  const bool comp_eq = comp && L.legend_rows && spec.companion_equilibrium.tension.size() == links;
  const Rgba comp_eq_color = Mix(th.companion, th.panel, 0.7f);
  if (comp && L.legend_rows) {  // two rows: the curves now, then the references
    DrawLegend(p, tp.x1 - 26 * k, tp.y0 + 30 * k,
               {{LegendEntry::kLine, th.current, main_label + " now"},
                {LegendEntry::kLine, th.companion, comp_label + " now"}},
               th, th.panel);
    std::vector<LegendEntry> refs{{LegendEntry::kDash, th.equilibrium, "equilibrium"}};
    if (comp_eq) refs.push_back({LegendEntry::kDot, comp_eq_color, comp_label + " equilibrium"});
    refs.push_back({LegendEntry::kBand, th.envelope, main_label + " min\u2013max so far"});
    DrawLegend(p, tp.x1 - 26 * k, tp.y0 + 54 * k, refs, th, th.panel);
  } else if (comp) {  // a companion the spec does not name: one row, short labels
    DrawLegend(p, tp.x1 - 26 * k, tp.y0 + 30 * k,
               {{LegendEntry::kLine, th.current, main_label},
                {LegendEntry::kLine, th.companion, comp_label},
                {LegendEntry::kDash, th.equilibrium, "equilibrium"},
                {LegendEntry::kBand, th.envelope, "min\u2013max"}},
               th, th.panel);
  } else {
    DrawLegend(p, tp.x1 - 26 * k, tp.y0 + 30 * k,
               {{LegendEntry::kLine, th.current, "now"},
                {LegendEntry::kDash, th.equilibrium, "equilibrium"},
                {LegendEntry::kBand, th.envelope, "min\u2013max so far"}},
               th, th.panel);
  }
  DrawAxes(p, L.tension, "unstretched arc length from station 0 [m]", "tension [kN]", th, 8, 6);
  const PlotMapping& tm = L.tension;
  for (double b : spec.section_boundaries) {
    const float x = tm.PixelX(b);
    p.Dashed({{x, tm.rect.y0}, {x, tm.rect.y1}}, 1.2f * k, th.axis, 4 * k, 4 * k);
  }
  auto mid = [&](std::size_t j) { return 0.5 * (spec.arc_length[j] + spec.arc_length[j + 1]); };
  if (history.count() > 0 && history.link_min().size() == links) {
    const Rgba edge = Mix(Rgba{th.envelope.r, th.envelope.g, th.envelope.b, 1}, th.panel, 0.7f);
    std::vector<Vec2f> top, bottom;
    for (std::size_t j = 0; j < links; ++j) {
      top.push_back(PlotPoint(tm, mid(j), history.link_max()[j] / kN));
      bottom.push_back(PlotPoint(tm, mid(j), history.link_min()[j] / kN));
    }
    for (std::size_t j = 1; j < links; ++j) {
      p.Triangle(top[j - 1], top[j], bottom[j], th.envelope);
      p.Triangle(top[j - 1], bottom[j], bottom[j - 1], th.envelope);
    }
    p.Polyline(top, 1.2f * k, edge);
    p.Polyline(bottom, 1.2f * k, edge);
  }
  if (spec.equilibrium.tension.size() == links) {
    std::vector<Vec2f> eq;
    for (std::size_t j = 0; j < links; ++j)
      eq.push_back(PlotPoint(tm, mid(j), spec.equilibrium.tension[j] / kN));
    p.Dashed(eq, 2 * k, th.equilibrium, 8 * k, 6 * k);
  }
  if (comp_eq) {
    std::vector<Vec2f> eq;
    for (std::size_t j = 0; j < links; ++j)
      eq.push_back(PlotPoint(tm, mid(j), spec.companion_equilibrium.tension[j] / kN));
    p.Dashed(eq, 2 * k, comp_eq_color, 2 * k, 4 * k);
  }
  {
    std::vector<Vec2f> now;
    for (std::size_t j = 0; j < links; ++j) now.push_back(PlotPoint(tm, mid(j), snap.tension[j] / kN));
    p.Polyline(now, 2.6f * k, th.current);
  }
  if (comp) {  // thinner, on top: where the two agree the main curve shows as its edges
    std::vector<Vec2f> now;
    for (std::size_t j = 0; j < links; ++j)
      now.push_back(PlotPoint(tm, mid(j), snap.ctension[j] / kN));
    p.Polyline(now, 1.8f * k, th.companion);
  }

  // ---- Maximum tension against time (the paper's Figure 1, growing) ----------------------
  const PixelRect& mp = L.max_panel;
  p.Rect(mp, th.panel);
  p.Text("Maximum tension along the cable", {mp.x0 + 18 * k, mp.y0 + 30 * k}, 19 * k, th.text,
         HAlign::kLeft, VAlign::kBaseline, false, true);
  double peak_all = 0;
  for (double v : history.max_tension()) peak_all = std::max(peak_all, v);
  if (comp) {
    double cpeak_all = cpeak_now;  // NaN (no companion) compares false: skipped
    for (double v : history.companion_max_tension()) cpeak_all = std::max(cpeak_all, v);
    DrawLegend(p, mp.x1 - 26 * k, mp.y0 + 30 * k,
               {{LegendEntry::kLine, th.accent, main_label},
                {LegendEntry::kLine, th.companion, comp_label}},
               th, th.panel);
    if (L.legend_rows)
      p.Text(main_label + "  now " + Format("%.2f", peak_now / kN) + ", peak " +
                 Format("%.2f", peak_all / kN) + " kN      " + comp_label + "  now " +
                 Format("%.2f", cpeak_now / kN) + ", peak " + Format("%.2f", cpeak_all / kN) +
                 " kN",
             {mp.x1 - 26 * k, mp.y0 + 54 * k}, 15 * k, th.text_dim, HAlign::kRight);
  } else {
    p.Text("now " + Format("%.2f", peak_now / kN) + " kN    peak " + Format("%.2f", peak_all / kN) +
               " kN",
           {mp.x1 - 26 * k, mp.y0 + 30 * k}, 16 * k, th.text_dim, HAlign::kRight);
  }
  const PlotMapping& mm = L.max_tension;
  DrawAxes(p, mm, "time [s]", "tension [kN]", th, 8, 6);
  if (spec.equilibrium.tension.size() == links && links > 0) {
    const double eq_max =
        *std::max_element(spec.equilibrium.tension.begin(), spec.equilibrium.tension.end());
    const float y = PlotPoint(mm, 0, eq_max / kN).y;
    p.Dashed({{mm.rect.x0, y}, {mm.rect.x1, y}}, 1.6f * k, th.equilibrium, 8 * k, 6 * k);
    p.Text("equilibrium", {mm.rect.x1 - 6 * k, y - 6 * k}, 14 * k, th.equilibrium, HAlign::kRight);
  }
  {
    const auto& ts = history.times();
    const auto& vs = history.max_tension();
    p.Polyline(DecimatedTrace(mm, ts, vs), 2.4f * k, th.accent);
    if (!ts.empty()) p.Disc(PlotPoint(mm, ts.back(), vs.back() / kN), 5 * k, th.accent);
    const auto& cs = history.companion_max_tension();
    if (comp && cs.size() == ts.size()) {  // thinner, on top, like the tension curves
      p.Polyline(DecimatedTrace(mm, ts, cs), 1.8f * k, th.companion);
      if (!ts.empty() && std::isfinite(cs.back()))
        p.Disc(PlotPoint(mm, ts.back(), cs.back() / kN), 4 * k, th.companion);
    }
  }
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
