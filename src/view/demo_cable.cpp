#include "view/demo_cable.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {
namespace {
constexpr double kLength = 91.44;          // [m]
constexpr double kEndX = 80.0, kEndY = 30.48, kAmplitude = 1.8288, kPeriod = 10.0;
constexpr double kPi = 3.14159265358979323846;
}  // namespace

CableSnapshot MakeDemoSnapshot(const FilmSpec& spec, double t) {
  const int n = static_cast<int>(spec.arc_length.size());
  const int s = n - 1;
  CableSnapshot snap;
  snap.t = t;
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
  return snap;
}

FilmSpec MakeDemoSpec(double duration, int segments) {
  FilmSpec spec;
  spec.title = "Sample mooring line, Polachek et al. 1963 (synthetic)";
  const int n = segments + 1;
  for (int j = 0; j < n; ++j) spec.arc_length.push_back(kLength * j / segments);
  spec.section_boundaries = {45.72};
  spec.section_names = {"wire", "nylon"};
  spec.weight_stations = {static_cast<int>(std::lround(27.432 / kLength * segments))};
  spec.fixed_ends = {0};
  spec.moving_ends = {segments};
  spec.duration = duration;
  spec.equilibrium = MakeDemoSnapshot(spec, 0);
  spec.tension_min = 0;
  spec.tension_max = 30000;
  spec.x_min = -1;
  spec.x_max = kEndX + kAmplitude + 1;
  spec.y_min = -12;
  spec.y_max = kEndY + 2 * kAmplitude + 1;
  return spec;
}

}  // namespace cablefilm
