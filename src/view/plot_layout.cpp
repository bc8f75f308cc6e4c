#include "view/plot_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cablefilm {

double NiceNum(double x, bool round) {
  const double exponent = std::floor(std::log10(x));
  const double fraction = x / std::pow(10.0, exponent);  // in [1, 10)
  double nice;
  if (round)
    nice = fraction < 1.5 ? 1 : fraction < 3 ? 2 : fraction < 7 ? 5 : 10;
  else
    nice = fraction <= 1 ? 1 : fraction <= 2 ? 2 : fraction <= 5 ? 5 : 10;
  return nice * std::pow(10.0, exponent);
}

namespace {
double NiceStep(double lo, double hi, int target) {
  if (!(hi > lo)) hi = lo + (lo != 0 ? std::fabs(lo) * 0.1 : 1);
  const double range = NiceNum(hi - lo, false);
  return NiceNum(range / std::max(1, target - 1), true);
}
}  // namespace

Ticks NiceTicks(double lo, double hi, int target) {
  Ticks ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  if (hi < lo) std::swap(lo, hi);
  ticks.step = NiceStep(lo, hi, target);
  ticks.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(ticks.step) + 1e-9)));
  const double eps = 1e-9 * std::max(std::fabs(lo), std::fabs(hi)) + 1e-12 * ticks.step;
  const double first = std::ceil((lo - eps) / ticks.step);
  for (double k = first;; k += 1) {
    double v = k * ticks.step;
    if (v > hi + eps) break;
    if (std::fabs(v) < ticks.step * 1e-9) v = 0;
    ticks.values.push_back(v);
    if (ticks.values.size() > 1000) break;  // guards against a degenerate step
  }
  return ticks;
}

void NiceRange(double* lo, double* hi, int target) {
  if (!std::isfinite(*lo) || !std::isfinite(*hi)) return;
  const double step = NiceStep(*lo, *hi, target);
  const double new_lo = std::floor(*lo / step + 1e-9) * step;
  const double new_hi = std::ceil(*hi / step - 1e-9) * step;
  *lo = new_lo;
  *hi = new_hi > new_lo ? new_hi : new_lo + step;
}

std::string FormatTick(double value, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  std::string s = buf;
  // "-0", "-0.0": a rounded zero carries no sign.
  bool zero = true;
  for (char c : s)
    if (c >= '1' && c <= '9') zero = false;
  if (zero && !s.empty() && s[0] == '-') s.erase(0, 1);
  return s;
}

float PlotMapping::PixelX(double x) const {
  return static_cast<float>(rect.x0 + (x - x_lo) / (x_hi - x_lo) * rect.width());
}
float PlotMapping::PixelY(double y) const {
  return static_cast<float>(rect.y1 - (y - y_lo) / (y_hi - y_lo) * rect.height());
}
Vec2f PlotMapping::ToPixel(double x, double y) const { return {PixelX(x), PixelY(y)}; }

}  // namespace cablefilm
