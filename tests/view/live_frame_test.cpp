#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/error.h"
#include "view/demo_cable.h"
#include "view/frame_builder.h"
#include "view/history.h"
#include "view/painter.h"
#include "test_scene.h"

namespace cablefilm {
namespace {

using testing::kLinks;
using testing::kTensionMax;

bool SameColor(const Rgba& a, const Rgba& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

// A live view: its scene, its (following) history, and the snapshot a frame draws.
struct Live {
  SceneView scene;
  History history;
  Snapshot now;
};

// The straight cable with its largest tension `max` [N] (at link 19, as every link's
// tension is scaled alike) and its moving end at `end` [m].
Snapshot Straight(double t, double max, Vec2f end = {kLinks, 0}) {
  Snapshot s = testing::StraightSnapshot(t);
  for (double& T : s.lines[0].tension) T *= max / ((kLinks - 0.5) / kLinks * kTensionMax);
  s.lines[0].x[kLinks] = end.x;
  s.lines[0].y[kLinks] = end.y;
  return s;
}

// The straight test cable as the live view sees it at t = 70 s, with a 60 s window [10, 70]:
// a sample every 0.1 s from t = 0 (its largest tension 0.5 to 0.9 of kTensionMax), the peak
// (39 kN at link 19) at t = 3.25 s, the moving end on a circle of 0.5 m (back at (20, 0) at
// t = 70 s), and `markers` added as their time came (by default at 12, 30 and 55 s, inside the
// window, and at 5 s, scrolled out of it). Its sections are named "chain" and "rope".
using Markers = std::vector<TimeMarker>;
Live StraightLive(SceneView scene = {},
                  Markers markers = {{5, "old"}, {12, "speed 2x"}, {30, "amplitude 3 m"},
                                     {55, "current 0.5 m/s"}},
                  const Wave& wave = {}) {
  if (scene.lines.empty()) {
    scene = testing::StraightScene();
    scene.lines[0].section_names = {"chain", "rope"};
  }
  History history(scene, FollowingPolicy{60, wave});
  std::size_t next = 0;
  for (int i = 0; i <= 700; ++i) {
    const double t = i * 0.1;
    while (next < markers.size() && markers[next].t <= t) {
      history.AddMarker(markers[next].t, markers[next].label);
      ++next;
    }
    if (i == 33) history.Add(Straight(3.25, 0.975 * kTensionMax));  // the peak
    const double phase = 2 * M_PI * t / 10;
    const Vec2f end{static_cast<float>(kLinks + 0.5 * std::sin(phase)),
                    static_cast<float>(0.5 * (1 - std::cos(phase)))};
    const double max = kTensionMax * (0.5 + 0.4 * std::sin(i * 0.05));
    history.Add(Straight(t, max, i < 700 ? end : Vec2f{kLinks, 0}));
  }
  Snapshot now = history.now();
  return {std::move(scene), std::move(history), std::move(now)};
}

FrameLayout Layout(const Live& l, int width, int height) {
  return MakeFrameLayout(l.scene, l.history, width, height);
}
Frame Draw(const Live& l, int width, int height, const Colormap& colormap,
           const Theme& th = Theme::Dark(), const std::string& status = "live \u00b7 2.0x") {
  return MakeFrame(l.scene, l.history, l.now, Layout(l, width, height), colormap, th, status);
}

const TextItem* FindText(const Frame& f, const std::string& text) {
  for (const TextItem& t : f.texts)
    if (t.text == text) return &t;
  return nullptr;
}

TEST(LiveFrame, MarkersAreDashedLinesAtTheirTimeWithTheirLabel) {
  const Live in = StraightLive();
  const FrameLayout L = Layout(in, 1280, 720);
  const Frame frame = Draw(in, 1280, 720, Colormap("viridis"));
  const Theme th = Theme::Dark();
  const PlotMapping& m = L.max_tension;
  EXPECT_DOUBLE_EQ(m.x_lo, 10);
  EXPECT_DOUBLE_EQ(m.x_hi, 70);
  // Every vertical segment in the marker colour, by its x: one dashed line per inside marker.
  std::vector<float> xs;
  for (const Shape& s : frame.shapes)
    if (s.kind == ShapeKind::kSegment && SameColor(s.color, th.event)) {
      EXPECT_FLOAT_EQ(s.a.x, s.b.x) << "a marker line is vertical";
      EXPECT_TRUE(m.rect.Contains(s.a) && m.rect.Contains(s.b)) << "inside the time plot";
      if (std::none_of(xs.begin(), xs.end(), [&](float x) { return x == s.a.x; }))
        xs.push_back(s.a.x);
    }
  ASSERT_EQ(xs.size(), 3u);  // the marker at 5 s is before the window
  std::sort(xs.begin(), xs.end());
  const double times[] = {12, 30, 55};
  for (int i = 0; i < 3; ++i) {
    EXPECT_FLOAT_EQ(xs[i], m.PixelX(times[i])) << times[i] << " s";
    // Dashed: several pieces over the plot's height.
    int pieces = 0;
    for (const Shape& s : frame.shapes)
      pieces += s.kind == ShapeKind::kSegment && SameColor(s.color, th.event) && s.a.x == xs[i];
    EXPECT_GT(pieces, 5);
  }
  // Each label next to its line, rotated, in the marker colour, near the plot's top.
  const char* labels[] = {"speed 2x", "amplitude 3 m", "current 0.5 m/s"};
  for (int i = 0; i < 3; ++i) {
    const TextItem* t = FindText(frame, labels[i]);
    ASSERT_NE(t, nullptr) << labels[i];
    EXPECT_TRUE(t->vertical);
    EXPECT_TRUE(SameColor(t->color, th.event));
    EXPECT_NEAR(t->pos.x, xs[i], 8 * L.scale);
    EXPECT_NEAR(t->pos.y, m.rect.y0, 10 * L.scale);
  }
  EXPECT_EQ(FindText(frame, "old"), nullptr);
}

// A seabed: the cable panel draws its line across the plot at its elevation and names it.
TEST(LiveFrame, SeabedLineAndLegend) {
  SceneView scene = testing::StraightScene();
  scene.sea.seabed = true;
  scene.sea.seabed_y = -0.25;
  const Live in = StraightLive(scene);
  const Theme th = Theme::Dark();
  const FrameLayout L = Layout(in, 1280, 720);
  const Frame f = Draw(in, 1280, 720, Colormap("viridis"), th);
  const float y = L.cable.PixelY(scene.sea.seabed_y);
  int line = 0;
  for (const Shape& s : f.shapes)
    line += s.kind == ShapeKind::kSegment && SameColor(s.color, th.seabed) && s.a.y == y &&
            s.b.y == y;
  EXPECT_EQ(line, 1);
  EXPECT_NE(FindText(f, "seabed"), nullptr);
  EXPECT_EQ(FindText(Draw(StraightLive(), 1280, 720, Colormap("viridis"), th), "seabed"), nullptr);
}

// Waves: the snapshot's water surface is drawn (a segment between each pair of samples) and named.
TEST(LiveFrame, WaterSurfaceLineAndLegend) {
  SceneView scene = testing::StraightScene();
  scene.sea.surface = true;
  WaveSpec w;
  w.present = true;
  w.height = 0.5;
  w.period = 4;
  w.depth = 30;
  w.surface_y = 1.5;  // above the line
  Live in = StraightLive(scene, {}, MakeWave(w, 9.80665));
  const WorldBox box = in.history.box();
  in.now.surface_x.clear();
  in.now.surface_y.clear();
  for (int i = 0; i < 9; ++i) {
    in.now.surface_x.push_back(box.x_min + (box.x_max - box.x_min) * i / 8);
    in.now.surface_y.push_back(box.y_min + 0.9 * (box.y_max - box.y_min));
  }
  const Theme th = Theme::Dark();
  const Frame f = Draw(in, 1280, 720, Colormap("viridis"), th);
  const FrameLayout L = Layout(in, 1280, 720);
  int line = 0;  // in the plot (the legend's swatch is in the panel's head, above it)
  for (const Shape& s : f.shapes)
    line += s.kind == ShapeKind::kSegment && SameColor(s.color, th.water) &&
            s.a.y >= L.cable.rect.y0;
  EXPECT_EQ(line, 8);
  EXPECT_NE(FindText(f, "water surface"), nullptr);
  EXPECT_EQ(FindText(Draw(StraightLive(), 1280, 720, Colormap("viridis"), th), "water surface"),
            nullptr);
}

TEST(LiveFrame, CloseMarkersKeepTheNewestLabelAndLongLabelsAreCut) {
  const Live in =
      StraightLive({}, {{30, "first"}, {30.05, "second"}, {40, std::string(60, 'x')}});
  const Frame frame = Draw(in, 1280, 720, Colormap("viridis"));
  EXPECT_EQ(FindText(frame, "first"), nullptr);  // 0.05 s apart: under a pixel
  EXPECT_NE(FindText(frame, "second"), nullptr);
  EXPECT_NE(FindText(frame, std::string(28, 'x') + "\u2026"), nullptr);
}

TEST(LiveFrame, CableSegmentsCarryTheColourOfTheirTension) {
  const Live in = StraightLive();
  const FrameLayout L = Layout(in, 1280, 720);
  const Colormap map("magma");
  const Frame frame = Draw(in, 1280, 720, map);
  const double lo = in.history.range_min(), hi = in.history.range_max();
  int found = 0;
  for (int j = 0; j < kLinks; ++j) {
    const Vec2f a = L.cable.ToPixel(j, 0), b = L.cable.ToPixel(j + 1, 0);
    const Rgba want = map.Map(in.now.lines[0].tension[j], lo, hi);
    for (const Shape& s : frame.shapes)
      if (s.kind == ShapeKind::kSegment && s.a.x == a.x && s.a.y == a.y && s.b.x == b.x &&
          s.b.y == b.y && SameColor(s.color, want) && s.size == L.cable_width) {
        ++found;
        break;
      }
  }
  EXPECT_EQ(found, kLinks);
  // Equal scale in x and y, and the whole box visible.
  const PlotMapping& c = L.cable;
  const WorldBox box = in.history.box();
  EXPECT_NEAR(c.rect.width() / (c.x_hi - c.x_lo), c.rect.height() / (c.y_hi - c.y_lo), 1e-4);
  EXPECT_LE(c.x_lo, box.x_min);
  EXPECT_GE(c.x_hi, box.x_max);
}

TEST(LiveFrame, SectionNamesAreCentredInTheirSpans) {
  Live in = StraightLive();
  const FrameLayout L = Layout(in, 1280, 720);
  const Frame frame = Draw(in, 1280, 720, Colormap("viridis"));
  const PlotMapping& tm = L.tension;
  const TextItem* chain = FindText(frame, "chain");
  const TextItem* rope = FindText(frame, "rope");
  ASSERT_TRUE(chain && rope);
  EXPECT_FLOAT_EQ(chain->pos.x, (tm.PixelX(0) + tm.PixelX(10)) / 2);
  EXPECT_FLOAT_EQ(rope->pos.x, (tm.PixelX(10) + tm.PixelX(20)) / 2);
  for (const TextItem* t : {chain, rope}) {
    EXPECT_TRUE(tm.rect.Contains(t->pos)) << t->text;
    EXPECT_LT(t->pos.y, tm.rect.y0 + 0.1f * tm.rect.height()) << "near the top";
  }
  in.scene.lines[0].section_names.clear();  // unnamed: no names, still valid
  const Frame plain = Draw(in, 1280, 720, Colormap("viridis"));
  EXPECT_EQ(FindText(plain, "chain"), nullptr);
}

TEST(LiveFrame, HeaderShowsStatusTimeAndPeak) {
  Live in = StraightLive();
  in.history.LockRange(true);
  const Frame frame = Draw(in, 1920, 1080, Colormap("viridis"));
  EXPECT_NE(FindText(frame, "Straight test cable"), nullptr);
  EXPECT_NE(FindText(frame, "live \u00b7 2.0x"), nullptr);
  EXPECT_NE(FindText(frame, "t = 70.00 s"), nullptr);
  EXPECT_NE(FindText(frame, "peak 39.00 kN at t = 3.25 s, link 19"), nullptr);
  EXPECT_NE(FindText(frame, "tension [kN], locked"), nullptr);
  in.history.LockRange(false);
  const Frame free = Draw(in, 1920, 1080, Colormap("viridis"));
  EXPECT_NE(FindText(free, "tension [kN]"), nullptr);
  EXPECT_EQ(FindText(free, "tension [kN], locked"), nullptr);
}

// Each piece of the picture's input, spoiled, is an error (at the history's construction, at
// Add, at the layout or at the frame), never a wrong picture.
TEST(LiveFrame, InconsistentInputThrows) {
  auto draw = [](const Live& l) { Draw(l, 640, 360, Colormap("viridis")); };
  // The snapshot now at 70.1 s carrying two rows, their `maxima` and an envelope of `links`.
  auto with_rows = [](const Live& l, std::size_t maxima, std::size_t links) {
    Snapshot s = l.now;
    s.t = 70.1;
    s.row_t = {70.05, 70.1};
    s.lines[0].row_max.assign(maxima, 1000);
    s.lines[0].row_link_min.assign(links, 0);
    s.lines[0].row_link_max.assign(links, 1000);
    return s;
  };
  // The live view of a scene spoiled, or of the usual one with its snapshot now spoiled.
  auto spoiled_line = [&](const std::function<void(LineView&)>& spoil) {
    SceneView scene = testing::StraightScene();
    spoil(scene.lines[0]);
    draw(StraightLive(scene));
  };
  auto spoiled_now = [&](const std::function<void(Snapshot&)>& spoil) {
    Live l = StraightLive();
    spoil(l.now);
    draw(l);
  };
  const std::vector<std::pair<const char*, std::function<void()>>> bad = {
      {"short tension", [&] { spoiled_now([](Snapshot& s) { s.lines[0].tension.pop_back(); }); }},
      {"short x", [&] { spoiled_now([](Snapshot& s) { s.lines[0].x.pop_back(); }); }},
      {"NaN station", [&] { spoiled_now([](Snapshot& s) { s.lines[0].y[3] = NAN; }); }},
      {"second line", [&] { spoiled_now([](Snapshot& s) { s.lines.push_back(s.lines[0]); }); }},
      {"names", [&] { spoiled_line([](LineView& l) { l.section_names = {"a", "b", "c"}; }); }},
      {"envelope", [&] { Live l = StraightLive(); l.history.Add(with_rows(l, 2, kLinks - 1)); }},
      {"trace", [&] { Live l = StraightLive(); l.history.Add(with_rows(l, 1, kLinks)); }},
      {"equilibrium", [&] { spoiled_line([](LineView& l) { l.reference.x.pop_back(); }); }},
      {"moving end",
       [&] { spoiled_line([](LineView& l) { l.marks.moving_ends = {kLinks + 1}; }); }},
      {"weight", [&] { spoiled_line([](LineView& l) { l.marks.weights = {-1}; }); }},
      {"window", [&] { History h(testing::StraightScene(), FollowingPolicy{0, {}}); }},
      {"range", [&] { Live l = StraightLive(); l.history.SetRange(1000, 1000); draw(l); }},
      {"box", [&] {
         Live l = StraightLive();
         Snapshot s = l.now;
         s.lines[0].x[3] = INFINITY;  // the box follows it out of bounds
         l.history.Add(s);
         l.now = testing::StraightSnapshot(70);
         draw(l);
       }},
      {"stations", [&] { spoiled_line([](LineView& l) { l.arc_length.resize(1); }); }},
  };
  for (const auto& [what, spoil] : bad) EXPECT_THROW(spoil(), Error) << what;
  // Optional series may be empty: no reference, and (a history of nothing yet) no trace, no
  // envelope, no end path, no markers.
  SceneView scene = testing::StraightScene();
  scene.lines[0].reference = LineState{};
  History empty(scene, testing::StraightPolicy());
  EXPECT_NO_THROW(MakeFrame(scene, empty, testing::StraightSnapshot(40),
                            MakeFrameLayout(scene, empty, 640, 360), Colormap("viridis")));
  History following(scene, FollowingPolicy{60, {}});
  following.Add(testing::StraightSnapshot(40));
  EXPECT_NO_THROW(MakeFrame(scene, following, following.now(),
                            MakeFrameLayout(scene, following, 640, 360), Colormap("viridis")));
}

TEST(LiveFrame, CostPerFrameIsBoundedByThePixels) {
  // A day of samples at 1 kHz squeezed into the window: the history keeps the newest
  // kMaxTracePoints and the trace two points per pixel column.
  Live in = StraightLive();
  Snapshot rows = Straight(70.1, 0.5 * kTensionMax);
  for (int i = 0; i < 600000; ++i) {
    rows.row_t.push_back(10.1 + i * 1e-4);
    rows.lines[0].row_max.push_back(kTensionMax * (0.5 + 0.4 * std::sin(i * 0.01)));
  }
  in.history.Add(rows);
  in.now = rows;
  ASSERT_EQ(in.history.times().size(), History::kMaxTracePoints);
  const FrameLayout L = Layout(in, 1280, 720);
  const Frame frame = Draw(in, 1280, 720, Colormap("viridis"));
  const Rgba accent = Theme::Dark().accent;
  int trace = 0;
  for (const Shape& s : frame.shapes)
    if (s.kind == ShapeKind::kSegment && SameColor(s.color, accent) &&
        L.max_tension.rect.Contains(s.a))
      ++trace;
  EXPECT_GT(trace, 100);
  EXPECT_LE(trace, 2 * static_cast<int>(L.max_tension.rect.width()) + 4);
}

// ---- Layout -------------------------------------------------------------------------------

bool Overlap(const PixelRect& a, const PixelRect& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

// The P63-like demo box (84 m x 47 m) gets a cable panel as wide as its shape needs, the
// tension along the cable beside it and a full-width time plot; a long flat box keeps the
// cable across the whole top row. Panels never overlap and stay inside the frame.
// The straight scene's layout for a film whose box is `box`.
FrameLayout BoxLayout(const WorldBox& box, int w, int h) {
  const SceneView scene = testing::StraightScene();
  FixedPolicy policy = testing::StraightPolicy();
  policy.box = box;
  return MakeFrameLayout(scene, History(scene, policy), w, h);
}

TEST(FrameLayoutFit, CablePanelWidthFollowsTheBoxShape) {
  for (auto [w, h] : {std::pair{1920, 1080}, std::pair{1280, 720}, std::pair{640, 360}}) {
    const FrameLayout L = BoxLayout({-1, 83, -12, 35}, w, h);
    EXPECT_TRUE(L.side_by_side) << w << "x" << h;
    EXPECT_LT(L.cable_panel.width(), 0.62f * w);
    EXPECT_FLOAT_EQ(L.cable_panel.y0, L.tension_panel.y0);
    EXPECT_FLOAT_EQ(L.max_panel.x0, L.cable_panel.x0);
    EXPECT_FLOAT_EQ(L.max_panel.x1, L.tension_panel.x1);
    // The cable's box fills the axes' height (it is what limits the scale) and most of their
    // width (the panel grows in steps of 1/64 of the frame's width).
    const PlotMapping& c = L.cable;
    const double ppm = c.rect.height() / (c.y_hi - c.y_lo);
    EXPECT_NEAR(ppm, c.rect.height() / (47 * 1.0 + 2 * 0.04 * 84), 1e-3 * ppm);
    EXPECT_GT(84 * 1.08 * ppm, 0.9 * c.rect.width());

    const FrameLayout flat = BoxLayout({0, 400, -5, 5}, w, h);
    EXPECT_FALSE(flat.side_by_side) << w << "x" << h;

    for (const FrameLayout* l : {&L, &flat}) {
      const PixelRect panels[] = {l->cable_panel, l->tension_panel, l->max_panel};
      for (int i = 0; i < 3; ++i) {
        EXPECT_GE(panels[i].x0, 0);
        EXPECT_GE(panels[i].y0, 0);
        EXPECT_LE(panels[i].x1, w);
        EXPECT_LE(panels[i].y1, h);
        for (int j = i + 1; j < 3; ++j) EXPECT_FALSE(Overlap(panels[i], panels[j])) << i << j;
      }
      EXPECT_TRUE(Overlap(l->colorbar, l->cable_panel));
      EXPECT_FALSE(Overlap(l->colorbar, l->cable.rect));
    }
  }
}

// The straight line's stations evenly from (x0, y0) to (x1, y1) [m] at t [s].
Snapshot Chord(double t, double x0, double y0, double x1, double y1) {
  Snapshot s = testing::StraightSnapshot(t);
  for (int j = 0; j <= kLinks; ++j) {
    s.lines[0].x[j] = x0 + (x1 - x0) * j / kLinks;
    s.lines[0].y[j] = y0 + (y1 - y0) * j / kLinks;
  }
  return s;
}

// The live view fits its panels to the box over the run so far (layout_aspect): they stay
// still while the box follows the lines.
TEST(FrameLayoutFit, LayoutAspectKeepsPanelsStill) {
  SceneView scene = testing::StraightScene();
  scene.lines[0].marks.moving_ends.clear();  // no end path holding the box
  History history(scene, FollowingPolicy{60, {}});
  history.Add(Chord(1, -1, -12, 83, 35));
  const double aspect = history.layout_aspect();
  const WorldBox before = history.box();
  const FrameLayout a = MakeFrameLayout(scene, history, 1280, 720);
  for (int i = 0; i < 30; ++i) history.Add(Chord(1.1 + 0.1 * i, -1, -12, 83, 25));
  EXPECT_LT(history.box().y_max, before.y_max - 1);  // the box shrank
  EXPECT_EQ(history.layout_aspect(), aspect);
  const FrameLayout b = MakeFrameLayout(scene, history, 1280, 720);
  EXPECT_FLOAT_EQ(a.cable_panel.x1, b.cable_panel.x1);
  EXPECT_FLOAT_EQ(a.tension.rect.x0, b.tension.rect.x0);
}

// No two text items overlap, by their estimated extents, in the film's and the live view's
// frames at the three usual sizes (tick labels of one axis are spaced by NiceTicks; this is
// about titles, legends, notes, names and markers against everything else).
PixelRect TextBox(const TextItem& t) {
  // DejaVu Sans: cap height 0.73 em, ascent 0.76 em, descent 0.24 em; the descent only counts
  // for text with a descender (tick labels, digits only, have none).
  const float len = EstimateTextWidth(t.text, t.size, t.bold), h = t.size;
  const bool descends = t.text.find_first_of("gjpqy()[],;/|") != std::string::npos;
  float u0 = 0;  // along the text, from the anchor
  if (t.halign == HAlign::kCenter) u0 = -len / 2;
  if (t.halign == HAlign::kRight) u0 = -len;
  float baseline = 0;  // across, down from the anchor (Renderer's FontAtlas::Layout)
  if (t.valign == VAlign::kTop) baseline = 0.73f * h;
  if (t.valign == VAlign::kMiddle) baseline = 0.365f * h;
  if (t.valign == VAlign::kBottom) baseline = -0.24f * h;
  const float v0 = baseline - 0.76f * h, v1 = baseline + (descends ? 0.24f * h : 0);
  if (!t.vertical) return {t.pos.x + u0, t.pos.y + v0, t.pos.x + u0 + len, t.pos.y + v1};
  return {t.pos.x + v0, t.pos.y - u0 - len, t.pos.x + v1, t.pos.y - u0};
}

void ExpectNoTextOverlaps(const Frame& f, const std::string& what) {
  for (std::size_t i = 0; i < f.texts.size(); ++i)
    for (std::size_t j = i + 1; j < f.texts.size(); ++j) {
      const PixelRect a = TextBox(f.texts[i]), b = TextBox(f.texts[j]);
      EXPECT_FALSE(Overlap(a, b)) << what << ": '" << f.texts[i].text << "' and '"
                                  << f.texts[j].text << "'";
    }
}

TEST(FrameLayoutFit, NoTextOverlapsAtTheUsualSizes) {
  const SceneView scene = MakeDemoScene();
  const FixedPolicy policy = MakeDemoPolicy(60);
  History history(scene, policy);
  Snapshot s;
  for (int i = 0; i <= 300; ++i) {
    s = MakeDemoSnapshot(scene, i / 10.0);
    history.Add(s);
  }
  // The demo with a second line (a copy 1 m lower, 10 % more tension) names both lines: its
  // legends take second rows.
  SceneView both = scene;
  both.lines[0].label = "elastic";
  both.lines.push_back(both.lines[0]);
  both.lines[1].label = "inextensible";
  FixedPolicy both_policy = policy;
  both_policy.box.y_min -= 1;
  Snapshot sc = s;
  sc.lines.push_back(s.lines[0]);
  for (double& y : sc.lines[1].y) y -= 1;
  for (double& T : sc.lines[1].tension) T *= 1.1;
  History both_history(both, both_policy);
  both_history.Add(sc);
  const SceneView straight = testing::StraightPairScene();  // flat: the stacked layout
  History straight_history(straight, testing::StraightPolicy());
  const Snapshot ss = testing::StraightPairSnapshot(1);
  straight_history.Add(ss);
  const Live live = StraightLive();
  for (auto [w, h] : {std::pair{1920, 1080}, std::pair{1280, 720}, std::pair{640, 360}}) {
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    ExpectNoTextOverlaps(MakeFrame(scene, history, s, MakeFrameLayout(scene, history, w, h),
                                   Colormap("viridis")),
                         "film " + size);
    ExpectNoTextOverlaps(MakeFrame(both, both_history, sc,
                                   MakeFrameLayout(both, both_history, w, h), Colormap("viridis")),
                         "film of two lines " + size);
    ExpectNoTextOverlaps(MakeFrame(straight, straight_history, ss,
                                   MakeFrameLayout(straight, straight_history, w, h),
                                   Colormap("viridis")),
                         "flat film of two lines " + size);
    ExpectNoTextOverlaps(Draw(live, w, h, Colormap("viridis")), "live " + size);
  }
}

}  // namespace
}  // namespace cablefilm
