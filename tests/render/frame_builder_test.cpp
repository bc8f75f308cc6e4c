#include "render/frame_builder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "render/demo_cable.h"
#include "test_scene.h"

namespace cablefilm {
namespace {

using testing::kLinks;
using testing::kTensionMax;

bool SameColor(const Rgba& a, const Rgba& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

TEST(FrameLayout, CableIsToScaleAndPanelsInsideTheFrame) {
  const FilmSpec spec = testing::StraightSpec();
  for (auto [w, h] : {std::pair{1920, 1080}, std::pair{1280, 720}, std::pair{320, 180}}) {
    const FrameLayout L = MakeFrameLayout(spec, w, h);
    const PlotMapping& c = L.cable;
    const double ppm_x = c.rect.width() / (c.x_hi - c.x_lo);
    const double ppm_y = c.rect.height() / (c.y_hi - c.y_lo);
    EXPECT_NEAR(ppm_x, ppm_y, 1e-6 * ppm_x) << "equal x and y scale at " << w << "x" << h;
    // The whole world box is visible.
    EXPECT_LE(c.x_lo, spec.x_min);
    EXPECT_GE(c.x_hi, spec.x_max);
    EXPECT_LE(c.y_lo, spec.y_min);
    EXPECT_GE(c.y_hi, spec.y_max);
    for (const PixelRect& r : {L.cable_panel, L.tension_panel, L.max_panel}) {
      EXPECT_GE(r.x0, 0);
      EXPECT_GE(r.y0, 0);
      EXPECT_LE(r.x1, w);
      EXPECT_LE(r.y1, h);
    }
    // The tension axis is the fixed range widened to nice ticks: [0, 40] kN stays [0, 40].
    EXPECT_DOUBLE_EQ(L.tension.y_lo, 0);
    EXPECT_DOUBLE_EQ(L.tension.y_hi, 40);
    EXPECT_DOUBLE_EQ(L.max_tension.x_hi, spec.duration);
  }
}

TEST(MakeFrame, CableSegmentsCarryTheirLinkTensionColour) {
  const FilmSpec spec = testing::StraightSpec();
  const CableSnapshot snap = testing::StraightSnapshot(1.0);
  FilmHistory history(spec);
  history.Add(snap);
  const FrameLayout L = MakeFrameLayout(spec, 1280, 720);
  const Colormap map("viridis");
  const Frame frame = MakeFrame(spec, history, snap, L, map);
  EXPECT_EQ(frame.width, 1280);
  EXPECT_EQ(frame.height, 720);
  int found = 0;
  for (int j = 0; j < kLinks; ++j) {
    const Vec2f a = L.cable.ToPixel(j, 0), b = L.cable.ToPixel(j + 1, 0);
    const Rgba want = map.Map(snap.tension[j], 0, kTensionMax);
    for (const Shape& s : frame.shapes)
      if (s.kind == ShapeKind::kSegment && s.a.x == a.x && s.a.y == a.y && s.b.x == b.x &&
          s.b.y == b.y && SameColor(s.color, want) && s.size == L.cable_width) {
        ++found;
        break;
      }
  }
  EXPECT_EQ(found, kLinks);
}

TEST(MakeFrame, ColourBarSpansTheMapBottomToTop) {
  const FilmSpec spec = testing::StraightSpec();
  FilmHistory history(spec);
  const FrameLayout L = MakeFrameLayout(spec, 1280, 720);
  const Colormap map("cividis");
  const Frame frame = MakeFrame(spec, history, testing::StraightSnapshot(0), L, map);
  // The bands inside the colour bar: the lowest is the map's low end, the highest its top.
  const Shape* lowest = nullptr;
  const Shape* highest = nullptr;
  for (const Shape& s : frame.shapes)
    if (s.kind == ShapeKind::kRect && s.a.x == L.colorbar.x0 && s.b.x == L.colorbar.x1) {
      if (!lowest || s.b.y > lowest->b.y) lowest = &s;
      if (!highest || s.a.y < highest->a.y) highest = &s;
    }
  ASSERT_TRUE(lowest && highest);
  // Bands are 1/128 of the range: their centres are 1/256 from the ends, one table entry.
  EXPECT_TRUE(SameColor(lowest->color, map.At(0.5 / 128)));
  EXPECT_TRUE(SameColor(highest->color, map.At(1 - 0.5 / 128)));
  EXPECT_NEAR(lowest->b.y, L.colorbar.y1, 1.0);
  EXPECT_NEAR(highest->a.y, L.colorbar.y0, 1.0);
}

TEST(MakeFrame, TensionLabelsAreNiceKilonewtons) {
  const FilmSpec spec = testing::StraightSpec();
  FilmHistory history(spec);
  const FrameLayout L = MakeFrameLayout(spec, 1920, 1080);
  const Frame frame = MakeFrame(spec, history, testing::StraightSnapshot(2.5), L, Colormap("viridis"));
  std::vector<std::string> texts;
  for (const TextItem& t : frame.texts) texts.push_back(t.text);
  auto has = [&](const std::string& s) { return std::find(texts.begin(), texts.end(), s) != texts.end(); };
  // 0..40 kN with about 6 ticks: step 10 (40 -> nice 50, 50 / 5 = 10).
  for (const char* tick : {"0", "10", "20", "30", "40"}) EXPECT_TRUE(has(tick)) << tick;
  EXPECT_TRUE(has("t = 2.50 s"));
  EXPECT_TRUE(has("Straight test cable"));
  EXPECT_TRUE(has("tension [kN]"));
  EXPECT_TRUE(has("time [s]"));
}

TEST(FilmHistory, EnvelopeTraceAndEndPath) {
  const FilmSpec spec = testing::StraightSpec();
  FilmHistory history(spec);
  CableSnapshot a = testing::StraightSnapshot(0), b = testing::StraightSnapshot(0.1);
  for (double& T : b.tension) T *= 0.5;
  b.tension[3] = 1e6;
  b.x[kLinks] += 1;  // the moving end moved 1 m
  history.Add(a);
  history.Add(b);
  EXPECT_EQ(history.count(), 2);
  EXPECT_DOUBLE_EQ(history.link_min()[0], 0.5 * a.tension[0]);
  EXPECT_DOUBLE_EQ(history.link_max()[0], a.tension[0]);
  EXPECT_DOUBLE_EQ(history.link_max()[3], 1e6);
  EXPECT_EQ(history.max_tension(), (std::vector<double>{a.tension.back(), 1e6}));
  EXPECT_EQ(history.times(), (std::vector<double>{0, 0.1}));
  ASSERT_EQ(history.end_paths().size(), 1u);
  ASSERT_EQ(history.end_paths()[0].size(), 1u);  // one segment from the first to the second
  EXPECT_FLOAT_EQ(history.end_paths()[0][0].a.x, kLinks);
  EXPECT_FLOAT_EQ(history.end_paths()[0][0].b.x, kLinks + 1);
  // A snapshot of the wrong size is an error naming the sizes.
  CableSnapshot bad = a;
  bad.tension.pop_back();
  EXPECT_THROW(history.Add(bad), Error);
}

TEST(MakeFrame, LongFilmsStayBoundedPerFrame) {
  // A ten-minute film at 30 fps: the max-tension trace is decimated to pixel columns.
  const FilmSpec spec = MakeDemoSpec(600);
  FilmHistory history(spec);
  CableSnapshot s;
  for (int i = 0; i < 600 * 30; ++i) {
    s = MakeDemoSnapshot(spec, i / 30.0);
    history.Add(s);
  }
  const FrameLayout L = MakeFrameLayout(spec, 1920, 1080);
  const Frame frame = MakeFrame(spec, history, s, L, Colormap("viridis"));
  EXPECT_LT(frame.shapes.size(), 6000u);
  // The end circles with a 10 s period: after the ramp its path retraces the same grid cells,
  // so it stops growing (one lap is ~400 cells of 1/1000 of the box).
  EXPECT_LT(history.end_paths()[0].size(), 3000u);
}

TEST(MakeFrame, ValuesOutsideTheRangeStayOnTheirPlot) {
  const FilmSpec spec = testing::StraightSpec();
  FilmHistory history(spec);
  CableSnapshot s = testing::StraightSnapshot(1);
  s.tension[0] = 10 * kTensionMax;
  history.Add(s);
  const FrameLayout L = MakeFrameLayout(spec, 960, 540);
  const Frame frame = MakeFrame(spec, history, s, L, Colormap("viridis"));
  const Theme th = Theme::Dark();
  for (const Shape& sh : frame.shapes) {
    // The data curves: the current tension and the max-tension trace.
    if (sh.kind != ShapeKind::kSegment || !(SameColor(sh.color, th.current) || SameColor(sh.color, th.accent)))
      continue;
    for (const PixelRect& r : {L.tension.rect, L.max_tension.rect})
      if (r.Contains(sh.a)) {
        EXPECT_TRUE(r.Contains(sh.b)) << "segment leaves the plot";
      }
  }
}

TEST(MakeMaxTensionFigure, SeriesAndLegend) {
  MaxTensionSeries elastic{"elastic", {0, 1, 2}, {1000, 3000, 2000}};
  MaxTensionSeries inext{"inextensible", {0, 1, 2}, {1200, 3500, 2100}};
  const Frame f = MakeMaxTensionFigure("Figure 1", {elastic, inext}, 800, 450);
  int labels = 0;
  for (const TextItem& t : f.texts) labels += t.text == "elastic" || t.text == "inextensible";
  EXPECT_EQ(labels, 2);
  MaxTensionSeries bad{"bad", {0, 1}, {1}};
  EXPECT_THROW(MakeMaxTensionFigure("x", {bad}, 800, 450), Error);
}

}  // namespace
}  // namespace cablefilm
