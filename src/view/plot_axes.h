#pragma once
// What every plot of a frame shares: the unit its tensions are shown in, points clamped to the
// plot area, the grid with its ticks and axis titles, and a time trace thinned to pixel columns.
#include <string>
#include <vector>

#include "view/painter.h"
#include "view/plot_layout.h"
#include "view/theme.h"

namespace cablefilm {

constexpr double kNewtonsPerKilonewton = 1000.0;  // tensions are shown in kN

// m.ToPixel clamped to the plot area, so a value outside the fixed ranges stays on its plot.
Vec2f PlotPoint(const PlotMapping& m, double x, double y);

// Grid, axis lines, tick labels (about x_target and y_target ticks) and axis titles of a plot
// area; the tick labels and titles sit outside the area (below it and to its left).
void DrawAxes(Painter& p, const PlotMapping& m, const std::string& x_label,
              const std::string& y_label, const Theme& th, int x_target = 8, int y_target = 6);

// A trace of vs / unit against ts with at most two points (the min and max, in time order) per
// pixel column of the plot: the cost of a frame stays bounded however many samples there are.
// Samples left or right of the plot collapse into one column at each side; NaN values are
// skipped. Points are clamped to the plot (PlotPoint).
std::vector<Vec2f> DecimatedTrace(const PlotMapping& m, const std::vector<double>& ts,
                                  const std::vector<double>& vs, double unit = 1);

}  // namespace cablefilm
