#pragma once
// A small, exactly known scene for the render tests: a straight horizontal cable of 20 links
// of 1 m from (0, 0) to (20, 0), tensions rising linearly across the colour range.
#include <cmath>
#include <filesystem>
#include <string>

#include "view/history.h"
#include "view/scene_view.h"
#include "view/snapshot.h"

namespace cablefilm::testing {

constexpr int kLinks = 20;
constexpr double kTensionMax = 40000;  // [N]

// One line; its reference 1 m below the cable (y = -1) at a quarter of the maximum.
inline SceneView StraightScene() {
  SceneView scene;
  scene.title = "Straight test cable";
  scene.lines.resize(1);
  LineView& line = scene.lines[0];
  for (int j = 0; j <= kLinks; ++j) line.arc_length.push_back(j);
  line.section_boundaries = {10};
  line.marks.weights = {5};
  line.marks.fixed_ends = {0};
  line.marks.moving_ends = {kLinks};
  for (int j = 0; j <= kLinks; ++j) {
    line.reference.x.push_back(j);
    line.reference.y.push_back(-1);
  }
  line.reference.tension.assign(kLinks, 0.25 * kTensionMax);
  return scene;
}

// The film's: 10 s, the colour range 0 to kTensionMax, the box x 0..20 m, y -2..2 m.
inline FixedPolicy StraightPolicy() {
  FixedPolicy policy;
  policy.duration = 10;
  policy.tension_min = 0;
  policy.tension_max = kTensionMax;
  policy.box = {0, kLinks, -2, 2};
  return policy;
}

// Link j carries (j + 0.5) / kLinks of the maximum: colours sweep the whole map.
inline LineSnapshot StraightLine() {
  LineSnapshot s;
  for (int j = 0; j <= kLinks; ++j) {
    s.x.push_back(j);
    s.y.push_back(0);
  }
  for (int j = 0; j < kLinks; ++j) s.tension.push_back((j + 0.5) / kLinks * kTensionMax);
  return s;
}
inline Snapshot StraightSnapshot(double t) {
  Snapshot s;
  s.t = t;
  s.lines = {StraightLine()};
  return s;
}

// The straight scene with a second line 1.5 m above the first (y = 1.5), its tensions running
// the other way: link j carries (kLinks - j - 0.5) / kLinks of the maximum. The lines are
// named "elastic" and "inextensible"; the second's reference tension is 0.3 of the maximum.
constexpr double kSecondY = 1.5;  // [m]
inline SceneView StraightPairScene() {
  SceneView scene = StraightScene();
  scene.lines[0].label = "elastic";
  scene.lines.push_back(scene.lines[0]);
  scene.lines[1].label = "inextensible";
  scene.lines[1].reference.tension.assign(kLinks, 0.3 * kTensionMax);
  return scene;
}
inline Snapshot StraightPairSnapshot(double t) {
  Snapshot s = StraightSnapshot(t);
  LineSnapshot second;
  for (int j = 0; j <= kLinks; ++j) {
    second.x.push_back(j);
    second.y.push_back(kSecondY);
  }
  for (int j = 0; j < kLinks; ++j)
    second.tension.push_back((kLinks - j - 0.5) / kLinks * kTensionMax);
  s.lines.push_back(second);
  return s;
}

inline std::string OutputDir(const std::string& name) {
  const auto dir = std::filesystem::path(CABLEFILM_BINARY_DIR) / "test_output" / "render" / name;
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace cablefilm::testing
