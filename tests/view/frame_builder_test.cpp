#include "view/frame_builder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/error.h"
#include "view/demo_cable.h"
#include "test_scene.h"

namespace cablefilm {
namespace {

using testing::kLinks;
using testing::kTensionMax;

bool SameColor(const Rgba& a, const Rgba& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

TEST(FrameLayout, CableIsToScaleAndPanelsInsideTheFrame) {
  const SceneView scene = testing::StraightScene();
  const FixedPolicy policy = testing::StraightPolicy();
  const WorldBox& box = policy.box;
  const History history(scene, policy);
  for (auto [w, h] : {std::pair{1920, 1080}, std::pair{1280, 720}, std::pair{320, 180}}) {
    const FrameLayout L = MakeFrameLayout(scene, history, w, h);
    const PlotMapping& c = L.cable;
    const double ppm_x = c.rect.width() / (c.x_hi - c.x_lo);
    const double ppm_y = c.rect.height() / (c.y_hi - c.y_lo);
    EXPECT_NEAR(ppm_x, ppm_y, 1e-6 * ppm_x) << "equal x and y scale at " << w << "x" << h;
    // The whole world box is visible.
    EXPECT_LE(c.x_lo, box.x_min);
    EXPECT_GE(c.x_hi, box.x_max);
    EXPECT_LE(c.y_lo, box.y_min);
    EXPECT_GE(c.y_hi, box.y_max);
    for (const PixelRect& r : {L.cable_panel, L.tension_panel, L.max_panel}) {
      EXPECT_GE(r.x0, 0);
      EXPECT_GE(r.y0, 0);
      EXPECT_LE(r.x1, w);
      EXPECT_LE(r.y1, h);
    }
    // The tension axis is the fixed range widened to nice ticks: [0, 40] kN stays [0, 40].
    EXPECT_DOUBLE_EQ(L.tension.y_lo, 0);
    EXPECT_DOUBLE_EQ(L.tension.y_hi, 40);
    EXPECT_DOUBLE_EQ(L.max_tension.x_hi, policy.duration);
  }
}

TEST(MakeFrame, CableSegmentsCarryTheirLinkTensionColour) {
  const SceneView scene = testing::StraightScene();
  const Snapshot snap = testing::StraightSnapshot(1.0);
  History history(scene, testing::StraightPolicy());
  history.Add(snap);
  const FrameLayout L = MakeFrameLayout(scene, history, 1280, 720);
  const Colormap map("viridis");
  const Frame frame = MakeFrame(scene, history, snap, L, map);
  EXPECT_EQ(frame.width, 1280);
  EXPECT_EQ(frame.height, 720);
  int found = 0;
  for (int j = 0; j < kLinks; ++j) {
    const Vec2f a = L.cable.ToPixel(j, 0), b = L.cable.ToPixel(j + 1, 0);
    const Rgba want = map.Map(snap.lines[0].tension[j], 0, kTensionMax);
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
  const SceneView scene = testing::StraightScene();
  History history(scene, testing::StraightPolicy());
  const FrameLayout L = MakeFrameLayout(scene, history, 1280, 720);
  const Colormap map("cividis");
  const Frame frame = MakeFrame(scene, history, testing::StraightSnapshot(0), L, map);
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
  const SceneView scene = testing::StraightScene();
  History history(scene, testing::StraightPolicy());
  const FrameLayout L = MakeFrameLayout(scene, history, 1920, 1080);
  const Frame frame =
      MakeFrame(scene, history, testing::StraightSnapshot(2.5), L, Colormap("viridis"));
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

// Segments of the end paths: a point fewer than the points of each piece.
std::size_t Segments(const EndPath& path) {
  std::size_t n = 0;
  for (const auto& piece : path.pieces) n += piece.size() - 1;
  return n;
}

TEST(FilmHistory, EnvelopeTraceAndEndPath) {
  const SceneView scene = testing::StraightScene();
  History history(scene, testing::StraightPolicy());
  Snapshot a = testing::StraightSnapshot(0), b = testing::StraightSnapshot(0.1);
  LineSnapshot& lb = b.lines[0];
  for (double& T : lb.tension) T *= 0.5;
  lb.tension[3] = 1e6;
  lb.x[kLinks] += 1;  // the moving end moved 1 m
  history.Add(a);
  history.Add(b);
  const LineSnapshot& la = a.lines[0];
  EXPECT_EQ(history.count(), 2);
  EXPECT_DOUBLE_EQ(history.link_min()[0], 0.5 * la.tension[0]);
  EXPECT_DOUBLE_EQ(history.link_max()[0], la.tension[0]);
  EXPECT_DOUBLE_EQ(history.link_max()[3], 1e6);
  ASSERT_EQ(history.max_tension().size(), 1u);  // one line
  EXPECT_EQ(history.max_tension()[0], (std::vector<double>{la.tension.back(), 1e6}));
  EXPECT_EQ(history.times(), (std::vector<double>{0, 0.1}));
  ASSERT_EQ(history.end_paths().size(), 1u);
  const EndPath& path = history.end_paths()[0];
  EXPECT_EQ(path.line, 0);
  EXPECT_EQ(path.station, kLinks);
  ASSERT_EQ(path.pieces.size(), 1u);  // one segment from the first to the second
  ASSERT_EQ(path.pieces[0].size(), 2u);
  EXPECT_FLOAT_EQ(path.pieces[0][0].x, kLinks);
  EXPECT_FLOAT_EQ(path.pieces[0][1].x, kLinks + 1);
  // A snapshot of the wrong size is an error naming the sizes.
  Snapshot bad = a;
  bad.lines[0].tension.pop_back();
  EXPECT_THROW(history.Add(bad), Error);
}

TEST(MakeFrame, LongFilmsStayBoundedPerFrame) {
  // A ten-minute film at 30 fps: the max-tension trace is decimated to pixel columns.
  const SceneView scene = MakeDemoScene();
  History history(scene, MakeDemoPolicy(600));
  Snapshot s;
  for (int i = 0; i < 600 * 30; ++i) {
    s = MakeDemoSnapshot(scene, i / 30.0);
    history.Add(s);
  }
  const FrameLayout L = MakeFrameLayout(scene, history, 1920, 1080);
  const Frame frame = MakeFrame(scene, history, s, L, Colormap("viridis"));
  EXPECT_LT(frame.shapes.size(), 6000u);
  // The end circles with a 10 s period: after the ramp its path retraces the same grid cells,
  // so it stops growing (one lap is ~400 cells of 1/1000 of the box).
  EXPECT_LT(Segments(history.end_paths()[0]), 3000u);
}

TEST(MakeFrame, ValuesOutsideTheRangeStayOnTheirPlot) {
  const SceneView scene = testing::StraightScene();
  History history(scene, testing::StraightPolicy());
  Snapshot s = testing::StraightSnapshot(1);
  s.lines[0].tension[0] = 10 * kTensionMax;
  history.Add(s);
  const FrameLayout L = MakeFrameLayout(scene, history, 960, 540);
  const Frame frame = MakeFrame(scene, history, s, L, Colormap("viridis"));
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

TEST(MakeFrame, SectionNamesCentredInTheirSpans) {
  SceneView scene = testing::StraightScene();
  scene.lines[0].section_names = {"chain", "rope"};
  History history(scene, testing::StraightPolicy());
  const FrameLayout L = MakeFrameLayout(scene, history, 1280, 720);
  const Frame frame =
      MakeFrame(scene, history, testing::StraightSnapshot(1), L, Colormap("viridis"));
  const PlotMapping& tm = L.tension;
  int found = 0;
  for (const TextItem& t : frame.texts) {
    if (t.text != "chain" && t.text != "rope") continue;
    ++found;
    const double mid = t.text == "chain" ? 5 : 15;  // [m], spans [0, 10] and [10, 20]
    EXPECT_FLOAT_EQ(t.pos.x, (tm.PixelX(mid - 5) + tm.PixelX(mid + 5)) / 2) << t.text;
    EXPECT_TRUE(tm.rect.Contains(t.pos)) << t.text;
    EXPECT_LT(t.pos.y, tm.rect.y0 + 0.1f * tm.rect.height()) << "near the top";
  }
  EXPECT_EQ(found, 2);
  // One name per section or none: another count is an error naming both.
  scene.lines[0].section_names = {"chain"};
  try {
    MakeFrameLayout(scene, history, 1280, 720);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("1 section names for 2 sections"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(History(scene, testing::StraightPolicy()), Error);
  // The demo cable names its two sections.
  EXPECT_EQ(MakeDemoScene().lines[0].section_names, (std::vector<std::string>{"wire", "nylon"}));
}

// The demo (P63-like) cable's box is about 1.7 times as wide as high: its panel takes the width
// that shape needs at the top left, the tension along the cable the rest of the top row, and
// the time plot the whole bottom row. The cable is then as large as in the stacked layout
// (the top row's height limits both) and no width is left empty around it.
TEST(FrameLayout, CablePanelFitsTheCable) {
  const SceneView scene = MakeDemoScene();
  const FixedPolicy policy = MakeDemoPolicy(60);
  const WorldBox& box = policy.box;
  const History history(scene, policy);
  for (auto [w, h] : {std::pair{1920, 1080}, std::pair{1280, 720}, std::pair{640, 360}}) {
    const FrameLayout L = MakeFrameLayout(scene, history, w, h);
    EXPECT_TRUE(L.side_by_side) << w << "x" << h;
    EXPECT_LT(L.cable_panel.x1, L.tension_panel.x0);
    EXPECT_LT(L.cable_panel.y1, L.max_panel.y0);
    EXPECT_FLOAT_EQ(L.max_panel.width(), w - 2 * L.cable_panel.x0);  // margin to margin
    // Equal scale; the padded box (4 % of its larger side around it) fills the axes' height
    // and at least 90 % of their width.
    const PlotMapping& c = L.cable;
    const double ppm = c.rect.height() / (c.y_hi - c.y_lo);
    EXPECT_NEAR(c.rect.width() / (c.x_hi - c.x_lo), ppm, 1e-4 * ppm);
    const double pad = 0.04 * (box.x_max - box.x_min);
    EXPECT_NEAR(c.y_hi - c.y_lo, box.y_max - box.y_min + 2 * pad, 1e-3);
    EXPECT_GT((box.x_max - box.x_min + 2 * pad) * ppm, 0.9 * c.rect.width());
  }
  // The straight test cable (20 m x 4 m) is too flat for that: it spans the top row.
  const SceneView straight = testing::StraightScene();
  const FrameLayout flat =
      MakeFrameLayout(straight, History(straight, testing::StraightPolicy()), 1280, 720);
  EXPECT_FALSE(flat.side_by_side);
  EXPECT_FLOAT_EQ(flat.cable_panel.x1, flat.max_panel.x1);
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


// A material's minimum breaking load on the tension plots (issue 21 item 5): a labelled dashed
// line when it lies within (or a quarter of the traces' span beyond) the plotted range, else
// named in a note with the peak's utilisation, the axis not stretched to it.
const TextItem* FindText(const Frame& f, const std::string& start) {
  for (const TextItem& t : f.texts)
    if (t.text.rfind(start, 0) == 0) return &t;
  return nullptr;
}

TEST(MakeMaxTensionFigure, BreakingLoadNearThePeakIsALabelledLine) {
  // Peak 3 kN, span 2 kN: an MBL of 3.4 kN is within a quarter of the span above it.
  MaxTensionSeries s{"elastic", {0, 1, 2}, {1000, 3000, 2000}, 3400.0};
  const Frame f = MakeMaxTensionFigure("Figure 1", {s}, 800, 450);
  // 3000 / 3400 = 88.24 %: three digits.
  const TextItem* label = FindText(f, "MBL 3.4 kN, peak utilisation 88.2 %");
  ASSERT_NE(label, nullptr);
  // Left in the plot, above the dashed line: inside the plot area (between the title and the
  // time axis), and the axis reaches the MBL (a tick at 3.5 kN or above).
  EXPECT_GT(label->pos.y, 80 * 0.5f);
  EXPECT_LT(label->pos.y, 450 - 80 * 0.5f);
  bool reaches = false;
  for (const TextItem& t : f.texts) {
    char* end = nullptr;
    const double v = std::strtod(t.text.c_str(), &end);
    if (end != t.text.c_str() && *end == '\0' && v >= 3.4) reaches = true;
  }
  EXPECT_TRUE(reaches);
  // Different breaking loads (a material per series): none drawn.
  MaxTensionSeries other = s;
  other.breaking_load = 5000;
  EXPECT_EQ(FindText(MakeMaxTensionFigure("Figure 1", {s, other}, 800, 450), "MBL"), nullptr);
}

TEST(MakeMaxTensionFigure, FarBreakingLoadIsANoteAndTheAxisStays) {
  MaxTensionSeries s{"elastic", {0, 1, 2}, {1000, 3000, 2000}, 100e3};
  const Frame f = MakeMaxTensionFigure("Figure 1", {s}, 800, 450);
  const TextItem* note = FindText(f, "MBL 100 kN, peak utilisation 3 %");  // 3 kN of 100
  ASSERT_NE(note, nullptr);
  EXPECT_EQ(note->halign, HAlign::kRight);
  for (const TextItem& t : f.texts) {  // no tick near 100 kN: the axis ends near the peak
    char* end = nullptr;
    const double v = std::strtod(t.text.c_str(), &end);
    if (end != t.text.c_str() && *end == '\0') {
      EXPECT_LT(v, 10.0) << t.text;
    }
  }
}

TEST(MakeFrame, TimePlotShowsTheBreakingLoad) {
  // The straight scene's largest link tension is (kLinks - 0.5) / kLinks of kTensionMax, the
  // time plot's axis 0 to kTensionMax.
  const double peak = (testing::kLinks - 0.5) / testing::kLinks * testing::kTensionMax;
  for (const double mbl : {0.8 * testing::kTensionMax, 10 * testing::kTensionMax}) {
    SceneView scene = testing::StraightScene();
    scene.lines[0].breaking_load = mbl;
    const Snapshot snap = testing::StraightSnapshot(1.0);
    History history(scene, testing::StraightPolicy());
    history.Add(snap);
    const FrameLayout L = MakeFrameLayout(scene, history, 1280, 720);
    const Frame frame = MakeFrame(scene, history, snap, L, Colormap("viridis"));
    const std::string expected = "MBL " + FormatValue("%.4g", mbl / 1000) +
                                 " kN, peak utilisation " + FormatValue("%.3g", 100 * peak / mbl) +
                                 " %";
    const TextItem* found = nullptr;
    for (const TextItem& t : frame.texts)
      if (t.text.find(expected) != std::string::npos) found = &t;
    ASSERT_NE(found, nullptr) << expected;
    const PixelRect& plot = L.max_tension.rect;
    if (mbl < testing::kTensionMax) {  // on the plot, above its dashed line at the MBL
      EXPECT_EQ(found->text, expected);
      EXPECT_NEAR(found->pos.y, L.max_tension.PixelY(mbl / 1000), 12.0f);
      EXPECT_GT(found->pos.x, plot.x0);
    } else {  // in the readout over the plot
      EXPECT_LT(found->pos.y, plot.y0);
    }
  }
}

// ---- A second line (the compare film's inextensible run) ------------------------------------

// Largest channel difference between two colours.
float ColorGap(const Rgba& a, const Rgba& b) {
  return std::max({std::fabs(a.r - b.r), std::fabs(a.g - b.g), std::fabs(a.b - b.b)});
}

TEST(MakeFrame, SecondLineSegmentsCarryTheirTensionColourBeneathTheFirst) {
  const SceneView scene = testing::StraightPairScene();
  const Snapshot snap = testing::StraightPairSnapshot(1.0);
  History history(scene, testing::StraightPolicy());
  history.Add(snap);
  const FrameLayout L = MakeFrameLayout(scene, history, 1280, 720);
  EXPECT_LT(L.overlay_width, L.cable_width);
  const Colormap map("viridis");
  const Frame frame = MakeFrame(scene, history, snap, L, map);
  // Index of the first segment of the first line (its colour at link 0).
  const Vec2f m0 = L.cable.ToPixel(0, 0), m1 = L.cable.ToPixel(1, 0);
  std::size_t first_main = frame.shapes.size();
  for (std::size_t i = 0; i < frame.shapes.size(); ++i) {
    const Shape& s = frame.shapes[i];
    if (s.kind == ShapeKind::kSegment && s.a.x == m0.x && s.a.y == m0.y && s.b.x == m1.x &&
        s.b.y == m1.y && s.size == L.cable_width) {
      first_main = i;
      break;
    }
  }
  ASSERT_LT(first_main, frame.shapes.size());
  const std::vector<double>& second = snap.lines[1].tension;
  int found = 0;
  for (int j = 0; j < kLinks; ++j) {
    const Vec2f a = L.cable.ToPixel(j, testing::kSecondY);
    const Vec2f b = L.cable.ToPixel(j + 1, testing::kSecondY);
    const Rgba want = map.Map(second[j], 0, kTensionMax);
    for (std::size_t i = 0; i < frame.shapes.size(); ++i) {
      const Shape& s = frame.shapes[i];
      // Exact geometry; the colour within float rounding of the map's (the same table entry).
      if (s.kind == ShapeKind::kSegment && s.a.x == a.x && s.a.y == a.y && s.b.x == b.x &&
          s.b.y == b.y && s.size == L.overlay_width && ColorGap(s.color, want) < 1e-6f) {
        EXPECT_LT(i, first_main) << "second line's link " << j << " is drawn over the first line";
        ++found;
        break;
      }
    }
  }
  EXPECT_EQ(found, kLinks);
  // The reversed tensions really give other colours than the first line's at the ends.
  EXPECT_GT(ColorGap(map.Map(second[0], 0, kTensionMax),
                     map.Map(snap.lines[0].tension[0], 0, kTensionMax)),
            0.3f);
}

TEST(MakeFrame, LegendsNameBothLines) {
  const SceneView scene = testing::StraightPairScene();
  const Snapshot snap = testing::StraightPairSnapshot(2.0);
  History history(scene, testing::StraightPolicy());
  history.Add(snap);
  const FrameLayout L = MakeFrameLayout(scene, history, 1920, 1080);
  const Frame frame = MakeFrame(scene, history, snap, L, Colormap("viridis"));
  auto count_in = [&](const std::string& text, const PixelRect& r) {
    int n = 0;
    for (const TextItem& t : frame.texts) n += t.text == text && r.Contains(t.pos);
    return n;
  };
  // Cable panel: one entry per line; tension panel: each line's curve now; max panel: both.
  EXPECT_EQ(count_in("elastic", L.cable_panel), 1);
  EXPECT_EQ(count_in("inextensible", L.cable_panel), 1);
  EXPECT_EQ(count_in("elastic now", L.tension_panel), 1);
  EXPECT_EQ(count_in("inextensible now", L.tension_panel), 1);
  EXPECT_EQ(count_in("inextensible equilibrium", L.tension_panel), 1);
  EXPECT_EQ(count_in("elastic", L.max_panel), 1);
  EXPECT_EQ(count_in("inextensible", L.max_panel), 1);
  // With one line none of these appear.
  const SceneView plain = testing::StraightScene();
  History h2(plain, testing::StraightPolicy());
  const Frame f2 = MakeFrame(plain, h2, testing::StraightSnapshot(2.0),
                             MakeFrameLayout(plain, h2, 1920, 1080), Colormap("viridis"));
  for (const TextItem& t : f2.texts) {
    EXPECT_EQ(t.text.find("inextensible"), std::string::npos) << t.text;
    EXPECT_EQ(t.text.find("elastic"), std::string::npos) << t.text;
  }
}

// A seabed: its line across the cable plot at its elevation, the ground below it shaded (drawn
// before the cable, so the line resting on it lies over it), and a legend entry; none without.
TEST(MakeFrame, SeabedLineGroundAndLegend) {
  SceneView scene = testing::StraightScene();
  const FixedPolicy policy = testing::StraightPolicy();
  scene.sea.seabed = true;
  scene.sea.seabed_y = policy.box.y_min + 0.25 * (policy.box.y_max - policy.box.y_min);
  const Snapshot snap = testing::StraightSnapshot(1.0);
  History history(scene, policy);
  history.Add(snap);
  const FrameLayout L = MakeFrameLayout(scene, history, 1280, 720);
  const Theme th = Theme::Dark();
  const Frame frame = MakeFrame(scene, history, snap, L, Colormap("viridis"), th);
  const float y = L.cable.PixelY(scene.sea.seabed_y);
  int line = -1, ground = -1, first_cable = -1;
  for (std::size_t i = 0; i < frame.shapes.size(); ++i) {
    const Shape& s = frame.shapes[i];
    if (s.kind == ShapeKind::kSegment && SameColor(s.color, th.seabed) && s.a.y == y &&
        s.b.y == y && s.a.x == L.cable.rect.x0 && s.b.x == L.cable.rect.x1)
      line = static_cast<int>(i);
    if (s.kind == ShapeKind::kRect && SameColor(s.color, Mix(th.seabed, th.panel, 0.22f)) &&
        s.a.y == y && s.b.y == L.cable.rect.y1)
      ground = static_cast<int>(i);
    if (first_cable < 0 && s.kind == ShapeKind::kSegment && s.size == L.cable_width)
      first_cable = static_cast<int>(i);
  }
  EXPECT_GE(line, 0);
  EXPECT_GE(ground, 0);
  EXPECT_LT(line, first_cable);
  EXPECT_LT(ground, first_cable);
  int legend = 0;
  for (const TextItem& t : frame.texts) legend += t.text == "seabed" && L.cable_panel.Contains(t.pos);
  EXPECT_EQ(legend, 1);
  const SceneView plain = testing::StraightScene();
  History h2(plain, policy);
  const Frame f2 = MakeFrame(plain, h2, snap, MakeFrameLayout(plain, h2, 1280, 720),
                             Colormap("viridis"), th);
  for (const TextItem& t : f2.texts) EXPECT_NE(t.text, "seabed");
  for (const Shape& s : f2.shapes) EXPECT_FALSE(SameColor(s.color, th.seabed));
}

// Waves: the snapshot's water surface drawn as a line through its samples, the water below it
// (down to the seabed) washed with triangles, both before the cable; a legend entry; none
// without.
TEST(MakeFrame, WaterSurfaceLineWashAndLegend) {
  SceneView scene = testing::StraightScene();
  const FixedPolicy policy = testing::StraightPolicy();
  const WorldBox& box = policy.box;
  scene.sea.seabed = true;
  scene.sea.seabed_y = box.y_min + 0.1 * (box.y_max - box.y_min);
  scene.sea.surface = true;
  Snapshot snap = testing::StraightSnapshot(1.0);
  const double level = box.y_min + 0.8 * (box.y_max - box.y_min);
  const int n = 33;
  for (int i = 0; i < n; ++i) {
    const double x = box.x_min + (box.x_max - box.x_min) * i / (n - 1);
    snap.surface_x.push_back(x);
    snap.surface_y.push_back(level + 0.05 * (box.y_max - box.y_min) * std::cos(0.3 * i));
  }
  History history(scene, policy);
  history.Add(snap);
  const FrameLayout L = MakeFrameLayout(scene, history, 1280, 720);
  const Theme th = Theme::Dark();
  const Frame frame = MakeFrame(scene, history, snap, L, Colormap("viridis"), th);
  int segments = 0, wash = 0, last_water = -1, first_cable = -1, matched = 0;
  for (std::size_t i = 0; i < frame.shapes.size(); ++i) {
    const Shape& s = frame.shapes[i];
    if (first_cable < 0 && s.kind == ShapeKind::kSegment && s.size == L.cable_width)
      first_cable = static_cast<int>(i);
    // (the legend's swatch, in the panel's head above the plot, is not the surface)
    if (s.kind == ShapeKind::kSegment && SameColor(s.color, th.water) &&
        s.a.y >= L.cable.rect.y0) {
      const Vec2f a = L.cable.ToPixel(snap.surface_x[segments], snap.surface_y[segments]);
      const Vec2f b = L.cable.ToPixel(snap.surface_x[segments + 1], snap.surface_y[segments + 1]);
      matched += a.x == s.a.x && a.y == s.a.y && b.x == s.b.x && b.y == s.b.y;
      ++segments;
      last_water = static_cast<int>(i);
    }
    if (s.kind == ShapeKind::kTriangle && s.color.r == th.water.r && s.color.a < 0.5f) {
      ++wash;
      // Down to the seabed's line, never below it.
      EXPECT_LE(std::max({s.a.y, s.b.y, s.c.y}), L.cable.PixelY(scene.sea.seabed_y) + 1e-3f);
      last_water = std::max(last_water, static_cast<int>(i));
    }
  }
  EXPECT_EQ(segments, n - 1);
  EXPECT_EQ(matched, n - 1);  // through the samples, in order
  EXPECT_EQ(wash, 2 * (n - 1));
  EXPECT_LT(last_water, first_cable);
  int legend = 0;
  for (const TextItem& t : frame.texts)
    legend += t.text == "water surface" && L.cable_panel.Contains(t.pos);
  EXPECT_EQ(legend, 1);
  // A surface reaching a box's width beyond the box on either side (as the film samples it) is
  // clipped to the plot's x range: its line runs from the plot's left edge to its right edge.
  Snapshot wide = testing::StraightSnapshot(1.0);
  const double width = box.x_max - box.x_min;
  for (int i = 0; i <= 300; ++i) {
    wide.surface_x.push_back(box.x_min - width + 3 * width * i / 300);
    wide.surface_y.push_back(level);
  }
  const Frame f3 = MakeFrame(scene, history, wide, L, Colormap("viridis"), th);
  float left = 1e9f, right = -1e9f;
  for (const Shape& s : f3.shapes)
    if (s.kind == ShapeKind::kSegment && SameColor(s.color, th.water) &&
        s.a.y >= L.cable.rect.y0) {
      left = std::min({left, s.a.x, s.b.x});
      right = std::max({right, s.a.x, s.b.x});
    }
  EXPECT_FLOAT_EQ(left, L.cable.rect.x0);
  EXPECT_FLOAT_EQ(right, L.cable.rect.x1);
  const SceneView plain = testing::StraightScene();
  History h2(plain, policy);
  const Frame f2 = MakeFrame(plain, h2, testing::StraightSnapshot(1.0),
                             MakeFrameLayout(plain, h2, 1280, 720), Colormap("viridis"), th);
  for (const TextItem& t : f2.texts) EXPECT_NE(t.text, "water surface");
  for (const Shape& s : f2.shapes) EXPECT_FALSE(SameColor(s.color, th.water));
}

TEST(MakeFrame, SecondLineTensionCurveAndMaxTrace) {
  const SceneView scene = testing::StraightPairScene();
  History history(scene, testing::StraightPolicy());
  Snapshot snap;
  for (int i = 0; i <= 20; ++i) {
    snap = testing::StraightPairSnapshot(i * 0.5);
    for (double& T : snap.lines[1].tension) T *= 0.5 + 0.02 * i;
    history.Add(snap);
  }
  const FrameLayout L = MakeFrameLayout(scene, history, 1280, 720);
  const Frame frame = MakeFrame(scene, history, snap, L, Colormap("viridis"));
  const Theme th = Theme::Dark();
  const std::vector<double>& second = snap.lines[1].tension;
  // The second line's current tension: a vertex at each link midpoint, in the overlay colour.
  int vertices = 0, trace = 0;
  for (int j = 0; j < kLinks; ++j) {
    const Vec2f want = L.tension.ToPixel(j + 0.5, second[j] / 1000);
    for (const Shape& s : frame.shapes)
      if (s.kind == ShapeKind::kSegment && SameColor(s.color, th.overlay) &&
          std::fabs(s.a.x - want.x) < 1e-3f && std::fabs(s.a.y - want.y) < 1e-3f) {
        ++vertices;
        break;
      }
  }
  EXPECT_EQ(vertices, kLinks - 1);  // the last midpoint only ends a segment
  for (const Shape& s : frame.shapes)
    trace += s.kind == ShapeKind::kSegment && SameColor(s.color, th.overlay) &&
             L.max_tension.rect.Contains(s.a) && L.max_tension.rect.Contains(s.b);
  EXPECT_EQ(trace, 20);  // 21 snapshots, each in its own pixel column
  // The second line's max tension, one per snapshot.
  ASSERT_EQ(history.max_tension().size(), 2u);
  ASSERT_EQ(history.max_tension()[1].size(), 21u);
  EXPECT_DOUBLE_EQ(history.max_tension()[1][0], 0.5 * second[0] / (0.5 + 0.02 * 20));
  EXPECT_DOUBLE_EQ(history.max_tension()[1][20], second[0]);
}

TEST(CheckSnapshot, RejectsASecondLineOfTheWrongSize) {
  const SceneView scene = testing::StraightPairScene();
  const Snapshot good = testing::StraightPairSnapshot(1.5);
  EXPECT_NO_THROW(CheckSnapshot(scene, good));
  auto message = [&](const Snapshot& s) -> std::string {
    try {
      CheckSnapshot(scene, s);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  Snapshot short_x = good;
  short_x.lines[1].x.pop_back();
  const std::string m1 = message(short_x);
  EXPECT_NE(m1.find("line 2 at t = 1.5"), std::string::npos) << m1;
  EXPECT_NE(m1.find("20 x, 21 y and 20 tensions"), std::string::npos) << m1;
  EXPECT_NE(m1.find("21 stations and 20 links"), std::string::npos) << m1;
  Snapshot long_t = good;
  long_t.lines[1].tension.push_back(1);
  EXPECT_NE(message(long_t).find("21 tensions"), std::string::npos) << message(long_t);
  // The scene has two lines: a snapshot of one is an error too.
  const std::string m3 = message(testing::StraightSnapshot(1.5));
  EXPECT_NE(m3.find("has 1 line; the scene has 2"), std::string::npos) << m3;
  Snapshot nan = good;
  nan.lines[1].tension[7] = NAN;
  EXPECT_NE(message(nan).find("tension of link 7 of line 2"), std::string::npos) << message(nan);
  // A scene of one line takes a snapshot of one line, and no other.
  const SceneView plain = testing::StraightScene();
  EXPECT_NO_THROW(CheckSnapshot(plain, testing::StraightSnapshot(1)));
  EXPECT_THROW(CheckSnapshot(plain, good), Error);
  EXPECT_THROW(CheckSnapshot(plain, short_x), Error);
  // History::Add checks the sizes the same way, before changing anything.
  History history(scene, testing::StraightPolicy());
  EXPECT_THROW(history.Add(short_x), Error);
  EXPECT_THROW(history.Add(testing::StraightSnapshot(1)), Error);
  EXPECT_EQ(history.count(), 0);
  EXPECT_TRUE(history.times().empty());
  EXPECT_TRUE(history.max_tension()[1].empty());
  // And MakeFrame rejects it.
  EXPECT_THROW(MakeFrame(scene, history, short_x, MakeFrameLayout(scene, history, 320, 180),
                         Colormap("viridis")),
               Error);
}

// Lines after the first without labels: the legends give them default names on one row (the
// layout makes no second row), and the time plot has no readout. A row a line has no value for
// is a gap (NaN) in its trace.
TEST(FilmHistory, UnnamedLinesHaveDefaultNamesAndRowsMayHaveGaps) {
  SceneView scene = testing::StraightPairScene();
  for (LineView& line : scene.lines) line.label.clear();
  History history(scene, testing::StraightPolicy());
  const double kNaN = std::nan("");
  for (int i = 0; i < 3; ++i) {
    Snapshot s = testing::StraightPairSnapshot(0.1 * i);
    s.row_t = {0.1 * i};
    s.lines[0].row_max = {1000.0 * (i + 1)};
    s.lines[1].row_max = {i == 1 ? 2000.0 : kNaN};
    history.Add(s);
  }
  ASSERT_EQ(history.max_tension()[1].size(), 3u);
  EXPECT_TRUE(std::isnan(history.max_tension()[1][0]));
  EXPECT_DOUBLE_EQ(history.max_tension()[1][1], 2000);
  EXPECT_TRUE(std::isnan(history.max_tension()[1][2]));
  EXPECT_DOUBLE_EQ(history.peak(1), 2000);  // the gaps are not values
  EXPECT_DOUBLE_EQ(history.peak_t(1), 0.1);
  // Drawn with default names and one legend row (the layout has no second row).
  const FrameLayout L = MakeFrameLayout(scene, history, 1280, 720);
  EXPECT_FALSE(L.legend_rows);
  const Frame frame = MakeFrame(scene, history, testing::StraightPairSnapshot(0.3), L,
                                Colormap("viridis"));
  int named = 0;
  for (const TextItem& t : frame.texts) {
    named += t.text == "line 2";
    EXPECT_EQ(t.text.find("now"), std::string::npos) << "no readout: " << t.text;
    // Above the plots, only the row of the title and legend (no second row over the plots).
    if ((L.tension_panel.Contains(t.pos) || L.max_panel.Contains(t.pos)) &&
        t.pos.y < L.tension.rect.y0) {
      EXPECT_FLOAT_EQ(t.pos.y, L.tension_panel.y0 + 30 * L.scale) << t.text;
    }
  }
  EXPECT_EQ(named, 3);  // cable, tension and max-tension legends
}

}  // namespace
}  // namespace cablefilm
