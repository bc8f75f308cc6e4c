#include "view/colormap.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"

namespace cablefilm {
namespace {

// Compares with an sRGB hex colour; `tol` in 1/255 units.
void ExpectColor(const Rgba& c, std::uint32_t hex, double tol, const std::string& what) {
  EXPECT_NEAR(c.r * 255, (hex >> 16) & 0xff, tol) << what;
  EXPECT_NEAR(c.g * 255, (hex >> 8) & 0xff, tol) << what;
  EXPECT_NEAR(c.b * 255, hex & 0xff, tol) << what;
}

// Matplotlib's own tables: viridis at 0, 0.25, 0.5, 0.75, 1 is #440154, #3B528B, #21918C,
// #5DC863, #FDE725 (the 5-colour viridis palette). 0.25 and 0.75 fall between the samples the
// map is built from, so they test the CIELAB interpolation: 3/255 allows the rounding of the
// published hex values (1/255) and the table's 1/256 quantisation of u (about 1/255 of colour
// change per step here).
TEST(Colormap, ViridisMatchesMatplotlib) {
  const Colormap viridis("viridis");
  ExpectColor(viridis.At(0.0), 0x440154, 0.51, "u = 0");
  ExpectColor(viridis.At(0.25), 0x3B528B, 3, "u = 0.25");
  ExpectColor(viridis.At(0.5), 0x21918C, 1.5, "u = 0.5");
  ExpectColor(viridis.At(0.75), 0x5DC863, 3, "u = 0.75");
  ExpectColor(viridis.At(1.0), 0xFDE725, 0.51, "u = 1");
}

TEST(Colormap, OtherMapsEndpoints) {
  ExpectColor(Colormap("cividis").At(0), 0x00224E, 0.51, "cividis 0");
  ExpectColor(Colormap("cividis").At(1), 0xFEE838, 0.51, "cividis 1");
  ExpectColor(Colormap("magma").At(0), 0x000004, 0.51, "magma 0");
  ExpectColor(Colormap("magma").At(1), 0xFCFDBF, 0.51, "magma 1");
}

// Perceptually ordered: the relative luminance of viridis, cividis, magma rises monotonically.
TEST(Colormap, LuminanceIncreases) {
  for (const char* name : {"viridis", "cividis", "magma", "inferno"}) {
    const Colormap map(name);
    auto lum = [](Rgba c) {
      auto lin = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
      return 0.2126 * lin(c.r) + 0.7152 * lin(c.g) + 0.0722 * lin(c.b);
    };
    double prev = -1;
    for (int i = 0; i <= 32; ++i) {
      const double l = lum(map.At(i / 32.0));
      EXPECT_GT(l, prev) << name << " at " << i / 32.0;
      prev = l;
    }
  }
}

TEST(Colormap, MapClampsToTheFixedRange) {
  const Colormap map("viridis");
  ExpectColor(map.Map(-5, 0, 10), 0x440154, 0.51, "below");
  ExpectColor(map.Map(50, 0, 10), 0xFDE725, 0.51, "above");
  ExpectColor(map.Map(5, 0, 10), 0x21918C, 1.5, "middle");
  ExpectColor(map.At(std::nan("")), 0x440154, 0.51, "NaN");
}

TEST(Colormap, UnknownNameListsTheKnownOnes) {
  try {
    Colormap("jet");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("viridis"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("jet"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cablefilm
