// The CPU rasteriser (flat_raster.h) against the GL renderer on the same frames: the two
// compute the same coverage formulas at the same pixel centres, so they may differ only by
// rounding (float evaluation order in llvmpipe's fixed-point blend against ours).
#include "view/flat_raster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/error.h"
#include "encode/png_writer.h"
#include "view/frame_builder.h"
#include "view/painter.h"
#include "view/renderer.h"
#include "test_scene.h"

namespace cablefilm {
namespace {

struct Difference {
  int max = 0;           // largest channel difference [1/255]
  double above_1 = 0;    // share of pixels with a channel more than 1/255 apart
  double mean = 0;       // mean channel difference [1/255]
};

Difference Compare(const Image& a, const Image& b) {
  Difference d;
  long above = 0;
  double sum = 0;
  const long pixels = static_cast<long>(a.width) * a.height;
  for (long i = 0; i < pixels; ++i) {
    int m = 0;
    for (int c = 0; c < 3; ++c) {
      const int e = std::abs(a.rgba[4 * i + c] - b.rgba[4 * i + c]);
      m = std::max(m, e);
      sum += e;
    }
    d.max = std::max(d.max, m);
    if (m > 1) ++above;
  }
  d.above_1 = static_cast<double>(above) / pixels;
  d.mean = sum / (3.0 * pixels);
  return d;
}

Difference DrawBoth(const Frame& frame, const std::string& name) {
  RenderOptions options;
  options.width = frame.width;
  options.height = frame.height;
  Renderer renderer(options);
  const Image gl = renderer.Draw(frame);
  FontAtlas font;
  Image cpu;
  DrawFlatFrame(frame, &font, &cpu);
  EXPECT_EQ(cpu.width, gl.width);
  EXPECT_EQ(cpu.height, gl.height);
  const std::string dir = testing::OutputDir("flat_raster");
  WritePng(dir + "/" + name + "_gl.png", gl);
  WritePng(dir + "/" + name + "_cpu.png", cpu);
  const Difference d = Compare(gl, cpu);
  std::printf("%s: max %d/255, %.4f %% of pixels > 1/255, mean %.4f/255\n", name.c_str(), d.max,
              100 * d.above_1, d.mean);
  return d;
}

// The still a run writes, with two series and a breaking load's dashed line.
TEST(FlatRaster, MaxTensionFigureMatchesTheGlRenderer) {
  std::vector<MaxTensionSeries> series(2);
  for (int i = 0; i <= 600; ++i) {
    const double t = 0.05 * i;
    series[0].t.push_back(t);
    series[0].tension.push_back(4e5 + 2.5e5 * std::sin(0.7 * t) * std::exp(-0.02 * t));
    series[1].t.push_back(t);
    series[1].tension.push_back(3.8e5 + 2e5 * std::sin(0.7 * t + 0.3));
  }
  series[0].label = "elastic";
  series[1].label = "inextensible";
  for (auto& s : series) s.breaking_load = 7e5;
  const Frame frame = MakeMaxTensionFigure("Maximum tension along the cable: test", series, 1600, 900);
  const Difference d = DrawBoth(frame, "max_tension");
  // Same formulas at the same pixel centres: every difference is a rounding of the last bit,
  // so no channel may differ by more than 2/255 and nearly none by more than 1/255.
  EXPECT_LE(d.max, 2);
  EXPECT_LT(d.above_1, 1e-3);
  EXPECT_LT(d.mean, 0.05);
}

// Every shape kind, thin and thick, over a dark ground with light text (gamma 0.8), and a
// vertical label.
TEST(FlatRaster, EveryShapeKindAndTextMatchTheGlRenderer) {
  Frame frame;
  frame.width = 400;
  frame.height = 300;
  frame.background = {0.08f, 0.09f, 0.12f, 1};
  Painter p(&frame, 1);
  p.Rect({10.3f, 12.7f, 120.6f, 80.2f}, {0.9f, 0.3f, 0.2f, 0.8f});
  p.Line({20, 200}, {380, 140.5f}, 3.5f, {0.2f, 0.8f, 0.4f, 1});
  p.Line({20, 220}, {380, 230}, 0.6f, {1, 1, 1, 1});
  p.Disc({200.4f, 60.2f}, 17.3f, {0.3f, 0.5f, 0.95f, 0.7f});
  p.Diamond({300, 60}, 12, {0.95f, 0.85f, 0.2f, 1});
  p.Triangle({40, 280}, {140, 250}, {90, 295}, {0.6f, 0.2f, 0.7f, 0.5f});
  p.Dashed({{150, 100}, {390, 110}, {390, 290}}, 2, {0.8f, 0.8f, 0.8f, 1}, 8, 4);
  p.Text("Tension T [kN] 0.123", {30, 130}, 15, {0.95f, 0.95f, 0.95f, 1});
  p.Text("vertical", {380, 250}, 13, {0.8f, 0.9f, 1, 1}, HAlign::kCenter, VAlign::kMiddle, true);
  p.Text("bold, centred", {200, 280}, 14, {1, 0.8f, 0.6f, 1}, HAlign::kCenter, VAlign::kBottom,
         false, true);
  const Difference d = DrawBoth(frame, "shapes");
  EXPECT_LE(d.max, 2);  // as above
  EXPECT_LT(d.above_1, 1e-3);
  EXPECT_LT(d.mean, 0.05);
}

// Drawn in bands of rows (max_tension.png), the frame is the whole one byte for byte: every
// shape and glyph crossing a band's edge drawn in both bands, each pixel once.
TEST(FlatRaster, BandsOfRowsGiveTheWholeFrame) {
  std::vector<MaxTensionSeries> series(1);
  for (int i = 0; i <= 300; ++i) {
    series[0].t.push_back(0.1 * i);
    series[0].tension.push_back(4e5 + 2.5e5 * std::sin(0.7 * 0.1 * i));
  }
  series[0].label = "elastic";
  const Frame frame = MakeMaxTensionFigure("Maximum tension: bands", series, 640, 360);
  FontAtlas font;
  Image whole;
  DrawFlatFrame(frame, &font, &whole);
  const FlatFrameRaster raster(frame, &font);
  for (const int rows : {1, 7, 64, 360}) {
    Image joined(640, 360);
    for (int y0 = 0; y0 < 360; y0 += rows) {
      Image band(640, std::min(rows, 360 - y0));
      raster.DrawRows(y0, &band);
      std::copy(band.rgba.begin(), band.rgba.end(), joined.row(y0));
    }
    EXPECT_EQ(joined.rgba, whole.rgba) << "bands of " << rows << " rows";
  }
  Image outside(640, 8);
  EXPECT_THROW(raster.DrawRows(356, &outside), Error);
}

TEST(FlatRaster, RefusesA3dScene) {
  Frame frame;
  frame.width = 16;
  frame.height = 16;
  frame.scenes.emplace_back();
  FontAtlas font;
  Image out;
  EXPECT_THROW(DrawFlatFrame(frame, &font, &out), Error);
}

}  // namespace
}  // namespace cablefilm
