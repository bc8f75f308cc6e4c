// Issue 11, defect 11: what the film claims. Its time plot takes every output row the
// snapshots carry (so a peak between frames is drawn and its peak is the rows'), thinned at a
// bounded cost without losing an extreme; the dashed reference is named for what it is; the
// ends are named by their role.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.h"
#include "view/frame_builder.h"
#include "view/time_trace.h"
#include "test_scene.h"

namespace cablefilm {
namespace {

using testing::kLinks;
using testing::kTensionMax;

// A repeatable rough signal with one spike: sample i of n.
double Signal(long i) {
  std::uint64_t x = static_cast<std::uint64_t>(i) * 6364136223846793005ull + 1442695040888963407ull;
  x ^= x >> 29;
  const double noise = static_cast<double>(x % 100000) / 100000.0;  // [0, 1)
  return i == 123457 ? 9000.0 : 1000 + 500 * std::sin(i * 1e-4) + 200 * noise;
}

TEST(ThinnedTrace, KeepsEveryExtremeAtABoundedCost) {
  const long n = 1000000;
  const double dt = 1e-4;  // 100 s of samples
  ThinnedTrace trace(1, 100.0 / 1000);  // 1000 spans
  double max = -INFINITY, min = INFINITY, max_t = 0, min_t = 0;
  for (long i = 0; i < n; ++i) {
    const double v = Signal(i);
    trace.Add(i * dt, v);
    if (v > max) max = v, max_t = i * dt;
    if (v < min) min = v, min_t = i * dt;
  }
  EXPECT_EQ(trace.added(), n);
  EXPECT_LE(trace.size(), 3u * 1001);  // smallest, largest and last of each span
  EXPECT_GE(trace.size(), 2u * 1000);
  const auto& t = trace.times();
  const auto& v = trace.values();
  EXPECT_TRUE(std::is_sorted(t.begin(), t.end()));
  // Every point kept is a sample as added.
  for (std::size_t k = 0; k < t.size(); ++k) {
    const long i = std::lround(t[k] / dt);
    ASSERT_EQ(t[k], i * dt);
    ASSERT_EQ(v[k], Signal(i)) << "at t = " << t[k];
  }
  const auto top = std::max_element(v.begin(), v.end());
  const auto bottom = std::min_element(v.begin(), v.end());
  EXPECT_EQ(*top, 9000.0);
  EXPECT_EQ(*top, max);
  EXPECT_EQ(t[top - v.begin()], max_t);
  EXPECT_EQ(*bottom, min);
  EXPECT_EQ(t[bottom - v.begin()], min_t);
  EXPECT_EQ(t.back(), (n - 1) * dt);  // the newest sample is the last point
}

TEST(ThinnedTrace, TwoChannelsStayAlignedAndSpanZeroKeepsAll) {
  ThinnedTrace trace(2, 1.0);
  for (int i = 0; i < 1000; ++i) {  // 10 spans of 100 samples; the second channel from i = 500
    const double values[2] = {Signal(i), i < 500 ? NAN : 2 * Signal(i + 7)};
    trace.Add(i * 0.01, values);
  }
  ASSERT_EQ(trace.values(0).size(), trace.size());
  ASSERT_EQ(trace.values(1).size(), trace.size());
  double max1 = -INFINITY;
  for (std::size_t k = 0; k < trace.size(); ++k) {
    const long i = std::lround(trace.times()[k] / 0.01);
    ASSERT_EQ(trace.values(0)[k], Signal(i));
    if (i < 500)
      ASSERT_TRUE(std::isnan(trace.values(1)[k]));
    else
      ASSERT_EQ(trace.values(1)[k], 2 * Signal(i + 7));
    if (!std::isnan(trace.values(1)[k])) max1 = std::max(max1, trace.values(1)[k]);
  }
  double want = -INFINITY;
  for (int i = 500; i < 1000; ++i) want = std::max(want, 2 * Signal(i + 7));
  EXPECT_EQ(max1, want);
  EXPECT_LE(trace.size(), 10u * 5);

  ThinnedTrace all(1, 0);
  for (int i = 0; i < 100; ++i) all.Add(i * 0.5, Signal(i));
  ASSERT_EQ(all.size(), 100u);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(all.values()[i], Signal(i));
}

// A channel a line: three lines thinned together keep each one's extremes at their times.
TEST(ThinnedTrace, AnyNumberOfChannels) {
  ThinnedTrace trace(3, 1.0);
  double max[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (int i = 0; i < 1000; ++i) {
    const double values[3] = {Signal(i), 2 * Signal(i + 7), 3 * Signal(i + 13)};
    trace.Add(i * 0.01, values);
    for (int c = 0; c < 3; ++c) max[c] = std::max(max[c], values[c]);
  }
  ASSERT_EQ(trace.all_values().size(), 3u);
  EXPECT_LE(trace.size(), 10u * 7);  // smallest and largest of each channel, and the last
  for (int c = 0; c < 3; ++c) {
    ASSERT_EQ(trace.values(c).size(), trace.size());
    EXPECT_EQ(*std::max_element(trace.values(c).begin(), trace.values(c).end()), max[c]) << c;
    for (std::size_t k = 0; k < trace.size(); ++k) {  // each point a sample as added
      const long i = std::lround(trace.times()[k] / 0.01);
      ASSERT_EQ(trace.values(c)[k], (c + 1) * Signal(i + (c == 0 ? 0 : c == 1 ? 7 : 13)));
    }
  }
  EXPECT_THROW(ThinnedTrace(0, 1.0), Error);
}

// Two film frames (t = 0 and 1 s) of the straight test cable, the second carrying the rows of
// every 0.1 s since the first, one of them (t = 0.4 s) at 55 kN, above either frame's 39 kN.
TEST(FilmHistory, RowsBetweenFramesReachTheTimePlotAndTheEnvelope) {
  const SceneView scene = testing::StraightScene();
  const double frame_peak = (kLinks - 0.5) / kLinks * kTensionMax;  // 39 kN
  History history(scene, testing::StraightPolicy());
  Snapshot first = testing::StraightSnapshot(0);
  first.row_t = {0};
  first.lines[0].row_max = {frame_peak};
  history.Add(first);
  Snapshot second = testing::StraightSnapshot(1);
  LineSnapshot& line = second.lines[0];
  for (int i = 1; i <= 10; ++i) {
    second.row_t.push_back(i * 0.1);
    line.row_max.push_back(i == 4 ? 55000 : 30000 + 100 * i);
  }
  line.row_link_min.assign(kLinks, 0);
  line.row_link_max = line.tension;
  line.row_link_max[3] = 55000;  // link 3 carried the peak at t = 0.4 s
  history.Add(second);
  EXPECT_EQ(history.count(), 2);
  EXPECT_EQ(history.peak(), 55000);
  EXPECT_DOUBLE_EQ(history.peak_t(), 0.4);
  EXPECT_EQ(history.peak_link(), 3);  // the link of the rows' envelope
  ASSERT_EQ(history.times().size(), 11u);  // every row (the spans of 10 s / 8192 hold one each)
  EXPECT_EQ(history.max_tension()[0][4], 55000);
  EXPECT_EQ(history.link_max()[3], 55000);
  EXPECT_EQ(history.link_min()[3], 0);
  // The plot's readout says so: before, it read the frames' 39.00 kN.
  const Frame frame = MakeFrame(scene, history, second, MakeFrameLayout(scene, history, 1280, 720),
                                Colormap("viridis"));
  bool note = false;
  for (const TextItem& t : frame.texts) note |= t.text.find("peak 55.00 kN") != std::string::npos;
  EXPECT_TRUE(note);
  // Rows and their maxima must pair up.
  Snapshot bad = testing::StraightSnapshot(2);
  bad.row_t = {1.5, 2};
  bad.lines[0].row_max = {1};
  EXPECT_THROW(history.Add(bad), Error);
}

std::vector<std::string> Texts(const Frame& f) {
  std::vector<std::string> texts;
  for (const TextItem& t : f.texts) texts.push_back(t.text);
  return texts;
}
long CountText(const std::vector<std::string>& texts, const std::string& s) {
  return std::count(texts.begin(), texts.end(), s);
}

TEST(MakeFrame, StraightStartAndEndsAreNamedForWhatTheyAre) {
  // A straight start: the dashed reference is the initial state, not an equilibrium; the start
  // is fixed, the end free (a towed or dangling end): no "anchor", no "moving end".
  SceneView scene = testing::StraightScene();
  scene.reference_label = kStraightStateLabel;
  scene.lines[0].marks.moving_ends.clear();
  scene.lines[0].marks.free_ends = {kLinks};
  History history(scene, testing::StraightPolicy());
  const Snapshot snap = testing::StraightSnapshot(1);
  history.Add(snap);
  const std::vector<std::string> texts = Texts(MakeFrame(
      scene, history, snap, MakeFrameLayout(scene, history, 1920, 1080), Colormap("viridis")));
  // The cable's legend, the tension plot's legend and the time plot's dashed line.
  EXPECT_EQ(CountText(texts, "initial state (straight)"), 3);
  EXPECT_EQ(CountText(texts, "equilibrium"), 0);
  EXPECT_EQ(CountText(texts, "fixed end"), 1);
  EXPECT_EQ(CountText(texts, "free end"), 1);
  EXPECT_EQ(CountText(texts, "anchor"), 0);
  EXPECT_EQ(CountText(texts, "moving end"), 0);

  // The usual case: an equilibrium start, a fixed start and a driven end.
  const SceneView usual = testing::StraightScene();
  History h2(usual, testing::StraightPolicy());
  h2.Add(snap);
  const std::vector<std::string> t2 =
      Texts(MakeFrame(usual, h2, snap, MakeFrameLayout(usual, h2, 1920, 1080),
                      Colormap("viridis")));
  EXPECT_EQ(CountText(t2, "equilibrium"), 3);
  EXPECT_EQ(CountText(t2, "fixed end"), 1);
  EXPECT_EQ(CountText(t2, "moving end"), 1);
  EXPECT_EQ(CountText(t2, "free end"), 0);
  EXPECT_EQ(CountText(t2, "anchor"), 0);
}

}  // namespace
}  // namespace cablefilm
