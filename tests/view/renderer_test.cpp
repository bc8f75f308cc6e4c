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
#include "view/history.h"
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
    scene_ = testing::StraightScene();
    snap_ = testing::StraightSnapshot(2.0);
    History history(scene_, testing::StraightPolicy());
    history.Add(snap_);
    layout_ = MakeFrameLayout(scene_, history, kW, kH);
    frame_ = MakeFrame(scene_, history, snap_, layout_, map_);
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
  SceneView scene_;
  Snapshot snap_;
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
    const Rgba want = map_.Map(snap_.lines[0].tension[j], 0, kTensionMax);
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
    const Vec2f want = layout_.tension.ToPixel(mid, snap_.lines[0].tension[j] / 1000);
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
  const SceneView scene = MakeDemoScene();
  History history(scene, MakeDemoPolicy(20));
  Snapshot snap;
  for (int i = 0; i <= 150; ++i) {
    snap = MakeDemoSnapshot(scene, i / 10.0);
    history.Add(snap);
  }
  const FrameLayout layout = MakeFrameLayout(scene, history, 320, 180);
  const Frame frame = MakeFrame(scene, history, snap, layout, Colormap("viridis"));
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

// ---- A second line (the compare film's inextensible run) ------------------------------------

// The straight scene with its second line 1.5 m above the first (about 50 px at 960x540, far
// beyond both lines' rims). At the middle of each of its links, away from the weight marker
// and the ends, its coloured line is 2 px wide: the pixel holding the line's centre is within
// 0.5 px of it, so fully covered (coverage = clamp(w/2 + 0.5 - d) = 1) and shows the map at
// its tension, up to the 8-bit rounding of the vertex colour and of the framebuffer (sRGB
// values written as is): 2/255, as for the first line.
TEST(RendererSecondLine, ItsColourIsTheMapAtItsLinkTension) {
  constexpr int kW = 960, kH = 540;
  const SceneView scene = testing::StraightPairScene();
  const Snapshot snap = testing::StraightPairSnapshot(2.0);
  History history(scene, testing::StraightPolicy());
  history.Add(snap);
  const FrameLayout layout = MakeFrameLayout(scene, history, kW, kH);
  ASSERT_GE(layout.overlay_width, 2.0f);
  const Colormap map("viridis");
  RenderOptions options;
  options.width = kW;
  options.height = kH;
  const Image image = Renderer(options).Draw(MakeFrame(scene, history, snap, layout, map));
  WritePng(testing::OutputDir("renderer") + "/straight_two_lines_960x540.png", image);
  const float apart =
      layout.cable.ToPixel(0, 0).y - layout.cable.ToPixel(0, testing::kSecondY).y;
  ASSERT_GT(apart, 10 * layout.cable_width);
  int checked = 0;
  for (int j = 1; j < kLinks - 1; ++j) {
    if (j == 4 || j == 5) continue;  // the second line's weight marker at station 5
    const Vec2f p = layout.cable.ToPixel(j + 0.5, testing::kSecondY);
    const std::uint8_t* px =
        image.at(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)));
    const Rgba want = map.Map(snap.lines[1].tension[j], 0, kTensionMax);
    EXPECT_LE(ColorDistance(px, want), 2) << "second line's link " << j;
    // Not the first line's colour of that link (the tensions run the other way).
    if (std::abs(j - kLinks / 2) > 2) {
      EXPECT_GT(ColorDistance(px, map.Map(snap.lines[0].tension[j], 0, kTensionMax)), 20) << j;
    }
    ++checked;
  }
  EXPECT_EQ(checked, kLinks - 4);
}

// The demo cable with a second line (a lagged, lowered copy with larger tensions: a stand-in
// for the inextensible model) at full size, for looking at: test_output/render/renderer/.
TEST(RendererSecondLine, DemoFrameWithTwoLinesAt1080p) {
  SceneView scene = MakeDemoScene();
  scene.lines[0].label = "elastic";
  scene.lines.push_back(scene.lines[0]);
  scene.lines[1].label = "inextensible";
  for (double& T : scene.lines[1].reference.tension) T *= 1.12;
  FixedPolicy policy = MakeDemoPolicy(20);
  policy.box.y_min -= 2;
  auto both = [&](double t) {
    Snapshot s = MakeDemoSnapshot(scene, t);
    LineSnapshot second = MakeDemoSnapshot(scene, std::max(0.0, t - 0.35)).lines[0];
    for (std::size_t j = 0; j < second.y.size(); ++j) {
      const double u = static_cast<double>(j) / (second.y.size() - 1);
      second.y[j] -= 1.6 * 4 * u * (1 - u);  // sags a little more in the middle, same ends
    }
    for (double& T : second.tension) T *= 1.12;
    s.lines.push_back(second);
    return s;
  };
  History history(scene, policy);
  Snapshot snap;
  for (int i = 0; i <= 126; ++i) {
    snap = both(i / 10.0);
    history.Add(snap);
  }
  const FrameLayout layout = MakeFrameLayout(scene, history, 1920, 1080);
  RenderOptions options;
  const Image image =
      Renderer(options).Draw(MakeFrame(scene, history, snap, layout, Colormap("viridis")));
  ASSERT_EQ(image.width, 1920);
  WritePng(testing::OutputDir("renderer") + "/demo_two_lines_1920x1080.png", image);
}

// ---- Live view -----------------------------------------------------------------------------

// A live frame of the demo cable 95 s into a run (a 60 s window, two control changes), drawn
// at 1280x720 for looking at: test_output/render/renderer/live_1280x720.png. The markers show
// in their colour in their pixel column, and the cable in the map's colour of its tension.
TEST(RendererLive, LiveFrameAt720p) {
  const SceneView scene = MakeDemoScene();
  History history(scene, FollowingPolicy{60, {}});
  const double markers[] = {52.5, 80};
  const char* labels[] = {"speed 2.0x", "current 0.5 m/s"};
  int marked = 0;
  for (int i = 0; i <= 95 * 30; ++i) {
    const double t = i / 30.0;
    if (marked < 2 && t >= markers[marked]) {
      history.AddMarker(markers[marked], labels[marked]);
      ++marked;
    }
    history.Add(MakeDemoSnapshot(scene, t));
  }
  const Snapshot& now = history.now();
  const Colormap map("viridis");
  const FrameLayout layout = MakeFrameLayout(scene, history, 1280, 720);
  EXPECT_DOUBLE_EQ(layout.max_tension.x_lo, 35);
  EXPECT_DOUBLE_EQ(layout.max_tension.x_hi, 95);
  RenderOptions options;
  options.width = 1280;
  options.height = 720;
  const Image image = Renderer(options).Draw(
      MakeFrame(scene, history, now, layout, map, Theme::Dark(), "live \u00b7 1.0x"));
  WritePng(testing::OutputDir("renderer") + "/live_1280x720.png", image);
  const Rgba event = Theme::Dark().event;
  const PixelRect& plot = layout.max_tension.rect;
  for (double t : markers) {  // marker pixels (within anti-aliasing) in the line's column
    const int x = static_cast<int>(std::floor(layout.max_tension.PixelX(t)));
    int near = 0;
    for (int y = static_cast<int>(plot.y0); y < plot.y1; ++y)
      near += ColorDistance(image.at(x, y), event) < 60;
    EXPECT_GT(near, 0.3 * plot.height()) << "marker at " << t << " s";
  }
  const LineSnapshot& line = now.lines[0];
  for (int j : {10, 40, 50}) {  // the cable's centre pixels, away from its markers
    const double xm = 0.5 * (line.x[j] + line.x[j + 1]);
    const double ym = 0.5 * (line.y[j] + line.y[j + 1]);
    const Vec2f p = layout.cable.ToPixel(xm, ym);  // the line is 4 px wide: fully covered
    const Rgba want = map.Map(line.tension[j], history.range_min(), history.range_max());
    EXPECT_LE(ColorDistance(image.at(static_cast<int>(p.x), static_cast<int>(p.y)), want), 2)
        << "link " << j;
  }
}

// Redrawing only what changed (and reading back only that) gives the very pixels of drawing
// each frame whole: a live view of the demo cable, its time window filling (t < 60 s: the
// cable, the newest samples and the clock change), then rolling (t > 60 s: the time plot's
// axis moves too), a frame with nothing changed, and a change of colour map (the cable and the
// colour bar change colour).
TEST(RendererChanges, SamePixelsAsWholeFrames) {
  const SceneView scene = MakeDemoScene();
  History history(scene, FollowingPolicy{60, {}});
  RenderOptions options;
  options.width = 960;
  options.height = 540;
  Renderer whole(options);
  options.redraw_changes = true;
  Renderer changes(options);
  Image a, b;
  struct Step {
    double t;
    const char* map;
    double redrawn_max;  // the share of the frame drawn again, at most
  };
  // The first frame is drawn whole; then a sample more changes the cable, the tension curve,
  // the clock and the time plot's newest segment: a quarter of the frame in 32 px tiles
  // (measured 0.26), under 0.3. The same frame again: nothing. A new colour map: the cable
  // and the colour bar as well (measured 0.27), under 0.3. Past 60 s the time plot's axis
  // rolls with the clock: about half the frame (measured 0.47), under 0.6 (beyond, the whole
  // frame is drawn in one pass).
  const Step steps[] = {{20.0, "viridis", 1},        {20.0 + 1 / 30.0, "viridis", 0.3},
                        {20.0 + 2 / 30.0, "viridis", 0.3}, {20.0 + 2 / 30.0, "viridis", 0},
                        {20.0 + 3 / 30.0, "magma", 0.3},   {70.0, "magma", 1},
                        {70.0 + 1 / 30.0, "magma", 0.6},   {70.0 + 2 / 30.0, "magma", 0.6}};
  // Every digit in the header's regular and bold text first (t = 0.0 s to 0.9 s): a glyph new to
  // the atlas redraws the whole frame (its texture changed), which would hide what this test is
  // about.
  const std::string status = "live \u00b7 1.0x 0123456789";
  std::vector<Step> all;
  for (int k = 0; k < 10; ++k) all.push_back({0.1 * k, "viridis", 1});
  all.insert(all.end(), std::begin(steps), std::end(steps));
  double t_added = -1;
  for (const Step& s : all) {
    for (int i = static_cast<int>(std::floor(t_added * 30)) + 1; i <= std::lround(s.t * 30); ++i)
      history.Add(MakeDemoSnapshot(scene, i / 30.0));
    t_added = s.t;
    const FrameLayout layout = MakeFrameLayout(scene, history, 960, 540);
    const Frame frame = MakeFrame(scene, history, history.now(), layout, Colormap(s.map),
                                  Theme::Dark(), status);
    whole.Draw(frame, &a);
    changes.DrawOnto(frame, &b);  // b: the last frame, only what changed read back into it
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) differ += a.rgba[i] != b.rgba[i];
    EXPECT_EQ(differ, 0u) << "t = " << s.t;
    EXPECT_EQ(whole.redrawn(), 1);
    EXPECT_LE(changes.redrawn(), s.redrawn_max) << "t = " << s.t;
    if (s.redrawn_max == 0) {
      EXPECT_EQ(changes.redrawn(), 0) << "t = " << s.t;
    }
    std::printf("t = %.3f s %s: redrawn %.3f of the frame\n", s.t, s.map, changes.redrawn());
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
  for (const char* name :
       {"shape.vert", "shape.frag", "text.vert", "text.frag", "lit.vert", "lit.frag"}) {
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
