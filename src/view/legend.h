#pragma once
// Legends and the head of a panel: the bold title at its top left, legend rows right-aligned
// beside and below it. The frame layout plans the rows (PlanHeadRows) to place the plot below
// them, and the panel draws the same plan, so a legend never runs into a title or a plot.
#include <string>
#include <vector>

#include "view/painter.h"
#include "view/theme.h"

namespace cablefilm {

struct LegendEntry {
  enum Kind {
    kLine, kDash, kDot, kBand, kDiamond, kSquare, kRing,
    kCable,      // as the cable is drawn: the tension colour in its thin rim
    kOverlay,    // as a line after the first is drawn (cable_style.h)
    kText,       // no swatch: the label alone (a readout)
  } kind;
  Rgba color;
  std::string label;
};
using LegendGroup = std::vector<LegendEntry>;  // entries that stay on one row

// Width of a legend row at scale k [px], from estimated text widths.
float LegendWidth(const LegendGroup& entries, float k);
// A horizontal legend ending at `right`: each swatch followed by its label, left-aligned, so a
// label never runs into its own swatch. `panel` is the colour behind it (the ring's hole).
void DrawLegend(Painter& p, float right, float baseline, const LegendGroup& entries,
                const Theme& th, Rgba panel);

struct PanelHead {
  std::string title;
  std::vector<LegendGroup> groups;
  // Keep a row below the legend rows for a note the panel draws itself (e.g. a readout).
  bool note_row = false;
};
// Rows of legend entries, row 0 beside the title: every group there when they all fit, else a
// group per row (row 0 left empty when the first does not fit beside the title); then the note
// row (empty) when asked. Depends only on the labels, panel_width [px] and k.
std::vector<LegendGroup> PlanHeadRows(const PanelHead& head, float panel_width, float k);
// Rows the head takes: at least 1 (the title).
int HeadRowCount(const PanelHead& head, float panel_width, float k);
// Baseline of head row `row` below the panel's top [px].
float HeadBaseline(int row, float k);
// From the panel's top to the top of its plot area for a head of `rows` rows [px].
float HeadHeight(int rows, float k);
// The narrowest panel in which the title and each group fit on a row of their own [px].
float HeadMinWidth(const PanelHead& head, float k);
// Draws the panel's background, title and legend rows; returns the rows drawn. `plot_top` is
// where the panel's plot starts [px]: should the plan need more rows than fit above it (a head
// the layout was not told of), every entry goes on the title's row instead.
std::vector<LegendGroup> DrawPanelHead(Painter& p, const PixelRect& panel, const PanelHead& head,
                                       float plot_top, const Theme& th);

}  // namespace cablefilm
