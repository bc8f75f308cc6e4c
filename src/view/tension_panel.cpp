#include "view/tension_panel.h"

#include <algorithm>

#include "core/error.h"
#include "view/plot_axes.h"

namespace cablefilm {
namespace {

Rgba OverlayReferenceColor(const Theme& th) { return Mix(th.overlay, th.panel, 0.7f); }

bool PerLink(const std::vector<double>* v, std::size_t links) {
  return v != nullptr && v->size() == links;
}

}  // namespace

PanelHead TensionPanelHead(const SceneView& scene, bool named, const std::string& envelope_label,
                           const Theme& th) {
  PanelHead head;
  head.title = scene.lines_alike ? "Tension along each line" : "Tension along the cable";
  const std::string reference = ReferenceName(scene);
  const std::string first = LineName(scene, 0);
  const std::size_t lines = scene.lines.size();
  const bool band = !envelope_label.empty();
  if (scene.lines_alike) {  // a curve a line in its colour, the references dashed
    LegendGroup names;
    for (std::size_t i = 0; i < lines; ++i)
      names.push_back({LegendEntry::kLine, LineColor(th, i), LineName(scene, i)});
    head.groups.push_back(names);
    head.groups.push_back({{LegendEntry::kDash, th.equilibrium, reference + " (each line's)"}});
  } else if (lines > 1 && named) {  // the curves now, then the references
    LegendGroup now{{LegendEntry::kLine, th.current, first + " now"}};
    for (std::size_t i = 1; i < lines; ++i)
      now.push_back({LegendEntry::kLine, th.overlay, LineName(scene, i) + " now"});
    head.groups.push_back(now);
    LegendGroup refs{{LegendEntry::kDash, th.equilibrium, reference}};
    for (std::size_t i = 1; i < lines; ++i)
      if (!scene.lines[i].reference.tension.empty())
        refs.push_back({LegendEntry::kDot, OverlayReferenceColor(th),
                        LineName(scene, i) + " " + reference});
    if (band) refs.push_back({LegendEntry::kBand, th.envelope, first + " " + envelope_label});
    head.groups.push_back(refs);
  } else if (lines > 1) {  // one row, short labels
    LegendGroup row{{LegendEntry::kLine, th.current, first}};
    for (std::size_t i = 1; i < lines; ++i)
      row.push_back({LegendEntry::kLine, th.overlay, LineName(scene, i)});
    row.push_back({LegendEntry::kDash, th.equilibrium, reference});
    if (band) row.push_back({LegendEntry::kBand, th.envelope, "min\u2013max"});
    head.groups.push_back(row);
  } else {
    LegendGroup row{{LegendEntry::kLine, th.current, "now"},
                    {LegendEntry::kDash, th.equilibrium, reference}};
    if (band) row.push_back({LegendEntry::kBand, th.envelope, envelope_label});
    head.groups.push_back(row);
  }
  return head;
}

void DrawTensionPanel(Painter& p, const TensionPanelInput& in, const Theme& th) {
  const float k = p.k();
  const PlotMapping& tm = in.plot;
  const std::vector<LineView>& lines = *in.lines;
  const std::vector<LineSnapshot>& now = *in.now;
  const LineView& first = lines.front();
  const std::vector<double>& arc = first.arc_length;
  const std::size_t links = now.front().tension.size();
  constexpr double kN = kNewtonsPerKilonewton;
  if (arc.size() != links + 1)
    throw Error("tension panel: " + std::to_string(arc.size()) + " stations for " +
                std::to_string(links) + " link tensions");
  DrawPanelHead(p, in.panel, in.head, tm.rect.y0, th);
  DrawAxes(p, tm, "unstretched arc length from station 0 [m]", "tension [kN]", th, 8, 6);

  // The first line's sections (lines drawn alike have each their own: none are marked).
  static const std::vector<double> kNone;
  const bool sections = !in.alike || lines.size() == 1;
  const std::vector<double>& boundaries = sections ? first.section_boundaries : kNone;
  const std::vector<std::string>& names = first.section_names;
  for (double b : boundaries) {
    const float x = tm.PixelX(b);
    p.Dashed({{x, tm.rect.y0}, {x, tm.rect.y1}}, 1.2f * k, th.axis, 4 * k, 4 * k);
  }
  // Where they fit in their span, clear of the lines.
  if (sections && names.size() == boundaries.size() + 1) {
    const float font = 14 * k;
    for (std::size_t i = 0; i < names.size(); ++i) {
      const double a = i == 0 ? arc.front() : boundaries[i - 1];
      const double b = i < boundaries.size() ? boundaries[i] : arc.back();
      const float x0 = std::max(tm.PixelX(a), tm.rect.x0), x1 = std::min(tm.PixelX(b), tm.rect.x1);
      if (EstimateTextWidth(names[i], font) + 12 * k > x1 - x0) continue;
      p.Text(names[i], {(x0 + x1) / 2, tm.rect.y0 + 7 * k}, font, th.text_dim, HAlign::kCenter,
             VAlign::kTop);
    }
  }
  // At each link's midpoint of the line's own arc lengths.
  auto mid = [](const std::vector<double>& at, std::size_t j) { return 0.5 * (at[j] + at[j + 1]); };
  if (PerLink(in.envelope_min, links) && PerLink(in.envelope_max, links)) {
    const Rgba edge = Mix(Rgba{th.envelope.r, th.envelope.g, th.envelope.b, 1}, th.panel, 0.7f);
    std::vector<Vec2f> top, bottom;
    for (std::size_t j = 0; j < links; ++j) {
      top.push_back(PlotPoint(tm, mid(arc, j), (*in.envelope_max)[j] / kN));
      bottom.push_back(PlotPoint(tm, mid(arc, j), (*in.envelope_min)[j] / kN));
    }
    for (std::size_t j = 1; j < links; ++j) {
      p.Triangle(top[j - 1], top[j], bottom[j], th.envelope);
      p.Triangle(top[j - 1], bottom[j], bottom[j - 1], th.envelope);
    }
    p.Polyline(top, 1.2f * k, edge);
    p.Polyline(bottom, 1.2f * k, edge);
  }
  // Line i's curve of v, when v has a value per link of it and the line an arc length per station.
  auto drawable = [&](std::size_t i, const std::vector<double>& v) {
    return i < lines.size() && !v.empty() && lines[i].arc_length.size() == v.size() + 1;
  };
  auto curve = [&](std::size_t i, const std::vector<double>& v) {
    std::vector<Vec2f> pts;
    pts.reserve(v.size());
    for (std::size_t j = 0; j < v.size(); ++j)
      pts.push_back(PlotPoint(tm, mid(lines[i].arc_length, j), v[j] / kN));
    return pts;
  };
  if (in.alike) {  // every line's reference, then every line now, each in its colour
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (drawable(i, lines[i].reference.tension))
        p.Dashed(curve(i, lines[i].reference.tension), 1.6f * k,
                 Mix(LineColor(th, i), th.panel, 0.55f), 7 * k, 5 * k);
    for (std::size_t i = 0; i < now.size(); ++i)
      if (drawable(i, now[i].tension))
        p.Polyline(curve(i, now[i].tension), NestedWidth(i, now.size()) * k, LineColor(th, i));
    return;
  }
  if (PerLink(&first.reference.tension, links))
    p.Dashed(curve(0, first.reference.tension), 2 * k, th.equilibrium, 8 * k, 6 * k);
  for (std::size_t i = 1; in.overlay_references && i < lines.size(); ++i)
    if (drawable(i, lines[i].reference.tension))
      p.Dashed(curve(i, lines[i].reference.tension), 2 * k, OverlayReferenceColor(th), 2 * k,
               4 * k);
  p.Polyline(curve(0, now.front().tension), 2.6f * k, th.current);
  for (std::size_t i = 1; i < now.size(); ++i)  // thinner, on top: where a line agrees with the
    if (drawable(i, now[i].tension))            // first, the first shows as its edges
      p.Polyline(curve(i, now[i].tension), 1.8f * k, th.overlay);
}

}  // namespace cablefilm
