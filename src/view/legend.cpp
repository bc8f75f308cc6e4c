#include "view/legend.h"

#include <algorithm>
#include <cmath>

#include "view/cable_style.h"

namespace cablefilm {
namespace {

// Legend geometry in design pixels (times k): font, swatch length, gap between entries, space
// between a swatch and its label.
constexpr float kFont = 15, kSwatch = 24, kGap = 22, kPad = 7;
// Head geometry: title font, left and right insets, the least space between title and legend.
constexpr float kTitleFont = 19, kInsetLeft = 18, kInsetRight = 26, kTitleGap = 30;

float EntryWidth(const LegendEntry& e, float k) {
  const float text = EstimateTextWidth(e.label, kFont * k);
  return e.kind == LegendEntry::kText ? text : (kSwatch + kPad) * k + text;
}

float TitleWidth(const PanelHead& head, float k) {
  return EstimateTextWidth(head.title, kTitleFont * k, true);
}

}  // namespace

float LegendWidth(const LegendGroup& entries, float k) {
  float total = 0;
  for (const auto& e : entries) total += EntryWidth(e, k);
  if (entries.size() > 1) total += (entries.size() - 1) * kGap * k;
  return total;
}

void DrawLegend(Painter& p, float right, float baseline, const LegendGroup& entries,
                const Theme& th, Rgba panel) {
  const float k = p.k(), font = kFont * k, swatch = kSwatch * k;
  float x = right - LegendWidth(entries, k);
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
      case LegendEntry::kCable:
        p.Line({x + 3 * k, c.y}, {x + swatch - 3 * k, c.y}, 8.5f * k, th.halo);
        p.Line({x + 3 * k, c.y}, {x + swatch - 3 * k, c.y}, 6 * k, e.color);
        break;
      case LegendEntry::kOverlay:
        DrawOverlayLine(p, {{x + 1 * k, c.y}, {x + swatch - 1 * k, c.y}}, 3.6f * k, 12 * k,
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
      case LegendEntry::kText:
        break;
    }
    if (e.kind != LegendEntry::kText) x += swatch + kPad * k;
    p.Text(e.label, {x, baseline}, font, th.text_dim, HAlign::kLeft);
    x += EstimateTextWidth(e.label, font) + kGap * k;
  }
}

std::vector<LegendGroup> PlanHeadRows(const PanelHead& head, float panel_width, float k) {
  const float row = panel_width - (kInsetLeft + kInsetRight) * k;
  const float beside = row - TitleWidth(head, k) - kTitleGap * k;
  std::vector<LegendGroup> rows;
  LegendGroup all;
  for (const auto& g : head.groups) all.insert(all.end(), g.begin(), g.end());
  if (all.empty() || LegendWidth(all, k) <= beside) {
    if (!all.empty()) rows.push_back(all);
  } else {
    for (const auto& g : head.groups) {
      if (g.empty()) continue;
      if (rows.empty() && LegendWidth(g, k) > beside) rows.emplace_back();  // title alone
      rows.push_back(g);
    }
  }
  if (head.note_row) rows.emplace_back();
  return rows;
}

int HeadRowCount(const PanelHead& head, float panel_width, float k) {
  return std::max(1, static_cast<int>(PlanHeadRows(head, panel_width, k).size()));
}

float HeadBaseline(int row, float k) { return (30 + 24 * row) * k; }

float HeadHeight(int rows, float k) { return (50 + 24 * (std::max(1, rows) - 1)) * k; }

float HeadMinWidth(const PanelHead& head, float k) {
  float widest = TitleWidth(head, k);
  for (const auto& g : head.groups) widest = std::max(widest, LegendWidth(g, k));
  return widest + (kInsetLeft + kInsetRight) * k;
}

std::vector<LegendGroup> DrawPanelHead(Painter& p, const PixelRect& panel, const PanelHead& head,
                                       float plot_top, const Theme& th) {
  const float k = p.k();
  p.Rect(panel, th.panel);
  p.Text(head.title, {panel.x0 + kInsetLeft * k, panel.y0 + HeadBaseline(0, k)}, kTitleFont * k,
         th.text, HAlign::kLeft, VAlign::kBaseline, false, true);
  std::vector<LegendGroup> rows = PlanHeadRows(head, panel.width(), k);
  // Rows that fit above the plot: HeadHeight(rows) <= plot_top - panel.y0 (half a px slack).
  const int fit = 1 + static_cast<int>(std::floor((plot_top - panel.y0 - HeadHeight(1, k) + 0.5f) /
                                                  (HeadHeight(2, k) - HeadHeight(1, k))));
  if (static_cast<int>(rows.size()) > std::max(1, fit)) {
    LegendGroup all;
    for (const auto& g : head.groups) all.insert(all.end(), g.begin(), g.end());
    rows.assign(1, all);
  }
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (!rows[i].empty())
      DrawLegend(p, panel.x1 - kInsetRight * k, panel.y0 + HeadBaseline(static_cast<int>(i), k),
                 rows[i], th, th.panel);
  return rows;
}

}  // namespace cablefilm
