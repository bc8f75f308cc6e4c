#pragma once
// Axis arithmetic for the plots: "nice" tick values (Heckbert's NiceNum, as ImPlot does),
// their labels, and the linear map from data to pixels of a plot area.
#include <string>
#include <vector>

#include "view/frame.h"

namespace cablefilm {

// The nice number (1, 2, 5 times a power of ten; with round = false also 10) closest to x
// (round = true) or not less than x (round = false). x > 0.
double NiceNum(double x, bool round);

struct Ticks {
  std::vector<double> values;  // multiples of step inside [lo, hi]
  double step = 0;
  int decimals = 0;            // digits after the point that tell the ticks apart
};
// About `target` ticks covering [lo, hi]; values lie in [lo, hi] (to a relative 1e-9).
Ticks NiceTicks(double lo, double hi, int target = 6);
// [lo, hi] widened outwards to multiples of the nice step for about `target` ticks.
void NiceRange(double* lo, double* hi, int target = 6);
// Fixed-point label with `decimals` digits; never "-0".
std::string FormatTick(double value, int decimals);

struct PixelRect {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // top left, bottom right [px]
  float width() const { return x1 - x0; }
  float height() const { return y1 - y0; }
  bool Contains(Vec2f p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
};

// A plot area showing data [x_lo, x_hi] x [y_lo, y_hi] in `rect`, y up.
struct PlotMapping {
  PixelRect rect;
  double x_lo = 0, x_hi = 1, y_lo = 0, y_hi = 1;
  Vec2f ToPixel(double x, double y) const;
  float PixelX(double x) const;
  float PixelY(double y) const;
};

}  // namespace cablefilm
