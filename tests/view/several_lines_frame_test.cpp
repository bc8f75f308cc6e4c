// A frame of a system of lines (SceneView::lines_alike): every line drawn in full, alike (not
// as an overlay), its ends marked; a curve per line in each plot, in the line's own colour and
// named in the legend; the lines and points named on the picture.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "encode/png_writer.h"
#include "scene/film_view.h"
#include "scene/scene_loader.h"
#include "scene/scene_parser.h"
#include "view/frame_builder.h"
#include "view/history.h"
#include "view/plot_axes.h"
#include "view/renderer.h"
#include "view/tension_panel.h"
#include "view/time_panel.h"
#include "test_scene.h"

namespace cablefilm {
namespace {

constexpr int kLinks = 20;
constexpr double kMax = 40000;  // the colour range's top [N]
// The lines' tensions: each uniform, far apart on the colour map and in the plots.
constexpr double kTension[2] = {0.3 * kMax, 0.75 * kMax};  // [N]

struct Rgb {
  double r, g, b;  // 0..255
};
Rgb PixelAt(const Image& im, double x, double y) {
  const std::uint8_t* p = im.at(static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
  return {double(p[0]), double(p[1]), double(p[2])};
}
double Luma(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }
// How far a pixel is from `c` seen in some light: the largest channel difference after the best
// brightness scale (the tubes are lit: a surface's colour times 0.34 to 1).
double ShadedDistance(const Rgb& p, const Rgba& c) {
  const double r = 255 * c.r, g = 255 * c.g, b = 255 * c.b;
  const double s = (p.r * r + p.g * g + p.b * b) / std::max(1e-9, r * r + g * g + b * b);
  return std::max({std::fabs(p.r - s * r), std::fabs(p.g - s * g), std::fabs(p.b - s * b)});
}
double Distance(const Rgb& a, const Rgba& c) {
  return std::max({std::fabs(a.r - 255 * c.r), std::fabs(a.g - 255 * c.g),
                   std::fabs(a.b - 255 * c.b)});
}

// Two straight lines of 20 m in space, from anchors at (0, 0, z) to fairleads at (20, 0, z),
// one at z = 0 ("port"), one at z = 12 ("starboard"); points named at both ends of each.
SceneView SystemScene() {
  SceneView scene;
  scene.title = "Two lines";
  scene.space = true;
  scene.lines_alike = true;
  const char* names[2] = {"port", "starboard"};
  for (int i = 0; i < 2; ++i) {
    LineView l;
    l.label = names[i];
    for (int j = 0; j <= kLinks; ++j) {
      l.arc_length.push_back(j);
      l.reference.x.push_back(j);
      l.reference.y.push_back(0);
      l.reference.z.push_back(12.0 * i);
    }
    l.reference.tension.assign(kLinks, kTension[i]);
    l.marks.fixed_ends = {0};
    l.marks.moving_ends = {kLinks};
    scene.lines.push_back(l);
    scene.points.push_back({std::string("anchor_") + names[i], i, 0});
    scene.points.push_back({std::string("fairlead_") + names[i], i, kLinks});
  }
  return scene;
}

Snapshot SystemSnapshot(const SceneView& scene, double t) {
  Snapshot s;
  s.t = t;
  for (int i = 0; i < 2; ++i) {
    LineSnapshot l;
    static_cast<LineState&>(l) = scene.lines[i].reference;
    s.lines.push_back(l);
  }
  return s;
}

class SeveralLinesFrame : public ::testing::Test {
 protected:
  static constexpr int kW = 1920, kH = 1080;  // the design size: the thinnest curve 1.8 px
  void SetUp() override {
    scene_ = SystemScene();
    FixedPolicy policy;
    policy.duration = 10;
    policy.tension_min = 0;
    policy.tension_max = kMax;
    policy.box = {-1, 21, -3, 3, -1, 13};
    history_ = std::make_unique<History>(scene_, policy);
    for (double t : {0.0, 5.0}) {
      snap_ = SystemSnapshot(scene_, t);
      history_->Add(snap_);
    }
    layout_ = MakeFrameLayout(scene_, *history_, kW, kH);
    frame_ = MakeFrame(scene_, *history_, snap_, layout_, map_, th_);
    RenderOptions options;
    options.width = kW;
    options.height = kH;
    Renderer renderer(options);
    image_ = renderer.Draw(frame_);
    WritePng(testing::OutputDir("system") + "/system_frame_1920x1080.png", image_);
  }
  bool HasText(const std::string& s) const {
    return std::any_of(frame_.texts.begin(), frame_.texts.end(),
                       [&](const TextItem& t) { return t.text == s; });
  }
  // Pixels in `r` within 16/255 of colour c (sampled every pixel).
  int Count(const PixelRect& r, const Rgba& c) const {
    int n = 0;
    for (int y = static_cast<int>(r.y0); y < static_cast<int>(r.y1); ++y)
      for (int x = static_cast<int>(r.x0); x < static_cast<int>(r.x1); ++x)
        n += Distance(PixelAt(image_, x, y), c) < 16;
    return n;
  }

  SceneView scene_;
  Snapshot snap_;
  std::unique_ptr<History> history_;
  FrameLayout layout_;
  Colormap map_{"viridis"};
  Theme th_ = Theme::Dark();
  Frame frame_;
  Image image_;
};

TEST_F(SeveralLinesFrame, EachPlotHasACurveALineNamedInItsColour) {
  // The legends: a named entry per line, in the line's colour, the two colours apart.
  const PanelHead tension = TensionPanelHead(scene_, true, "", th_);
  const PanelHead time = TimePanelHead(scene_, true, th_);
  for (const PanelHead* head : {&tension, &time}) {
    ASSERT_FALSE(head->groups.empty());
    const LegendGroup& names = head->groups.front();
    ASSERT_EQ(names.size(), 2u);
    for (int i = 0; i < 2; ++i) {
      EXPECT_EQ(names[i].label, scene_.lines[i].label);
      EXPECT_EQ(Distance({255 * names[i].color.r, 255 * names[i].color.g, 255 * names[i].color.b},
                         LineColor(th_, i)), 0);
    }
  }
  const Rgba c0 = LineColor(th_, 0), c1 = LineColor(th_, 1);
  EXPECT_GT(Distance({255 * c0.r, 255 * c0.g, 255 * c0.b}, c1), 100);
  // The tension along each line: its curve at its tension, in its colour, the whole plot wide
  // (20 m of arc: a few hundred pixels, 2 px thick or more).
  const PlotMapping& tm = layout_.tension;
  for (int i = 0; i < 2; ++i) {
    const Vec2f at = PlotPoint(tm, 10.5, kTension[i] / 1000);
    EXPECT_LT(Distance(PixelAt(image_, at.x, at.y), LineColor(th_, i)), 12) << "line " << i;
    const float half = 0.5f * (tm.rect.y1 - tm.rect.y0);
    EXPECT_GT(Count({tm.rect.x0, at.y - 4, tm.rect.x1, at.y + 4}, LineColor(th_, i)),
              0.6 * (tm.PixelX(kLinks) - tm.PixelX(0)))
        << "line " << i << " (plot " << half << " px high)";
  }
  // The maximum tension against time: each line's trace from t = 0 to 5 s at its tension.
  const PlotMapping& mm = layout_.max_tension;
  for (int i = 0; i < 2; ++i) {
    const Vec2f at = PlotPoint(mm, 2.5, kTension[i] / 1000);
    EXPECT_GT(Count({at.x - 20, at.y - 4, at.x + 20, at.y + 4}, LineColor(th_, i)), 30)
        << "line " << i;
  }
}

TEST_F(SeveralLinesFrame, EveryLineIsDrawnInFullWithItsEndsAndIsNamed) {
  // In the plan (x across, z down): each line at full width in its tension colour (an overlay
  // would be 0.6 of it wide, in a dotted rim), and a fixed point's square at each anchor (an
  // overlay's ends are not marked).
  const PlotMapping& plan = layout_.plan;
  const float w = layout_.cable_width;
  for (int i = 0; i < 2; ++i) {
    const Rgba c = map_.Map(kTension[i], 0, kMax);
    const Vec2f mid = plan.ToPixel(10.5, 12.0 * i);
    int across = 0;  // pixels of the link's colour down a column through the line
    for (int dy = -10; dy <= 10; ++dy)
      across += Distance(PixelAt(image_, mid.x, mid.y + dy), c) < 10;
    EXPECT_GE(across, std::floor(0.75 * w)) << "line " << i << ", " << w << " px wide";
    EXPECT_LE(across, std::ceil(w) + 1) << "line " << i;
    const Vec2f anchor = plan.ToPixel(0, 12.0 * i);
    EXPECT_LT(Distance(PixelAt(image_, anchor.x + 7 * layout_.scale, anchor.y), th_.marker_edge),
              40)
        << "line " << i << "'s anchor";
  }
  // The 3D view: two lit tubes, each hundreds of pixels of its tension colour in some light.
  for (int i = 0; i < 2; ++i) {
    const Rgba c = map_.Map(kTension[i], 0, kMax), other = map_.Map(kTension[1 - i], 0, kMax);
    int n = 0;
    const PixelRect& r = layout_.space_view;
    for (int y = static_cast<int>(r.y0); y < static_cast<int>(r.y1); ++y)
      for (int x = static_cast<int>(r.x0); x < static_cast<int>(r.x1); ++x) {
        const Rgb q = PixelAt(image_, x, y);
        n += Luma(q) > 40 && ShadedDistance(q, c) < 10 && ShadedDistance(q, other) > 30;
      }
    EXPECT_GT(n, 300) << "line " << i << "'s tube";
  }
  // The names: each line's and each point's, on the picture; the headline counts the lines.
  for (const char* name : {"port", "starboard", "anchor_port", "fairlead_port", "anchor_starboard",
                           "fairlead_starboard"})
    EXPECT_TRUE(HasText(name)) << name;
  EXPECT_TRUE(std::any_of(frame_.texts.begin(), frame_.texts.end(), [](const TextItem& t) {
    return t.text.rfind("2 lines", 0) == 0;
  }));
}

// The two fairleads on a body with a box 2 m x 2 m x 16 m about the middle of the fairleads
// (two points give its place at its rest turn, none here): the plan and the elevation draw its
// edges (in the outline's colour, th.text_dim) instead of today's outline, the segment through
// the fairleads at x = 20; the 3D view draws them as tubes.
TEST(SeveralLinesFrameBody, ABoxIsDrawnByItsEdgesInsteadOfTheOutline) {
  constexpr int kW = 1920, kH = 1080;
  const Colormap map("viridis");
  const Theme th = Theme::Dark();
  FixedPolicy policy;
  policy.duration = 10;
  policy.tension_min = 0;
  policy.tension_max = kMax;
  policy.box = {-1, 23, -3, 3, -3, 15};
  auto draw = [&](bool box, FrameLayout* layout) {
    SceneView scene = SystemScene();
    BodyView body;
    body.name = "barge";
    body.points = {1, 3};  // the fairleads, at (20, 0, 0) and (20, 0, 12)
    body.local = {{0, 0, -6}, {0, 0, 6}};
    body.has_box = box;
    body.box = {2, 2, 16};  // x 19 to 21, y -1 to 1, z -2 to 14
    scene.bodies.push_back(body);
    History history(scene, policy);
    const Snapshot snap = SystemSnapshot(scene, 0);
    history.Add(snap);
    *layout = MakeFrameLayout(scene, history, kW, kH);
    RenderOptions options;
    options.width = kW;
    options.height = kH;
    Renderer renderer(options);
    return renderer.Draw(MakeFrame(scene, history, snap, *layout, map, th));
  };
  FrameLayout L, L0;
  const Image image = draw(true, &L), outline = draw(false, &L0);
  WritePng(testing::OutputDir("system") + "/system_frame_box_1920x1080.png", image);
  // Within 2 px of a point (the edge is 2.5 k px wide, anti-aliased): a pixel of the body's
  // colour (within 24/255: its edges are opaque, the panel shows only at their rim).
  auto body_near = [&](const Image& im, const PlotMapping& m, double x, double y) {
    const Vec2f c = m.ToPixel(x, y);
    double best = 1e9;
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx)
        best = std::min(best, Distance(PixelAt(im, c.x + dx, c.y + dy), th.text_dim));
    return best < 24;
  };
  // The plan (x, z): the box's four corners and the middle of its long sides; not the outline.
  for (double x : {19.0, 21.0})
    for (double z : {-2.0, 6.0, 14.0})
      EXPECT_TRUE(body_near(image, L.plan, x, z)) << x << ", " << z;
  EXPECT_FALSE(body_near(image, L.plan, 20.0, 6.0)) << "the outline drawn with a box";
  EXPECT_TRUE(body_near(outline, L0.plan, 20.0, 6.0)) << "no outline without a box";
  EXPECT_FALSE(body_near(outline, L0.plan, 19.0, 6.0)) << "a box drawn without one";
  // The elevation (along the first line's ends, x here; y up): its corners and sides.
  for (double x : {19.0, 21.0})
    for (double y : {-1.0, -0.5, 0.5, 1.0})  // not at 0: the lines cover it there
      EXPECT_TRUE(body_near(image, L.elevation, x, y)) << x << ", " << y;
  EXPECT_TRUE(body_near(image, L.elevation, 20.0, 1.0));
  // The 3D view: more pixels of the body's colour in some light with the box's 12 tubes than
  // with the outline's one.
  auto lit = [&](const Image& im, const FrameLayout& layout) {
    int n = 0;
    const PixelRect& r = layout.space_view;
    for (int y = static_cast<int>(r.y0); y < static_cast<int>(r.y1); ++y)
      for (int x = static_cast<int>(r.x0); x < static_cast<int>(r.x1); ++x) {
        const Rgb q = PixelAt(im, x, y);
        n += Luma(q) > 40 && ShadedDistance(q, th.text_dim) < 6;
      }
    return n;
  };
  EXPECT_GT(lit(image, L), lit(outline, L0) + 200);
}

TEST(SeveralLinesScene, PointsMustBeOnStationsOfTheirLines) {
  SceneView scene = SystemScene();
  scene.points.push_back({"lost", 1, kLinks + 1});
  EXPECT_THROW(CheckSceneView(scene), Error);
  scene.points.back() = {"lost", 2, 0};
  EXPECT_THROW(CheckSceneView(scene), Error);
}

// film.view = "auto": a system is drawn in space when a point leaves the plane z = 0 (its line
// ends are there), in the plane when every point, the current and the waves stay in it.
TEST(SeveralLinesScene, AutoViewFollowsThePoints) {
  const std::string path =
      std::string(CABLEFILM_SOURCE_DIR) + "/tests/scenes/system/clump_system.toml";
  std::string text = ReadSceneFile(path);
  EXPECT_FALSE(SceneIsPlanar(ParseScene(text, path)));  // the clump and fairlead at z 5, 10 m
  auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("current_heading = 34.4", "current_heading = 0.0");
  replace("position = [45.0, -40.0, 5.0]", "position = [45.0, -40.0, 0.0]");
  replace("position = [70.0, 0.0, 10.0]", "position = [70.0, 0.0, 0.0]");
  replace("z_amplitudes = [0.5, -0.4]", "z_amplitudes = [0.0, 0.0]");
  const SceneDef flat = ParseScene(text, path);
  EXPECT_TRUE(SceneIsPlanar(flat));
  EXPECT_FALSE(DrawsInSpace(flat, "auto"));
  // A point off the plane, moved across it or pushed across it is drawn in space.
  std::string off = text;
  off.replace(off.find("position = [45.0, -40.0, 0.0]"), 29, "position = [45.0, -40.0, 5.0]");
  EXPECT_TRUE(DrawsInSpace(ParseScene(off, path), "auto"));
  std::string moved = text;
  moved.replace(moved.find("z_amplitudes = [0.0, 0.0]"), 25, "z_amplitudes = [0.3, 0.0]");
  EXPECT_TRUE(DrawsInSpace(ParseScene(moved, path), "auto"));
  std::string pushed = text;
  pushed.replace(pushed.find("mass = 3000.0"), 13, "mass = 3000.0\nforce = [0.0, 0.0, 50.0]");
  EXPECT_TRUE(DrawsInSpace(ParseScene(pushed, path), "auto"));
  // The fairlead on a driven body (issue 20): turning about z keeps it in the plane, about x
  // or y takes it out.
  std::string on_body = text;
  const std::string fairlead =
      "name = \"fairlead\"\nposition = [70.0, 0.0, 0.0]\nmotion = \"trochoid\"\n"
      "x_amplitudes = [1.5, 0.0]\ny_amplitudes = [0.8, 0.6]\nz_amplitudes = [0.0, 0.0]\n"
      "period = 8.0\nramp_rate = 0.5\n";
  ASSERT_NE(on_body.find(fairlead), std::string::npos);
  on_body.replace(on_body.find(fairlead), fairlead.size(),
                  "name = \"fairlead\"\nbody = \"ship\"\nposition = [2.0, 0.0, 0.0]\n\n"
                  "[[body]]\nname = \"ship\"\nposition = [68.0, 0.0, 0.0]\nmotion = \"trochoid\"\n"
                  "period = 8.0\nramp_rate = 0.5\nrz_amplitudes = [2.0, 0.0]\n");
  EXPECT_TRUE(SceneIsPlanar(ParseScene(on_body, path))) << on_body;
  std::string tilted = on_body;
  tilted.replace(tilted.find("rz_amplitudes"), 13, "rx_amplitudes");
  EXPECT_FALSE(SceneIsPlanar(ParseScene(tilted, path)));
}

}  // namespace
}  // namespace cablefilm
