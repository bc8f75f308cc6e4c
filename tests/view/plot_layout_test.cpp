#include "view/plot_layout.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cablefilm {
namespace {

TEST(NiceNum, RoundsToOneTwoFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(NiceNum(1.2, true), 1);
  EXPECT_DOUBLE_EQ(NiceNum(2.9, true), 2);
  EXPECT_DOUBLE_EQ(NiceNum(3.1, true), 5);
  EXPECT_DOUBLE_EQ(NiceNum(7.5, true), 10);
  EXPECT_DOUBLE_EQ(NiceNum(0.034, true), 0.05);
  EXPECT_DOUBLE_EQ(NiceNum(430, false), 500);   // ceiling variant
  EXPECT_DOUBLE_EQ(NiceNum(1.0, false), 1);
  EXPECT_DOUBLE_EQ(NiceNum(1.01, false), 2);
}

TEST(NiceTicks, KnownRanges) {
  // 0..37.2 kN with about 6 ticks: range 37.2 -> nice 50, step 50/5 = 10 -> 0, 10, 20, 30.
  Ticks t = NiceTicks(0, 37.2, 6);
  EXPECT_DOUBLE_EQ(t.step, 10);
  EXPECT_EQ(t.values, (std::vector<double>{0, 10, 20, 30}));
  EXPECT_EQ(t.decimals, 0);
  // 0..60 s with 8 ticks: nice(60) = 100, 100/7 = 14.3 -> 10: 0, 10, ..., 60.
  t = NiceTicks(0, 60, 8);
  EXPECT_DOUBLE_EQ(t.step, 10);
  EXPECT_EQ(t.values.size(), 7u);
  // A small range needs decimals: 0.12..0.31 -> step 0.05 -> 0.15 .. 0.30.
  t = NiceTicks(0.12, 0.31, 6);
  EXPECT_DOUBLE_EQ(t.step, 0.05);
  ASSERT_EQ(t.values.size(), 4u);
  EXPECT_NEAR(t.values.front(), 0.15, 1e-12);
  EXPECT_NEAR(t.values.back(), 0.30, 1e-12);
  EXPECT_EQ(t.decimals, 2);
  // Negative ranges and a tick exactly at zero.
  t = NiceTicks(-75.3, 155.9, 10);
  EXPECT_DOUBLE_EQ(t.step, 50);  // range 231.2 -> nice 500, 500 / 9 = 55.6 -> 50
  EXPECT_EQ(t.values, (std::vector<double>{-50, 0, 50, 100, 150}));
}

TEST(NiceTicks, EveryTickIsInsideAndAMultipleOfTheStep) {
  for (double lo : {-3.7, 0.0, 1e-3, 12.5, 980.0})
    for (double span : {0.01, 0.7, 3.0, 45.0, 12345.0}) {
      const Ticks t = NiceTicks(lo, lo + span, 6);
      ASSERT_FALSE(t.values.empty()) << lo << " " << span;
      EXPECT_LE(t.values.size(), 12u);
      for (double v : t.values) {
        EXPECT_GE(v, lo - 1e-9 * span);
        EXPECT_LE(v, lo + span + 1e-9 * span);
        EXPECT_NEAR(v / t.step, std::round(v / t.step), 1e-6);
      }
    }
}

TEST(NiceRange, WidensToTickMultiples) {
  double lo = 3.2, hi = 28.7;
  NiceRange(&lo, &hi, 6);  // step 5
  EXPECT_DOUBLE_EQ(lo, 0);
  EXPECT_DOUBLE_EQ(hi, 30);
  lo = 0;
  hi = 30;  // already nice: unchanged
  NiceRange(&lo, &hi, 6);
  EXPECT_DOUBLE_EQ(lo, 0);
  EXPECT_DOUBLE_EQ(hi, 30);
}

TEST(FormatTick, FixedDecimalsNoNegativeZero) {
  EXPECT_EQ(FormatTick(20, 0), "20");
  EXPECT_EQ(FormatTick(0.15, 2), "0.15");
  EXPECT_EQ(FormatTick(-0.0001, 1), "0.0");
  EXPECT_EQ(FormatTick(-2.5, 1), "-2.5");
}

TEST(PlotMapping, MapsCornersAndIsLinear) {
  PlotMapping m;
  m.rect = {100, 50, 500, 250};
  m.x_lo = 0;
  m.x_hi = 40;
  m.y_lo = 10;
  m.y_hi = 30;
  EXPECT_FLOAT_EQ(m.ToPixel(0, 10).x, 100);
  EXPECT_FLOAT_EQ(m.ToPixel(0, 10).y, 250);  // y up: the low end at the bottom
  EXPECT_FLOAT_EQ(m.ToPixel(40, 30).x, 500);
  EXPECT_FLOAT_EQ(m.ToPixel(40, 30).y, 50);
  EXPECT_FLOAT_EQ(m.ToPixel(10, 25).x, 200);
  EXPECT_FLOAT_EQ(m.ToPixel(10, 25).y, 100);
}

}  // namespace
}  // namespace cablefilm
