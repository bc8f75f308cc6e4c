#include "view/live_frame.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/error.h"
#include "view/demo_cable.h"
#include "view/frame_builder.h"
#include "view/painter.h"
#include "test_scene.h"

namespace cablefilm {
namespace {

using testing::kLinks;
using testing::kTensionMax;

bool SameColor(const Rgba& a, const Rgba& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

// The straight test cable as the live view sees it at t = 40 s, with a 60 s window [10, 70],
// a trace of one sample per 0.1 s and markers at 12, 30 and 55 s (inside) and 5 s (outside).
LiveFrameInput StraightLive() {
  const FilmSpec spec = testing::StraightSpec();
  LiveFrameInput in;
  in.title = "Straight test cable";
  in.status = "live \u00b7 2.0x";
  in.snapshot = testing::StraightSnapshot(40);
  in.arc_length = spec.arc_length;
  in.section_boundaries = spec.section_boundaries;
  in.section_names = {"chain", "rope"};
  in.weight_stations = spec.weight_stations;
  in.moving_ends = spec.moving_ends;
  in.fixed_ends = spec.fixed_ends;
  in.equilibrium = spec.equilibrium;
  in.tension_min = 0;
  in.tension_max = kTensionMax;
  in.x_min = spec.x_min;
  in.x_max = spec.x_max;
  in.y_min = spec.y_min;
  in.y_max = spec.y_max;
  in.window_start = 10;
  in.window_end = 70;
  for (int i = 100; i <= 400; ++i) {
    in.times.push_back(i * 0.1);
    in.max_tension.push_back(kTensionMax * (0.5 + 0.4 * std::sin(i * 0.05)));
  }
  in.link_min.assign(kLinks, 0.1 * kTensionMax);
  in.link_max.assign(kLinks, 0.9 * kTensionMax);
  in.end_paths = {{{20, 0}, {20.5f, 0.5f}, {20, 1}}};
  in.markers = {{12, "speed 2x"}, {30, "amplitude 3 m"}, {55, "current 0.5 m/s"}, {5, "old"}};
  in.peak = 39000;
  in.peak_t = 3.25;
  in.peak_link = 19;
  return in;
}

const TextItem* FindText(const Frame& f, const std::string& text) {
  for (const TextItem& t : f.texts)
    if (t.text == text) return &t;
  return nullptr;
}

TEST(LiveFrame, MarkersAreDashedLinesAtTheirTimeWithTheirLabel) {
  const LiveFrameInput in = StraightLive();
  const FrameLayout L = MakeLiveFrameLayout(in, 1280, 720);
  const Frame frame = MakeLiveFrame(in, 1280, 720, Colormap("viridis"));
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
  LiveFrameInput in = StraightLive();
  in.seabed = true;
  in.seabed_y = in.y_min + 0.25 * (in.y_max - in.y_min);
  const Theme th = Theme::Dark();
  const FrameLayout L = MakeLiveFrameLayout(in, 1280, 720);
  const Frame f = MakeLiveFrame(in, 1280, 720, Colormap("viridis"), th);
  const float y = L.cable.PixelY(in.seabed_y);
  int line = 0;
  for (const Shape& s : f.shapes)
    line += s.kind == ShapeKind::kSegment && SameColor(s.color, th.seabed) && s.a.y == y &&
            s.b.y == y;
  EXPECT_EQ(line, 1);
  EXPECT_NE(FindText(f, "seabed"), nullptr);
  EXPECT_EQ(FindText(MakeLiveFrame(StraightLive(), 1280, 720, Colormap("viridis"), th), "seabed"),
            nullptr);
}

// Waves: the snapshot's water surface is drawn (a segment between each pair of samples) and named.
TEST(LiveFrame, WaterSurfaceLineAndLegend) {
  LiveFrameInput in = StraightLive();
  in.surface = true;
  for (int i = 0; i < 9; ++i) {
    in.snapshot.surface_x.push_back(in.x_min + (in.x_max - in.x_min) * i / 8);
    in.snapshot.surface_y.push_back(in.y_min + 0.9 * (in.y_max - in.y_min));
  }
  const Theme th = Theme::Dark();
  const Frame f = MakeLiveFrame(in, 1280, 720, Colormap("viridis"), th);
  const FrameLayout L = MakeLiveFrameLayout(in, 1280, 720);
  int line = 0;  // in the plot (the legend's swatch is in the panel's head, above it)
  for (const Shape& s : f.shapes)
    line += s.kind == ShapeKind::kSegment && SameColor(s.color, th.water) &&
            s.a.y >= L.cable.rect.y0;
  EXPECT_EQ(line, 8);
  EXPECT_NE(FindText(f, "water surface"), nullptr);
  EXPECT_EQ(FindText(MakeLiveFrame(StraightLive(), 1280, 720, Colormap("viridis"), th),
                     "water surface"),
            nullptr);
}

TEST(LiveFrame, CloseMarkersKeepTheNewestLabelAndLongLabelsAreCut) {
  LiveFrameInput in = StraightLive();
  in.markers = {{30, "first"}, {30.05, "second"}, {40, std::string(60, 'x')}};
  const Frame frame = MakeLiveFrame(in, 1280, 720, Colormap("viridis"));
  EXPECT_EQ(FindText(frame, "first"), nullptr);  // 0.05 s apart: under a pixel
  EXPECT_NE(FindText(frame, "second"), nullptr);
  EXPECT_NE(FindText(frame, std::string(28, 'x') + "\u2026"), nullptr);
}

TEST(LiveFrame, CableSegmentsCarryTheColourOfTheirTension) {
  const LiveFrameInput in = StraightLive();
  const FrameLayout L = MakeLiveFrameLayout(in, 1280, 720);
  const Colormap map("magma");
  const Frame frame = MakeLiveFrame(in, 1280, 720, map);
  int found = 0;
  for (int j = 0; j < kLinks; ++j) {
    const Vec2f a = L.cable.ToPixel(j, 0), b = L.cable.ToPixel(j + 1, 0);
    const Rgba want = map.Map(in.snapshot.tension[j], 0, kTensionMax);
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
  EXPECT_NEAR(c.rect.width() / (c.x_hi - c.x_lo), c.rect.height() / (c.y_hi - c.y_lo), 1e-4);
  EXPECT_LE(c.x_lo, in.x_min);
  EXPECT_GE(c.x_hi, in.x_max);
}

TEST(LiveFrame, SectionNamesAreCentredInTheirSpans) {
  LiveFrameInput in = StraightLive();
  const FrameLayout L = MakeLiveFrameLayout(in, 1280, 720);
  const Frame frame = MakeLiveFrame(in, 1280, 720, Colormap("viridis"));
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
  in.section_names.clear();  // unnamed: no names, still valid
  const Frame plain = MakeLiveFrame(in, 1280, 720, Colormap("viridis"));
  EXPECT_EQ(FindText(plain, "chain"), nullptr);
}

TEST(LiveFrame, HeaderShowsStatusTimeAndPeak) {
  LiveFrameInput in = StraightLive();
  in.range_locked = true;
  const Frame frame = MakeLiveFrame(in, 1920, 1080, Colormap("viridis"));
  EXPECT_NE(FindText(frame, "Straight test cable"), nullptr);
  EXPECT_NE(FindText(frame, "live \u00b7 2.0x"), nullptr);
  EXPECT_NE(FindText(frame, "t = 40.00 s"), nullptr);
  EXPECT_NE(FindText(frame, "peak 39.00 kN at t = 3.25 s, link 19"), nullptr);
  EXPECT_NE(FindText(frame, "tension [kN], locked"), nullptr);
  in.range_locked = false;
  const Frame free = MakeLiveFrame(in, 1920, 1080, Colormap("viridis"));
  EXPECT_NE(FindText(free, "tension [kN]"), nullptr);
  EXPECT_EQ(FindText(free, "tension [kN], locked"), nullptr);
}

TEST(LiveFrame, InconsistentInputThrows) {
  const std::vector<std::pair<const char*, std::function<void(LiveFrameInput&)>>> bad = {
      {"short tension", [](LiveFrameInput& in) { in.snapshot.tension.pop_back(); }},
      {"short x", [](LiveFrameInput& in) { in.snapshot.x.pop_back(); }},
      {"NaN station", [](LiveFrameInput& in) { in.snapshot.y[3] = NAN; }},
      {"companion", [](LiveFrameInput& in) { in.snapshot.cx = in.snapshot.x; }},
      {"names", [](LiveFrameInput& in) { in.section_names.push_back("extra"); }},
      {"envelope", [](LiveFrameInput& in) { in.link_max.pop_back(); }},
      {"trace", [](LiveFrameInput& in) { in.max_tension.pop_back(); }},
      {"equilibrium", [](LiveFrameInput& in) { in.equilibrium.x.pop_back(); }},
      {"moving end", [](LiveFrameInput& in) { in.moving_ends = {kLinks + 1}; }},
      {"peak link", [](LiveFrameInput& in) { in.peak_link = kLinks; }},
      {"window", [](LiveFrameInput& in) { in.window_end = in.window_start; }},
      {"range", [](LiveFrameInput& in) { in.tension_max = in.tension_min; }},
      {"box", [](LiveFrameInput& in) { in.x_max = INFINITY; }},
      {"stations", [](LiveFrameInput& in) { in.arc_length.resize(1); }},
  };
  for (const auto& [what, spoil] : bad) {
    LiveFrameInput in = StraightLive();
    spoil(in);
    EXPECT_THROW(MakeLiveFrame(in, 640, 360, Colormap("viridis")), Error) << what;
  }
  // Optional series may be empty.
  LiveFrameInput in = StraightLive();
  in.link_min.clear();
  in.link_max.clear();
  in.times.clear();
  in.max_tension.clear();
  in.equilibrium = CableSnapshot{};
  in.end_paths.clear();
  in.markers.clear();
  EXPECT_NO_THROW(MakeLiveFrame(in, 640, 360, Colormap("viridis")));
}

TEST(LiveFrame, CostPerFrameIsBoundedByThePixels) {
  // A day of samples at 1 kHz squeezed into the window: the trace keeps two points per column.
  LiveFrameInput in = StraightLive();
  in.times.clear();
  in.max_tension.clear();
  for (int i = 0; i < 600000; ++i) {
    in.times.push_back(10 + i * 1e-4);
    in.max_tension.push_back(kTensionMax * (0.5 + 0.4 * std::sin(i * 0.01)));
  }
  const FrameLayout L = MakeLiveFrameLayout(in, 1280, 720);
  const Frame frame = MakeLiveFrame(in, 1280, 720, Colormap("viridis"));
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
TEST(FrameLayoutFit, CablePanelWidthFollowsTheBoxShape) {
  for (auto [w, h] : {std::pair{1920, 1080}, std::pair{1280, 720}, std::pair{640, 360}}) {
    LiveFrameInput in = StraightLive();
    in.x_min = -1;
    in.x_max = 83;
    in.y_min = -12;
    in.y_max = 35;
    const FrameLayout L = MakeLiveFrameLayout(in, w, h);
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

    in.x_min = 0;
    in.x_max = 400;
    in.y_min = -5;
    in.y_max = 5;
    const FrameLayout flat = MakeLiveFrameLayout(in, w, h);
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

// A steady layout_aspect fixes the panels while the box changes.
TEST(FrameLayoutFit, LayoutAspectKeepsPanelsStill) {
  LiveFrameInput in = StraightLive();
  in.layout_aspect = 1.8;
  in.x_min = -1;
  in.x_max = 83;
  in.y_min = -12;
  in.y_max = 35;
  const FrameLayout a = MakeLiveFrameLayout(in, 1280, 720);
  in.y_max = 25;
  const FrameLayout b = MakeLiveFrameLayout(in, 1280, 720);
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
  const FilmSpec spec = MakeDemoSpec(60);
  FilmHistory history(spec);
  CableSnapshot s;
  for (int i = 0; i <= 300; ++i) {
    s = MakeDemoSnapshot(spec, i / 10.0);
    history.Add(s);
  }
  // The demo with a companion cable (a copy 1 m lower, 10 % more tension) names both cables:
  // its legends take second rows.
  FilmSpec both = spec;
  both.label = "elastic";
  both.companion_label = "inextensible";
  both.companion_equilibrium = spec.equilibrium;
  both.y_min -= 1;
  CableSnapshot sc = s;
  sc.cx = s.x;
  sc.cy = s.y;
  for (double& y : sc.cy) y -= 1;
  sc.ctension = s.tension;
  for (double& T : sc.ctension) T *= 1.1;
  FilmHistory both_history(both);
  both_history.Add(sc);
  const FilmSpec straight = testing::StraightCompanionSpec();  // flat: the stacked layout
  FilmHistory straight_history(straight);
  const CableSnapshot ss = testing::StraightCompanionSnapshot(1);
  straight_history.Add(ss);
  for (auto [w, h] : {std::pair{1920, 1080}, std::pair{1280, 720}, std::pair{640, 360}}) {
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    ExpectNoTextOverlaps(MakeFrame(spec, history, s, MakeFrameLayout(spec, w, h), Colormap("viridis")),
                         "film " + size);
    ExpectNoTextOverlaps(MakeFrame(both, both_history, sc, MakeFrameLayout(both, w, h),
                                   Colormap("viridis")),
                         "film with companion " + size);
    ExpectNoTextOverlaps(MakeFrame(straight, straight_history, ss,
                                   MakeFrameLayout(straight, w, h), Colormap("viridis")),
                         "flat film with companion " + size);
    ExpectNoTextOverlaps(MakeLiveFrame(StraightLive(), w, h, Colormap("viridis")), "live " + size);
  }
}

}  // namespace
}  // namespace cablefilm
