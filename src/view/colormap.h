#pragma once
// Perceptually uniform colour maps (matplotlib's viridis, cividis, magma, inferno, plasma),
// rebuilt from published sRGB samples at evenly spaced positions, interpolated linearly into a
// 256-entry table: within about 3/255 of the full published tables, exact at the samples.
#include <array>
#include <string>
#include <vector>

#include "view/frame.h"

namespace cablefilm {

class Colormap {
 public:
  // Throws Error naming the known maps when `name` is unknown.
  explicit Colormap(const std::string& name);
  static std::vector<std::string> Names();

  const std::string& name() const { return name_; }
  // Colour at u in [0, 1] (clamped; NaN gives the low end). Nearest of 256 table entries.
  Rgba At(double u) const;
  // Colour of `value` on the fixed range [lo, hi] (clamped).
  Rgba Map(double value, double lo, double hi) const;

 private:
  std::string name_;
  std::array<Rgba, 256> table_;
};

}  // namespace cablefilm
