#include "view/tension_panel.h"

#include <algorithm>

#include "core/error.h"
#include "view/plot_axes.h"

namespace cablefilm {
namespace {

Rgba CompanionEquilibriumColor(const Theme& th) { return Mix(th.overlay, th.panel, 0.7f); }

bool PerLink(const std::vector<double>* v, std::size_t links) {
  return v != nullptr && v->size() == links;
}

}  // namespace

PanelHead TensionPanelHead(bool companion, bool two_rows, bool companion_equilibrium,
                           const std::string& main_label, const std::string& companion_label,
                           const std::string& envelope_label, const Theme& th,
                           const std::string& reference_label) {
  PanelHead head;
  head.title = "Tension along the cable";
  const bool band = !envelope_label.empty();
  if (companion && two_rows) {  // the curves now, then the references
    head.groups.push_back({{LegendEntry::kLine, th.current, main_label + " now"},
                           {LegendEntry::kLine, th.overlay, companion_label + " now"}});
    LegendGroup refs{{LegendEntry::kDash, th.equilibrium, reference_label}};
    if (companion_equilibrium)
      refs.push_back({LegendEntry::kDot, CompanionEquilibriumColor(th),
                      companion_label + " " + reference_label});
    if (band) refs.push_back({LegendEntry::kBand, th.envelope, main_label + " " + envelope_label});
    head.groups.push_back(refs);
  } else if (companion) {  // one row, short labels
    LegendGroup row{{LegendEntry::kLine, th.current, main_label},
                    {LegendEntry::kLine, th.overlay, companion_label},
                    {LegendEntry::kDash, th.equilibrium, reference_label}};
    if (band) row.push_back({LegendEntry::kBand, th.envelope, "min\u2013max"});
    head.groups.push_back(row);
  } else {
    LegendGroup row{{LegendEntry::kLine, th.current, "now"},
                    {LegendEntry::kDash, th.equilibrium, reference_label}};
    if (band) row.push_back({LegendEntry::kBand, th.envelope, envelope_label});
    head.groups.push_back(row);
  }
  return head;
}

void DrawTensionPanel(Painter& p, const TensionPanelInput& in, const Theme& th) {
  const float k = p.k();
  const PlotMapping& tm = in.plot;
  const std::vector<double>& arc = *in.arc_length;
  const std::size_t links = in.tension->size();
  constexpr double kN = kNewtonsPerKilonewton;
  if (arc.size() != links + 1)
    throw Error("tension panel: " + std::to_string(arc.size()) + " stations for " +
                std::to_string(links) + " link tensions");
  DrawPanelHead(p, in.panel, in.head, tm.rect.y0, th);
  DrawAxes(p, tm, "unstretched arc length from station 0 [m]", "tension [kN]", th, 8, 6);

  if (in.section_boundaries) {
    for (double b : *in.section_boundaries) {
      const float x = tm.PixelX(b);
      p.Dashed({{x, tm.rect.y0}, {x, tm.rect.y1}}, 1.2f * k, th.axis, 4 * k, 4 * k);
    }
    // Names where they fit in their span, clear of the boundary lines.
    const std::vector<std::string>* names = in.section_names;
    if (names && names->size() == in.section_boundaries->size() + 1 && !arc.empty()) {
      const float font = 14 * k;
      for (std::size_t i = 0; i < names->size(); ++i) {
        const double a = i == 0 ? arc.front() : (*in.section_boundaries)[i - 1];
        const double b = i < in.section_boundaries->size() ? (*in.section_boundaries)[i] : arc.back();
        const float x0 = std::max(tm.PixelX(a), tm.rect.x0), x1 = std::min(tm.PixelX(b), tm.rect.x1);
        if (EstimateTextWidth((*names)[i], font) + 12 * k > x1 - x0) continue;
        p.Text((*names)[i], {(x0 + x1) / 2, tm.rect.y0 + 7 * k}, font, th.text_dim, HAlign::kCenter,
               VAlign::kTop);
      }
    }
  }
  auto mid = [&](std::size_t j) { return 0.5 * (arc[j] + arc[j + 1]); };
  if (PerLink(in.envelope_min, links) && PerLink(in.envelope_max, links)) {
    const Rgba edge = Mix(Rgba{th.envelope.r, th.envelope.g, th.envelope.b, 1}, th.panel, 0.7f);
    std::vector<Vec2f> top, bottom;
    for (std::size_t j = 0; j < links; ++j) {
      top.push_back(PlotPoint(tm, mid(j), (*in.envelope_max)[j] / kN));
      bottom.push_back(PlotPoint(tm, mid(j), (*in.envelope_min)[j] / kN));
    }
    for (std::size_t j = 1; j < links; ++j) {
      p.Triangle(top[j - 1], top[j], bottom[j], th.envelope);
      p.Triangle(top[j - 1], bottom[j], bottom[j - 1], th.envelope);
    }
    p.Polyline(top, 1.2f * k, edge);
    p.Polyline(bottom, 1.2f * k, edge);
  }
  auto curve = [&](const std::vector<double>& v) {
    std::vector<Vec2f> pts;
    pts.reserve(links);
    for (std::size_t j = 0; j < links; ++j) pts.push_back(PlotPoint(tm, mid(j), v[j] / kN));
    return pts;
  };
  if (PerLink(in.equilibrium, links)) p.Dashed(curve(*in.equilibrium), 2 * k, th.equilibrium, 8 * k, 6 * k);
  if (PerLink(in.companion_equilibrium, links))
    p.Dashed(curve(*in.companion_equilibrium), 2 * k, CompanionEquilibriumColor(th), 2 * k, 4 * k);
  p.Polyline(curve(*in.tension), 2.6f * k, th.current);
  if (PerLink(in.companion_tension, links))  // thinner, on top: where the two agree the main
    p.Polyline(curve(*in.companion_tension), 1.8f * k, th.overlay);  // shows as its edges
}

}  // namespace cablefilm
