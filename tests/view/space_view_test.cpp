// Issue 19, "the picture": a line in space is drawn as a lit tube coloured by tension, in a
// perspective view beside its plan and elevation; a scene in the plane keeps the 2D picture
// unless film.view says "3d".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "encode/png_writer.h"
#include "scene/film_view.h"
#include "scene/scene_loader.h"
#include "scene/scene_parser.h"
#include "view/camera.h"
#include "view/frame_builder.h"
#include "view/history.h"
#include "view/plane_views.h"
#include "view/renderer.h"
#include "test_scene.h"

namespace cablefilm {
namespace {

using testing::kLinks;
using testing::kTensionMax;

struct Rgb {
  double r, g, b;  // 0..255
};
Rgb PixelAt(const Image& im, double x, double y) {
  const std::uint8_t* p = im.at(static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
  return {double(p[0]), double(p[1]), double(p[2])};
}
double Luma(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }
double Distance(const Rgb& a, const Rgb& b) {
  return std::max({std::fabs(a.r - b.r), std::fabs(a.g - b.g), std::fabs(a.b - b.b)});
}
// How far a pixel is from `c` seen in some light: the largest channel difference after the best
// brightness scale s (the shading multiplies a surface's colour by s, 0.34 to 1 in lit.frag).
double ShadedDistance(const Rgb& p, const Rgba& c) {
  const double r = 255 * c.r, g = 255 * c.g, b = 255 * c.b;
  const double s = (p.r * r + p.g * g + p.b * b) / std::max(1e-9, r * r + g * g + b * b);
  return Distance(p, {s * r, s * g, s * b});
}

// The straight test cable turned out of the plane: from (0, 0, 0) to (20, 0, 10), sagging
// 3 m in the middle, tensions rising along it over the whole colour range.
SceneView SpaceScene() {
  SceneView scene = testing::StraightScene();
  LineState& r = scene.lines[0].reference;
  r.z.clear();
  for (int j = 0; j <= kLinks; ++j) {
    const double u = double(j) / kLinks;
    r.x[j] = 20 * u;
    r.y[j] = -12 * u * (1 - u);
    r.z.push_back(10 * u);
  }
  scene.space = true;
  return scene;
}
Snapshot SpaceSnapshot(const SceneView& scene) {
  Snapshot s = testing::StraightSnapshot(2.0);
  LineSnapshot& l = s.lines[0];
  const LineState& r = scene.lines[0].reference;
  l.x = r.x;
  l.y = r.y;
  l.z = r.z;
  return s;
}
FixedPolicy SpacePolicy() {
  FixedPolicy p = testing::StraightPolicy();
  p.box = {-1, 21, -4, 1, -1, 11};
  return p;
}

// ---- (1) the tube is lit ---------------------------------------------------------------------

// A grey tube seen broadside, lit from straight above: across its width the shading runs from
// the full colour on top to the ambient third underneath.
TEST(SpaceRenderer, TubeIsShadedAcrossItsWidth) {
  constexpr int kW = 480, kH = 240;
  Frame frame;
  frame.width = kW;
  frame.height = kH;
  frame.background = Rgba{0.05f, 0.05f, 0.05f, 1};
  Scene3 s;
  s.background = frame.background;
  s.light = {0, 1, 0};
  Tube tube;
  for (int i = 0; i <= 20; ++i) tube.points.push_back({float(i), 0, 0});
  tube.colors = {Rgba{0.6f, 0.6f, 0.6f, 1}};
  tube.radius = 1;
  s.tubes.push_back(tube);
  OrbitCamera camera;
  camera.azimuth = 90;  // from +z: the tube runs across the view
  camera.elevation = 0;
  const WorldBox box{0, 20, -1, 1, -1, 1};
  const ViewProjection v = MakeViewProjection(camera, box, box, PixelRect{0, 0, kW, kH});
  v.Fill(&s);
  frame.scenes.push_back(s);
  RenderOptions options;
  options.width = kW;
  options.height = kH;
  Renderer renderer(options);
  const Image image = renderer.Draw(frame);
  WritePng(testing::OutputDir("space") + "/lit_tube.png", image);

  // The column through the tube's middle: the rows it covers (brighter than the background by
  // more than anti-aliasing leaves at its edges) and their brightness.
  Vec2f top, bottom;
  ASSERT_TRUE(v.ToPixel(Vec(10, 1, 0), &top));
  ASSERT_TRUE(v.ToPixel(Vec(10, -1, 0), &bottom));
  double lo = 255, hi = 0;
  int rows = 0;
  for (int y = static_cast<int>(top.y) + 2; y < static_cast<int>(bottom.y) - 1; ++y) {
    const double l = Luma(PixelAt(image, kW / 2.0, y));
    lo = std::min(lo, l);
    hi = std::max(hi, l);
    ++rows;
  }
  ASSERT_GE(rows, 10) << "the tube is " << bottom.y - top.y << " px wide";
  // Lit from above, seen from the side (lit.frag): the rows sampled run from the top, which
  // faces the light and carries the highlight (0.6 x 255 = 153 and more), to the underside,
  // turned 70 degrees or more away from it (0.34 + 0.66 cos 70 = 0.57 of 153: ~87, less lower
  // down). An unlit (flat) tube would be one brightness; 40 levels is well under the ~66 of
  // the diffuse light alone.
  EXPECT_GT(hi - lo, 40) << "brightness " << lo << " to " << hi;
  EXPECT_LT(lo, 0.8 * 153);  // a side in shade: darker than the colour as given
  EXPECT_GT(hi, 153);        // the top: the colour as given, and the specular highlight
}

// ---- (2), (3) a frame of a line in space -----------------------------------------------------

class SpaceFrameTest : public ::testing::Test {
 protected:
  static constexpr int kW = 1280, kH = 720;
  void SetUp() override {
    scene_ = SpaceScene();
    snap_ = SpaceSnapshot(scene_);
    history_ = std::make_unique<History>(scene_, SpacePolicy());
    history_->Add(snap_);
    layout_ = MakeFrameLayout(scene_, *history_, kW, kH);
    frame_ = MakeFrame(scene_, *history_, snap_, layout_, map_);
    RenderOptions options;
    options.width = kW;
    options.height = kH;
    Renderer renderer(options);
    image_ = renderer.Draw(frame_);
    WritePng(testing::OutputDir("space") + "/space_frame_1280x720.png", image_);
  }
  // The projection the frame's perspective view was drawn with (its default camera).
  ViewProjection Perspective() const {
    return MakeViewProjection(DefaultCamera(scene_), history_->view_box(), history_->view_box(),
                              layout_.space_view);
  }
  Vec Station(int j) const {
    const LineState& r = scene_.lines[0].reference;
    return Vec(r.x[j], r.y[j], r.z[j]);
  }
  // Link j's colour on the map.
  Rgba LinkColor(int j) const { return map_.Map(snap_.lines[0].tension[j], 0, kTensionMax); }
  // The pixel within `radius` px of p nearest to `c` in some light (ShadedDistance).
  Rgb NearestShaded(Vec2f p, const Rgba& c, int radius) const {
    Rgb best = PixelAt(image_, p.x, p.y);
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx) {
        const Rgb q = PixelAt(image_, p.x + dx, p.y + dy);
        if (ShadedDistance(q, c) < ShadedDistance(best, c)) best = q;
      }
    return best;
  }
  // Pixels in `r` unlike the panel's own colour (sampled at its top left corner).
  int Drawn(const PixelRect& r, Rgb panel) const {
    int n = 0;
    for (int y = static_cast<int>(r.y0); y < static_cast<int>(r.y1); y += 2)
      for (int x = static_cast<int>(r.x0); x < static_cast<int>(r.x1); x += 2)
        n += Distance(PixelAt(image_, x, y), panel) > 24;
    return n;
  }

  SceneView scene_;
  Snapshot snap_;
  std::unique_ptr<History> history_;
  FrameLayout layout_;
  Colormap map_{"viridis"};
  Frame frame_;
  Image image_;
};

// (3) The 3D layout: the perspective view at the left of the top row, the plan over the
// elevation at its right, the two plots below, each with something drawn in it.
TEST_F(SpaceFrameTest, HasThePerspectivePlanAndElevationPanels) {
  const FrameLayout& L = layout_;
  ASSERT_TRUE(L.space);
  ASSERT_EQ(frame_.scenes.size(), 1u);
  EXPECT_LT(L.space_panel.x1, L.plan_panel.x0);
  EXPECT_LT(L.plan_panel.y1, L.elevation_panel.y0);
  EXPECT_NEAR(L.plan_panel.x0, L.elevation_panel.x0, 0.5);
  EXPECT_LT(L.space_panel.y1, L.tension_panel.y0);
  EXPECT_LT(L.elevation_panel.y1, L.max_panel.y0);
  // The plan and the elevation are to one scale (their lengths compare).
  EXPECT_NEAR(L.plan.rect.width() / (L.plan.x_hi - L.plan.x_lo),
              L.elevation.rect.width() / (L.elevation.x_hi - L.elevation.x_lo), 1e-3);
  // Something is drawn in each: the tube (~450 px long, ~10 px across: ~1100 of the samples
  // taken every 2 px) against the 3D view's own background, and the lines, markers and ticks
  // of the plan, the elevation and the plot against the panels' colour (a few hundred samples).
  const Rgb sea = PixelAt(image_, L.space_view.x1 - 3, L.space_view.y0 + 3);
  EXPECT_GT(Drawn(L.space_view, sea), 400);
  const Rgb panel = PixelAt(image_, L.plan_panel.x0 + 2, L.plan_panel.y0 + 2);
  EXPECT_GT(Drawn(L.plan.rect, panel), 100);
  EXPECT_GT(Drawn(L.elevation.rect, panel), 100);
  EXPECT_GT(Drawn(L.tension.rect, panel), 100);
}

// (2) The tube, and the plan's and elevation's lines, are coloured link by link: the low-tension
// end shows the bottom of the map, the high-tension end its top, in all three views.
TEST_F(SpaceFrameTest, TubeIsColouredByTension) {
  const ViewProjection v = Perspective();
  const int low = 2, high = kLinks - 3;  // away from the ends' markers
  auto mid = [&](int j) -> Vec { return 0.5 * (Station(j) + Station(j + 1)); };
  Vec2f p_low, p_high;
  ASSERT_TRUE(v.ToPixel(mid(low), &p_low));
  ASSERT_TRUE(v.ToPixel(mid(high), &p_high));
  ASSERT_TRUE(layout_.space_view.Contains(p_low) && layout_.space_view.Contains(p_high));
  // Within 3 px of the axis (the tube is ~10 px across), some pixel shows the link's colour in
  // the light that falls on it, to 14/255: 8-bit colour, the normals interpolated around a ring
  // of 10 sides, the specular highlight (white, added) kept to a narrow band.
  const Rgb at_low = NearestShaded(p_low, LinkColor(low), 3);
  const Rgb at_high = NearestShaded(p_high, LinkColor(high), 3);
  EXPECT_LT(ShadedDistance(at_low, LinkColor(low)), 14);
  EXPECT_LT(ShadedDistance(at_high, LinkColor(high)), 14);
  // And that pixel is not the other end's colour in any light: viridis' ends differ in hue, not
  // only in brightness (purple against yellow-green: over 100/255 apart after the best scale).
  EXPECT_GT(ShadedDistance(at_low, LinkColor(high)), 60);
  EXPECT_GT(ShadedDistance(at_high, LinkColor(low)), 60);

  // The plan (x across, z down) and the elevation (along the plane, y up): flat lines, the
  // colour as given, to the anti-aliasing of a 6 px line's middle (4/255).
  const ElevationPlane e = MakeElevationPlane(scene_);
  for (int j : {low, high}) {
    const Vec m = mid(j);
    const Vec2f plan = layout_.plan.ToPixel(m.x(), m.z());
    const Vec2f elev = layout_.elevation.ToPixel(e.Along(m.x(), m.z()), m.y());
    const Rgba c = LinkColor(j);
    const Rgb want{255.0 * c.r, 255.0 * c.g, 255.0 * c.b};
    EXPECT_LT(Distance(PixelAt(image_, plan.x, plan.y), want), 8) << "plan, link " << j;
    EXPECT_LT(Distance(PixelAt(image_, elev.x, elev.y), want), 8) << "elevation, link " << j;
  }
}

// ---- (4) which picture -----------------------------------------------------------------------

SceneDef Scene(const std::string& name) {
  return LoadScene(std::string(CABLEFILM_SOURCE_DIR) + "/scenes/" + name);
}

TEST(FilmView, PlaneSceneKeepsThe2DPictureUnlessTold) {
  SceneDef p63 = Scene("polachek1963.toml");
  EXPECT_EQ(p63.film.view, "auto");
  EXPECT_TRUE(SceneIsPlanar(p63));
  EXPECT_FALSE(DrawsInSpace(p63, p63.film.view));
  EXPECT_FALSE(DrawsInSpace(p63, "2d"));
  EXPECT_TRUE(DrawsInSpace(p63, "3d"));
  // The 2D layout for a scene view in the plane, the 3D one for the same view in space.
  SceneView scene = testing::StraightScene();
  History history(scene, testing::StraightPolicy());
  history.Add(testing::StraightSnapshot(1.0));
  EXPECT_FALSE(MakeFrameLayout(scene, history, 960, 540).space);
  scene.space = true;
  History space(scene, testing::StraightPolicy());
  space.Add(testing::StraightSnapshot(1.0));
  EXPECT_TRUE(MakeFrameLayout(scene, space, 960, 540).space);
}

TEST(FilmView, SceneOutOfThePlaneIsDrawnInSpace) {
  const SceneDef leg = Scene("mooring_leg_3d.toml");
  EXPECT_FALSE(SceneIsPlanar(leg));
  EXPECT_TRUE(DrawsInSpace(leg, "auto"));
  EXPECT_FALSE(DrawsInSpace(leg, "2d"));
  // Each way out of the plane alone is enough.
  SceneDef p63 = Scene("polachek1963.toml");
  SceneDef s = p63;
  s.points[1].motion.position[2] = 1;
  EXPECT_TRUE(DrawsInSpace(s, "auto"));
  s = p63;
  s.points[1].motion.z_amplitudes[1] = 0.5;
  EXPECT_TRUE(DrawsInSpace(s, "auto"));
}

TEST(FilmView, TheSceneKeySaysWhichAndABadValueIsRefusedByName) {
  const std::string base =
      "[[material]]\nname = \"w\"\ndiameter = 0.02\narea = 3e-4\nmass_per_length = 1.7\n"
      "youngs_modulus = 1e11\n[cable]\n[[cable.section]]\nmaterial = \"w\"\nlength = 100.0\n"
      "segments = 10\n[ends.start]\nposition = [0.0, 0.0]\n[ends.end]\nposition = [60.0, 60.0]\n";
  const SceneDef forced = ParseScene(base + "[film]\nview = \"3d\"\n", "forced.toml");
  EXPECT_EQ(forced.film.view, "3d");
  EXPECT_TRUE(DrawsInSpace(forced, forced.film.view));
  try {
    ParseScene(base + "[film]\nview = \"4d\"\n", "bad.toml");
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    for (const char* part : {"bad.toml", "view", "\"auto\"", "\"2d\"", "\"3d\"", "4d"})
      EXPECT_NE(what.find(part), std::string::npos) << part << " not in: " << what;
  }
  EXPECT_THROW(DrawsInSpace(forced, "4d"), Error);
}

}  // namespace
}  // namespace cablefilm
