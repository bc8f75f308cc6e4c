#include "view/renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "encode/png_writer.h"
#include "view/demo_cable.h"
#include "view/frame_builder.h"
#include "view/live_frame.h"
#include "view/shader_program.h"
#include "test_scene.h"

namespace cablefilm {
namespace {

using testing::kLinks;
using testing::kTensionMax;

// Largest channel difference between a pixel and an sRGB colour, in 1/255 units.
int ColorDistance(const std::uint8_t* p, const Rgba& c) {
  auto q = [](float v) { return static_cast<int>(std::lround(v * 255)); };
  return std::max({std::abs(p[0] - q(c.r)), std::abs(p[1] - q(c.g)), std::abs(p[2] - q(c.b))});
}

class RendererTest : public ::testing::Test {
 protected:
  static constexpr int kW = 960, kH = 540;
  void SetUp() override {
    spec_ = testing::StraightSpec();
    snap_ = testing::StraightSnapshot(2.0);
    FilmHistory history(spec_);
    history.Add(snap_);
    layout_ = MakeFrameLayout(spec_, kW, kH);
    frame_ = MakeFrame(spec_, history, snap_, layout_, map_);
    RenderOptions options;
    options.width = kW;
    options.height = kH;
    Renderer renderer(options);
    image_ = renderer.Draw(frame_);
    WritePng(testing::OutputDir("renderer") + "/straight_960x540.png", image_);
  }
  const std::uint8_t* Pixel(float x, float y) const {
    return image_.at(static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
  }
  FilmSpec spec_;
  CableSnapshot snap_;
  FrameLayout layout_;
  Colormap map_{"viridis"};
  Frame frame_;
  Image image_;
};

TEST_F(RendererTest, ImageHasTheFrameSizeAndBackground) {
  ASSERT_EQ(image_.width, kW);
  ASSERT_EQ(image_.height, kH);
  ASSERT_EQ(image_.rgba.size(), static_cast<std::size_t>(kW) * kH * 4);
  // The corners are background (outside every panel); exact up to 8-bit rounding (1/255).
  for (auto [x, y] : {std::pair{1, kH - 2}, std::pair{kW - 2, kH - 2}, std::pair{1, 1}}) {
    EXPECT_LE(ColorDistance(image_.at(x, y), frame_.background), 1) << x << "," << y;
    EXPECT_EQ(image_.at(x, y)[3], 255);
  }
}

// At the middle of each link (away from the markers) the line is 3 px wide and its centre pixel
// fully covered, so its colour is the map's at the link's tension, up to the 8-bit rounding of
// the vertex colour and of the framebuffer: 2/255.
TEST_F(RendererTest, CableColourIsTheMapAtTheLinkTension) {
  for (int j = 0; j < kLinks; ++j) {
    if (j == 4 || j == 5 || j == 0 || j == kLinks - 1) continue;  // weight, anchor, moving end
    const Vec2f p = layout_.cable.ToPixel(j + 0.5, 0);
    const Rgba want = map_.Map(snap_.tension[j], 0, kTensionMax);
    EXPECT_LE(ColorDistance(Pixel(p.x, p.y), want), 2) << "link " << j;
  }
}

// The colour bar's bottom and top are the map's ends. A band is 1/128 of the bar (under 2 px
// here) and the probe, 1.5 px inside the bar's frame, may fall in the first or second band: so
// the pixel must match, within 8-bit rounding (2/255), the map somewhere in its first (last)
// 2/128, i.e. table entries 0..4 (251..255).
TEST_F(RendererTest, ColourBarEnds) {
  const PixelRect& cb = layout_.colorbar;
  const float x = 0.5f * (cb.x0 + cb.x1);
  auto nearest = [&](const std::uint8_t* p, int first, int last) {
    int best = 255;
    for (int i = first; i <= last; ++i) best = std::min(best, ColorDistance(p, map_.At(i / 255.0)));
    return best;
  };
  EXPECT_LE(nearest(Pixel(x, cb.y1 - 1.5f), 0, 4), 2);
  EXPECT_LE(nearest(Pixel(x, cb.y0 + 1.5f), 251, 255), 2);
  // And the two ends are far apart (the bar is not one colour).
  EXPECT_GT(ColorDistance(Pixel(x, cb.y1 - 1.5f), map_.At(1)), 100);
}

// The current tension curve (drawn in the theme's 'current' colour) crosses the column of a
// link's midpoint at the height of that link's tension: within 1 px (the line is 1.3 px wide,
// the centre of its pixel run is within half a pixel of the true line, plus sub-pixel slope).
TEST_F(RendererTest, TensionCurveAtTheRightHeight) {
  const Rgba current = Theme::Dark().current;
  for (int j : {2, 7, 13, 17}) {
    const double mid = j + 0.5;
    const Vec2f want = layout_.tension.ToPixel(mid, snap_.tension[j] / 1000);
    const int x = static_cast<int>(std::floor(want.x));
    double sum = 0, weight = 0;
    for (int y = static_cast<int>(layout_.tension.rect.y0); y < layout_.tension.rect.y1; ++y) {
      const int d = ColorDistance(image_.at(x, y), current);
      if (d < 40) {
        sum += (y + 0.5) * (40 - d);
        weight += 40 - d;
      }
    }
    ASSERT_GT(weight, 0) << "no curve in column " << x;
    EXPECT_NEAR(sum / weight, want.y, 1.0) << "link " << j;
  }
}

TEST_F(RendererTest, TextIsDrawn) {
  // The title's row holds light text pixels on the dark background.
  int bright = 0;
  const int y0 = static_cast<int>(44 * layout_.scale) - 8, y1 = static_cast<int>(44 * layout_.scale);
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < kW / 3; ++x) bright += image_.at(x, y)[0] > 180;
  EXPECT_GT(bright, 50);
}

// A golden image of a tiny scene. llvmpipe (and FreeType) versions rasterise edges slightly
// differently, so a pixel may differ by up to 48/255 in a channel and up to 1 % of the pixels
// may differ by more; a real change (a moved curve, a missing label, another colour) changes
// far more. Set CABLEFILM_UPDATE_GOLDEN=1 to rewrite the golden file.
TEST(RendererGolden, TinyDemoFrame) {
  const FilmSpec spec = MakeDemoSpec(20);
  FilmHistory history(spec);
  CableSnapshot snap;
  for (int i = 0; i <= 150; ++i) {
    snap = MakeDemoSnapshot(spec, i / 10.0);
    history.Add(snap);
  }
  const FrameLayout layout = MakeFrameLayout(spec, 320, 180);
  const Frame frame = MakeFrame(spec, history, snap, layout, Colormap("viridis"));
  RenderOptions options;
  options.width = 320;
  options.height = 180;
  const Image actual = Renderer(options).Draw(frame);
  const std::string golden = std::string(CABLEFILM_SOURCE_DIR) + "/tests/view/golden/demo_320x180.png";
  if (const char* update = std::getenv("CABLEFILM_UPDATE_GOLDEN"); update && *update == '1') {
    std::filesystem::create_directories(std::filesystem::path(golden).parent_path());
    WritePng(golden, actual, PngOptions{9, false});
  }
  const Image expected = ReadPng(golden);
  ASSERT_EQ(expected.width, actual.width);
  ASSERT_EQ(expected.height, actual.height);
  long differing = 0;
  for (int y = 0; y < actual.height; ++y)
    for (int x = 0; x < actual.width; ++x) {
      const std::uint8_t* a = actual.at(x, y);
      const std::uint8_t* e = expected.at(x, y);
      const int d = std::max({std::abs(a[0] - e[0]), std::abs(a[1] - e[1]), std::abs(a[2] - e[2])});
      differing += d > 48;
    }
  const double fraction = static_cast<double>(differing) / (actual.width * actual.height);
  if (fraction > 0.01) {
    const std::string out = testing::OutputDir("golden") + "/demo_320x180_actual.png";
    WritePng(out, actual);
    ADD_FAILURE() << fraction * 100 << " % of pixels differ from " << golden
                  << "; the actual image is " << out;
  }
}

// ---- Companion cable ------------------------------------------------------------------------

// The straight scene with its companion 1.5 m above the main cable (about 50 px at 960x540,
// far beyond both cables' rims). At the middle of each companion link, away from the weight
// marker and the ends, the companion's coloured line is 2 px wide: the pixel holding the line's
// centre is within 0.5 px of it, so fully covered (coverage = clamp(w/2 + 0.5 - d) = 1) and
// shows the map at the companion's tension, up to the 8-bit rounding of the vertex colour and
// of the framebuffer (sRGB values written as is): 2/255, as for the main cable.
TEST(RendererCompanion, CompanionColourIsTheMapAtItsLinkTension) {
  constexpr int kW = 960, kH = 540;
  const FilmSpec spec = testing::StraightCompanionSpec();
  const CableSnapshot snap = testing::StraightCompanionSnapshot(2.0);
  FilmHistory history(spec);
  history.Add(snap);
  const FrameLayout layout = MakeFrameLayout(spec, kW, kH);
  ASSERT_GE(layout.overlay_width, 2.0f);
  const Colormap map("viridis");
  RenderOptions options;
  options.width = kW;
  options.height = kH;
  const Image image = Renderer(options).Draw(MakeFrame(spec, history, snap, layout, map));
  WritePng(testing::OutputDir("renderer") + "/straight_companion_960x540.png", image);
  const float apart = layout.cable.ToPixel(0, 0).y - layout.cable.ToPixel(0, testing::kCompanionY).y;
  ASSERT_GT(apart, 10 * layout.cable_width);
  int checked = 0;
  for (int j = 1; j < kLinks - 1; ++j) {
    if (j == 4 || j == 5) continue;  // the companion's weight marker at station 5
    const Vec2f p = layout.cable.ToPixel(j + 0.5, testing::kCompanionY);
    const std::uint8_t* px =
        image.at(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)));
    const Rgba want = map.Map(snap.ctension[j], 0, kTensionMax);
    EXPECT_LE(ColorDistance(px, want), 2) << "companion link " << j;
    // Not the main cable's colour of that link (the tensions run the other way).
    if (std::abs(j - kLinks / 2) > 2) {
      EXPECT_GT(ColorDistance(px, map.Map(snap.tension[j], 0, kTensionMax)), 20) << j;
    }
    ++checked;
  }
  EXPECT_EQ(checked, kLinks - 4);
}

// The demo cable with a companion (a lagged, lowered copy with larger tensions: a stand-in for
// the inextensible model) at full size, for looking at: test_output/render/renderer/.
TEST(RendererCompanion, DemoFrameWithCompanionAt1080p) {
  FilmSpec spec = MakeDemoSpec(20);
  spec.label = "elastic";
  spec.companion_label = "inextensible";
  spec.y_min -= 2;
  auto companion = [&](double t) {
    CableSnapshot s = MakeDemoSnapshot(spec, t);
    const CableSnapshot c = MakeDemoSnapshot(spec, std::max(0.0, t - 0.35));
    s.cx = c.x;
    s.cy = c.y;
    s.ctension = c.tension;
    for (std::size_t j = 0; j < s.cy.size(); ++j) {
      const double u = static_cast<double>(j) / (s.cy.size() - 1);
      s.cy[j] -= 1.6 * 4 * u * (1 - u);  // sags a little more in the middle, same ends
    }
    for (double& T : s.ctension) T *= 1.12;
    return s;
  };
  spec.companion_equilibrium = MakeDemoSnapshot(spec, 0);
  for (double& T : spec.companion_equilibrium.tension) T *= 1.12;
  FilmHistory history(spec);
  CableSnapshot snap;
  for (int i = 0; i <= 126; ++i) {
    snap = companion(i / 10.0);
    history.Add(snap);
  }
  const FrameLayout layout = MakeFrameLayout(spec, 1920, 1080);
  RenderOptions options;
  const Image image =
      Renderer(options).Draw(MakeFrame(spec, history, snap, layout, Colormap("viridis")));
  ASSERT_EQ(image.width, 1920);
  WritePng(testing::OutputDir("renderer") + "/demo_companion_1920x1080.png", image);
}

// ---- Live view -----------------------------------------------------------------------------

// A live frame of the demo cable 95 s into a run (a 60 s window, two control changes), drawn
// at 1280x720 for looking at: test_output/render/renderer/live_1280x720.png. The markers show
// in their colour in their pixel column, and the cable in the map's colour of its tension.
TEST(RendererLive, LiveFrameAt720p) {
  const FilmSpec spec = MakeDemoSpec(600);
  LiveFrameInput in;
  in.title = spec.title;
  in.status = "live \u00b7 1.0x";
  in.arc_length = spec.arc_length;
  in.section_boundaries = spec.section_boundaries;
  in.section_names = spec.section_names;
  in.weight_stations = spec.weight_stations;
  in.moving_ends = spec.moving_ends;
  in.fixed_ends = spec.fixed_ends;
  in.equilibrium = spec.equilibrium;
  in.tension_max = spec.tension_max;
  in.x_min = spec.x_min;
  in.x_max = spec.x_max;
  in.y_min = spec.y_min;
  in.y_max = spec.y_max;
  in.window_start = 35;
  in.window_end = 95;
  in.link_min.assign(spec.arc_length.size() - 1, INFINITY);
  in.link_max.assign(spec.arc_length.size() - 1, -INFINITY);
  std::vector<Vec2f> path;
  for (int i = 0; i <= 95 * 30; ++i) {
    in.snapshot = MakeDemoSnapshot(spec, i / 30.0);
    const auto& T = in.snapshot.tension;
    const auto peak = std::max_element(T.begin(), T.end());
    for (std::size_t j = 0; j < T.size(); ++j) {
      in.link_min[j] = std::min(in.link_min[j], T[j]);
      in.link_max[j] = std::max(in.link_max[j], T[j]);
    }
    if (*peak > in.peak) {
      in.peak = *peak;
      in.peak_t = in.snapshot.t;
      in.peak_link = static_cast<int>(peak - T.begin());
    }
    if (in.snapshot.t >= in.window_start) {
      in.times.push_back(in.snapshot.t);
      in.max_tension.push_back(*peak);
    }
    if (in.snapshot.t >= 85)
      path.push_back({static_cast<float>(in.snapshot.x.back()), static_cast<float>(in.snapshot.y.back())});
  }
  in.end_paths = {path};
  in.markers = {{52.5, "speed 2.0x"}, {80, "current 0.5 m/s"}};
  const Colormap map("viridis");
  const FrameLayout layout = MakeLiveFrameLayout(in, 1280, 720);
  RenderOptions options;
  options.width = 1280;
  options.height = 720;
  const Image image = Renderer(options).Draw(MakeLiveFrame(in, 1280, 720, map));
  WritePng(testing::OutputDir("renderer") + "/live_1280x720.png", image);
  const Rgba event = Theme::Dark().event;
  const PixelRect& plot = layout.max_tension.rect;
  for (double t : {52.5, 80.0}) {  // marker pixels (within anti-aliasing) in the line's column
    const int x = static_cast<int>(std::floor(layout.max_tension.PixelX(t)));
    int near = 0;
    for (int y = static_cast<int>(plot.y0); y < plot.y1; ++y) near += ColorDistance(image.at(x, y), event) < 60;
    EXPECT_GT(near, 0.3 * plot.height()) << "marker at " << t << " s";
  }
  for (int j : {10, 40, 50}) {  // the cable's centre pixels, away from its markers
    const double xm = 0.5 * (in.snapshot.x[j] + in.snapshot.x[j + 1]);
    const double ym = 0.5 * (in.snapshot.y[j] + in.snapshot.y[j + 1]);
    const Vec2f p = layout.cable.ToPixel(xm, ym);  // the line is 4 px wide: fully covered
    const Rgba want = map.Map(in.snapshot.tension[j], in.tension_min, in.tension_max);
    EXPECT_LE(ColorDistance(image.at(static_cast<int>(p.x), static_cast<int>(p.y)), want), 2)
        << "link " << j;
  }
}

TEST(ShaderProgram, DirectoryFromOptionThenEnvironmentThenBuiltIn) {
  EXPECT_EQ(ResolveShaderDir("/some/dir"), "/some/dir");
  ::setenv("CABLEFILM_SHADERS", "/from/env", 1);
  EXPECT_EQ(ResolveShaderDir(""), "/from/env");
  ::unsetenv("CABLEFILM_SHADERS");
  EXPECT_EQ(ResolveShaderDir(""), "");  // the shaders built into the program
}

// Issue 12: the program carries shaders/ as it was at build time, byte for byte.
TEST(ShaderProgram, BuiltInShadersAreTheSourceFiles) {
  for (const char* name : {"shape.vert", "shape.frag", "text.vert", "text.frag"}) {
    std::ifstream in(std::string(CABLEFILM_SOURCE_DIR) + "/shaders/" + name, std::ios::binary);
    std::ostringstream source;
    source << in.rdbuf();
    std::string built_in;
    ASSERT_TRUE(FindEmbeddedShader(name, &built_in)) << name;
    EXPECT_EQ(built_in, source.str()) << name;
  }
  std::string none;
  EXPECT_FALSE(FindEmbeddedShader("missing.vert", &none));
}

TEST(ShaderProgram, MissingShaderIsAnErrorNamingThePath) {
  RenderOptions options;
  options.width = 32;
  options.height = 32;
  options.shader_dir = "/nonexistent_cablefilm_shaders";
  try {
    Renderer renderer(options);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent_cablefilm_shaders/shape.vert"),
              std::string::npos)
        << e.what();
  }
}

TEST(ShaderProgram, CompileErrorCarriesTheCompilerLog) {
  const std::string dir = testing::OutputDir("broken_shaders");
  for (const char* name : {"shape.vert", "shape.frag", "text.vert", "text.frag"})
    std::filesystem::copy_file(std::string(CABLEFILM_SOURCE_DIR) + "/shaders/" + name,
                               dir + "/" + name,
                               std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir + "/shape.frag") << "#version 330 core\nout vec4 c;\nvoid main() { c = undefined_thing; }\n";
  RenderOptions options;
  options.width = 32;
  options.height = 32;
  options.shader_dir = dir;
  try {
    Renderer renderer(options);
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("shape.frag does not compile"), std::string::npos) << what;
    EXPECT_NE(what.find("undefined_thing"), std::string::npos) << what;  // the log itself
  }
}

}  // namespace
}  // namespace cablefilm
