#include "view/colormap.h"

#include <algorithm>
#include <cstdint>

#include "core/error.h"

namespace cablefilm {
namespace {

struct ControlPoints {
  const char* name;
  int count;                // samples, evenly spaced over [0, 1]
  std::uint32_t rgb[11];    // 0xRRGGBB
};

// Samples of the matplotlib maps (van der Walt & Smith; Nunez et al. for cividis) at evenly
// spaced positions (11, or 6 for cividis whose lightness is close to linear), as published.
constexpr ControlPoints kMaps[] = {
    {"viridis", 11, {0x440154, 0x482475, 0x414487, 0x355F8D, 0x2A788E, 0x21918C, 0x22A884, 0x44BF70,
                 0x7AD151, 0xBDDF26, 0xFDE725}},
    {"cividis", 6, {0x00224E, 0x35456C, 0x666970, 0x948E77, 0xC8B866, 0xFEE838}},
    {"magma", 11, {0x000004, 0x140E36, 0x3B0F70, 0x641A80, 0x8C2981, 0xB73779, 0xDE4968, 0xF7705C,
               0xFE9F6D, 0xFECF92, 0xFCFDBF}},
    {"inferno", 11, {0x000004, 0x160B39, 0x420A68, 0x6A176E, 0x932667, 0xBC3754, 0xDD513A, 0xF37819,
                 0xFCA50A, 0xF6D746, 0xFCFFA4}},
    {"plasma", 11, {0x0D0887, 0x41049D, 0x6A00A8, 0x8F0DA4, 0xB12A90, 0xCC4778, 0xE16462, 0xF2844B,
                0xFCA636, 0xFCCE25, 0xF0F921}},
};

}  // namespace

std::vector<std::string> Colormap::Names() {
  std::vector<std::string> names;
  for (const auto& m : kMaps) names.emplace_back(m.name);
  return names;
}

Colormap::Colormap(const std::string& name) : name_(name) {
  const ControlPoints* map = nullptr;
  for (const auto& m : kMaps)
    if (name == m.name) map = &m;
  if (!map) {
    std::string known;
    for (const auto& n : Names()) known += (known.empty() ? "" : ", ") + n;
    throw Error("unknown colour map '" + name + "' (known: " + known + ")");
  }
  // Piecewise linear in sRGB between the samples: checked against matplotlib's values between
  // samples (tests/view/colormap_test.cpp), it is closer there than CIELAB interpolation.
  const int n = map->count;
  auto channel = [](std::uint32_t rgb, int shift) { return ((rgb >> shift) & 0xff) / 255.0; };
  for (int i = 0; i < 256; ++i) {
    const double u = i / 255.0 * (n - 1);
    const int k = std::min(n - 2, static_cast<int>(u));
    const double f = u - k;
    auto mix = [&](int shift) {
      return static_cast<float>((1 - f) * channel(map->rgb[k], shift) +
                                f * channel(map->rgb[k + 1], shift));
    };
    table_[i] = {mix(16), mix(8), mix(0), 1.0f};
  }
}

Rgba Colormap::At(double u) const {
  if (!(u > 0)) return table_[0];
  if (u >= 1) return table_[255];
  return table_[static_cast<int>(u * 255 + 0.5)];
}

Rgba Colormap::Map(double value, double lo, double hi) const {
  return At(hi > lo ? (value - lo) / (hi - lo) : 0.5);
}

}  // namespace cablefilm
