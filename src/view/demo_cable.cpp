#include "view/demo_cable.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {
namespace {
constexpr double kLength = 91.44;          // [m]
constexpr double kEndX = 80.0, kEndY = 30.48, kAmplitude = 1.8288, kPeriod = 10.0;
constexpr double kPi = 3.14159265358979323846;
}  // namespace

Snapshot MakeDemoSnapshot(const SceneView& scene, double t) {
  const int n = static_cast<int>(scene.lines.front().arc_length.size());
  const int s = n - 1;
  Snapshot out;
  out.t = t;
  out.lines.resize(1);
  LineSnapshot& snap = out.lines[0];
  const double w = 2 * kPi / kPeriod;
  const double ramp = 1 - std::exp(-0.5 * t);
  const double ex = kEndX + ramp * kAmplitude * std::sin(w * t);
  const double ey = kEndY + ramp * kAmplitude * (1 - std::cos(w * t));
  const double chord = std::hypot(ex, ey);
  const double sag = 0.45 * std::sqrt(std::max(0.0, kLength * kLength - chord * chord));
  snap.x.resize(n);
  snap.y.resize(n);
  for (int j = 0; j <= s; ++j) {
    const double u = static_cast<double>(j) / s;
    snap.x[j] = u * ex;
    snap.y[j] = u * ey - sag * 4 * u * (1 - u) * (1 - 0.3 * u);
  }
  snap.tension.resize(s);
  for (int j = 0; j < s; ++j) {
    const double u = (j + 0.5) / s;
    const double height = 0.5 * (snap.y[j] + snap.y[j + 1]);
    const double wave = std::sin(w * t - 2.5 * u) * (0.4 + 0.6 * u);
    snap.tension[j] = std::max(0.0, 9000 + 260 * height + 9000 * ramp * wave - 15 * sag * sag);
  }
  return out;
}

SceneView MakeDemoScene(int segments) {
  SceneView scene;
  scene.title = "Sample mooring line, Polachek et al. 1963 (synthetic)";
  scene.lines.resize(1);
  LineView& line = scene.lines[0];
  const int n = segments + 1;
  for (int j = 0; j < n; ++j) line.arc_length.push_back(kLength * j / segments);
  line.section_boundaries = {45.72};
  line.section_names = {"wire", "nylon"};
  line.marks.weights = {static_cast<int>(std::lround(27.432 / kLength * segments))};
  line.marks.fixed_ends = {0};
  line.marks.moving_ends = {segments};
  line.reference = MakeDemoSnapshot(scene, 0).lines[0];
  return scene;
}

FixedPolicy MakeDemoPolicy(double duration) {
  FixedPolicy policy;
  policy.duration = duration;
  policy.tension_min = 0;
  policy.tension_max = 30000;
  policy.box = {-1, kEndX + kAmplitude + 1, -12, kEndY + 2 * kAmplitude + 1};
  return policy;
}

}  // namespace cablefilm
