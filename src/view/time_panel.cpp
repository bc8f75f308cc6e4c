#include "view/time_panel.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "view/plot_axes.h"

namespace cablefilm {
namespace {

// The first n characters (not bytes) of a UTF-8 string, with an ellipsis when cut.
std::string Shorten(const std::string& s, std::size_t n) {
  std::size_t chars = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if ((static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) continue;  // inside a character
    if (chars == n) return s.substr(0, i) + "\u2026";  // character n + 1 starts here
    ++chars;
  }
  return s;
}

}  // namespace

PanelHead TimePanelHead(const SceneView& scene, bool note_row, const Theme& th) {
  PanelHead head;
  head.title =
      scene.lines_alike ? "Maximum tension along each line" : "Maximum tension along the cable";
  if (scene.lines.size() > 1 || scene.lines_alike) {
    LegendGroup names{
        {LegendEntry::kLine, scene.lines_alike ? LineColor(th, 0) : th.accent, LineName(scene, 0)}};
    for (std::size_t i = 1; i < scene.lines.size(); ++i)
      names.push_back({LegendEntry::kLine, scene.lines_alike ? LineColor(th, i) : th.overlay,
                       LineName(scene, i)});
    head.groups.push_back(names);
    head.note_row = note_row;
  }
  return head;
}

void DrawTimePanel(Painter& p, const TimePanelInput& in, const Theme& th) {
  const float k = p.k();
  const PlotMapping& mm = in.plot;
  constexpr double kN = kNewtonsPerKilonewton;
  const std::vector<double>& ts = *in.times;
  const std::vector<std::vector<double>>& lines = *in.max_tension;
  if (lines.empty()) throw Error("time panel: no line's maximum tensions");
  const std::vector<double>& vs = lines.front();
  if (ts.size() != vs.size())
    throw Error("time panel: " + std::to_string(ts.size()) + " times and " +
                std::to_string(vs.size()) + " maximum tensions");
  const std::vector<LegendGroup> rows = DrawPanelHead(p, in.panel, in.head, mm.rect.y0, th);
  if (!in.note.empty()) {
    const bool own_row = in.head.note_row && rows.size() >= 2;
    p.Text(in.note,
           {in.panel.x1 - 26 * k,
            in.panel.y0 + HeadBaseline(own_row ? static_cast<int>(rows.size()) - 1 : 0, k)},
           (own_row ? 15 : 16) * k, th.text_dim, HAlign::kRight);
  }
  DrawAxes(p, mm, "time [s]", "tension [kN]", th, 8, 6);

  // Markers: lines first, under the traces; labels newest first, each kept only when clear
  // of the last one kept, so that a burst of changes stays readable.
  struct Label {
    std::string text;
    Vec2f pos;
    bool left;  // of its line (near the plot's right edge)
  };
  std::vector<Label> labels;
  const float label_font = 13 * k;
  if (in.markers) {
    std::vector<const TimeMarker*> inside;
    for (const TimeMarker& m : *in.markers)
      if (m.t >= std::min(mm.x_lo, mm.x_hi) && m.t <= std::max(mm.x_lo, mm.x_hi)) inside.push_back(&m);
    std::stable_sort(inside.begin(), inside.end(),
                     [](const TimeMarker* a, const TimeMarker* b) { return a->t > b->t; });
    float last = INFINITY;  // x of the last label kept [px]
    for (const TimeMarker* m : inside) {
      const float x = mm.PixelX(m->t);
      p.Dashed({{x, mm.rect.y0}, {x, mm.rect.y1}}, 1.6f * k, th.event, 6 * k, 4 * k);
      if (m->label.empty() || std::fabs(last - x) < label_font + 6 * k) continue;
      last = x;
      const bool left = x > mm.rect.x1 - label_font - 8 * k;
      labels.push_back({Shorten(m->label, kMaxMarkerLabel),
                        {left ? x - 4 * k : x + 4 * k, mm.rect.y0 + 6 * k}, left});
    }
  }
  // The first line's trace, then the others' (one of another size: none).
  const std::vector<Vec2f> trace = DecimatedTrace(mm, ts, vs, kN);
  std::vector<std::vector<Vec2f>> overlays;
  overlays.reserve(lines.size() - 1);
  for (std::size_t i = 1; i < lines.size(); ++i)
    overlays.push_back(lines[i].size() == ts.size() ? DecimatedTrace(mm, ts, lines[i], kN)
                                                    : std::vector<Vec2f>{});
  float veil_y0 = 0, veil_y1 = 0;  // the equilibrium label's veil, if it needs one [px]
  PixelRect eq_box{};
  if (std::isfinite(in.equilibrium_max)) {
    // Labelled above the line at one end; below it when a trace crosses the place above, and
    // on a veil when a trace crosses both.
    const float y = PlotPoint(mm, mm.x_lo, in.equilibrium_max / kN).y;
    p.Dashed({{mm.rect.x0, y}, {mm.rect.x1, y}}, 1.6f * k, th.equilibrium, 8 * k, 6 * k);
    const float font = 14 * k, w = EstimateTextWidth(in.equilibrium_label, font);
    const float x0 = in.equilibrium_label_left ? mm.rect.x0 + 6 * k : mm.rect.x1 - 6 * k - w;
    const PixelRect above{x0, y - 6 * k - std::max(kMinFontSize, font), x0 + w, y - 3 * k};
    const PixelRect below{x0, y + 3 * k, x0 + w, y + 6 * k + std::max(kMinFontSize, font)};
    auto crosses = [&](const std::vector<Vec2f>& t, const PixelRect& box) {
      for (std::size_t i = 1; i < t.size(); ++i) {
        const Vec2f a = t[i - 1], b = t[i];
        if (std::max(a.x, b.x) < box.x0 || std::min(a.x, b.x) > box.x1) continue;
        if (std::max(a.y, b.y) >= box.y0 && std::min(a.y, b.y) <= box.y1) return true;
      }
      return false;
    };
    auto crossed = [&](const PixelRect& box) {
      return crosses(trace, box) ||
             std::any_of(overlays.begin(), overlays.end(),
                         [&](const std::vector<Vec2f>& t) { return crosses(t, box); });
    };
    const bool under = crossed(above) && !crossed(below);
    eq_box = under ? below : above;
    if (crossed(eq_box)) {
      veil_y0 = eq_box.y0;
      veil_y1 = eq_box.y1;
    }
    p.Text(in.equilibrium_label, {x0, under ? y + 6 * k : y - 6 * k}, font, th.equilibrium, HAlign::kLeft,
           under ? VAlign::kTop : VAlign::kBaseline);
  }
  if (std::isfinite(in.breaking_load)) {  // under the traces, labelled at the left above it
    const float y = PlotPoint(mm, mm.x_lo, in.breaking_load / kN).y;
    if (y >= mm.rect.y0 && y <= mm.rect.y1) {
      p.Dashed({{mm.rect.x0, y}, {mm.rect.x1, y}}, 1.6f * k, th.event, 8 * k, 6 * k);
      p.Text(in.breaking_load_label, {mm.rect.x0 + 6 * k, y - 6 * k}, 14 * k, th.event,
             HAlign::kLeft);
    }
  }
  // Lines drawn alike: each its colour, each thinner than the one before (NestedWidth); else
  // the first thick, the others thinner on top, like the tension curves.
  const Rgba first_color = in.alike ? LineColor(th, 0) : th.accent;
  p.Polyline(trace, (in.alike ? NestedWidth(0, lines.size()) : 2.4f) * k, first_color);
  if (!ts.empty() && std::isfinite(vs.back()))
    p.Disc(PlotPoint(mm, ts.back(), vs.back() / kN), 5 * k, first_color);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].size() != ts.size()) continue;
    const Rgba c = in.alike ? LineColor(th, i) : th.overlay;
    p.Polyline(overlays[i - 1], (in.alike ? NestedWidth(i, lines.size()) : 1.8f) * k, c);
    if (!ts.empty() && std::isfinite(lines[i].back()))
      p.Disc(PlotPoint(mm, ts.back(), lines[i].back() / kN), (in.alike ? 5 : 4) * k, c);
  }
  const Rgba veil{th.panel.r, th.panel.g, th.panel.b, 0.8f};
  if (veil_y1 > veil_y0) p.Rect({eq_box.x0 - 2 * k, veil_y0, eq_box.x1 + 2 * k, veil_y1}, veil);
  // Each label reads bottom to top, its end near the plot's top, on a veil of the panel's
  // colour that keeps it readable where the trace crosses it.
  for (const Label& l : labels) {
    const float across = std::max(kMinFontSize, label_font), along = EstimateTextWidth(l.text, label_font);
    const float x0 = l.left ? l.pos.x - across : l.pos.x - 1 * k;
    p.Rect({x0, l.pos.y - 2 * k, x0 + across + 1 * k, l.pos.y + along + 2 * k}, veil);
    p.Text(l.text, l.pos, label_font, th.event, HAlign::kRight,
           l.left ? VAlign::kBottom : VAlign::kTop, true);
  }
}

}  // namespace cablefilm
