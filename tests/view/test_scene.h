#pragma once
// A small, exactly known scene for the render tests: a straight horizontal cable of 20 links
// of 1 m from (0, 0) to (20, 0), tensions rising linearly across the colour range.
#include <cmath>
#include <filesystem>
#include <string>

#include "view/frame.h"

namespace cablefilm::testing {

constexpr int kLinks = 20;
constexpr double kTensionMax = 40000;  // [N]

inline FilmSpec StraightSpec() {
  FilmSpec spec;
  spec.title = "Straight test cable";
  for (int j = 0; j <= kLinks; ++j) spec.arc_length.push_back(j);
  spec.section_boundaries = {10};
  spec.weight_stations = {5};
  spec.fixed_ends = {0};
  spec.moving_ends = {kLinks};
  spec.duration = 10;
  spec.tension_min = 0;
  spec.tension_max = kTensionMax;
  spec.x_min = 0;
  spec.x_max = kLinks;
  spec.y_min = -2;
  spec.y_max = 2;
  spec.equilibrium.t = 0;
  for (int j = 0; j <= kLinks; ++j) {
    spec.equilibrium.x.push_back(j);
    spec.equilibrium.y.push_back(-1);
  }
  spec.equilibrium.tension.assign(kLinks, 0.25 * kTensionMax);
  return spec;
}

// Link j carries (j + 0.5) / kLinks of the maximum: colours sweep the whole map.
inline CableSnapshot StraightSnapshot(double t) {
  CableSnapshot s;
  s.t = t;
  for (int j = 0; j <= kLinks; ++j) {
    s.x.push_back(j);
    s.y.push_back(0);
  }
  for (int j = 0; j < kLinks; ++j) s.tension.push_back((j + 0.5) / kLinks * kTensionMax);
  return s;
}

// The straight scene with a companion cable 1.5 m above the main one (y = 1.5), its tensions
// running the other way: link j carries (kLinks - j - 0.5) / kLinks of the maximum.
constexpr double kCompanionY = 1.5;  // [m]
inline FilmSpec StraightCompanionSpec() {
  FilmSpec spec = StraightSpec();
  spec.label = "elastic";
  spec.companion_label = "inextensible";
  spec.companion_equilibrium = spec.equilibrium;
  spec.companion_equilibrium.tension.assign(kLinks, 0.3 * kTensionMax);
  return spec;
}
inline CableSnapshot StraightCompanionSnapshot(double t) {
  CableSnapshot s = StraightSnapshot(t);
  for (int j = 0; j <= kLinks; ++j) {
    s.cx.push_back(j);
    s.cy.push_back(kCompanionY);
  }
  for (int j = 0; j < kLinks; ++j) s.ctension.push_back((kLinks - j - 0.5) / kLinks * kTensionMax);
  return s;
}

inline std::string OutputDir(const std::string& name) {
  const auto dir = std::filesystem::path(CABLEFILM_BINARY_DIR) / "test_output" / "render" / name;
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace cablefilm::testing
