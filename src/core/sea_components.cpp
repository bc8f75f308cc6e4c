#include "core/sea_components.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "core/waves.h"

namespace cablefilm {
namespace {
constexpr double kPi = 3.14159265358979323846;

// A double uniform in [0, 1) from the generator's top 53 bits: the same on every platform
// (std::uniform_real_distribution is not).
double Uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace

double SeaComponents::Variance() const {
  double m0 = 0;
  for (double a : amplitude) m0 += 0.5 * a * a;
  return m0;
}

double SeaComponents::SignificantHeight() const { return 4.0 * std::sqrt(Variance()); }

double SeaComponents::ShortestLength() const {
  double kmax = 0;
  for (double ki : k) kmax = std::max(kmax, ki);
  return kmax > 0 ? 2.0 * kPi / kmax : 0.0;
}

void SeaComponents::Add(double a, double w, double phi, double heading, double g, double h) {
  const double ki = WaveNumber(w, g, h);
  amplitude.push_back(a);
  omega.push_back(w);
  k.push_back(ki);
  phase.push_back(phi);
  dir_x.push_back(std::cos(heading));
  dir_z.push_back(std::sin(heading));
  decay.push_back(std::exp(-2.0 * ki * h));
  decay_gap.push_back(-std::expm1(-2.0 * ki * h));
  max_omega = std::max(max_omega, w);
  max_k = std::max(max_k, ki);
}

namespace {

// The cumulative weight of cos^{2s}(b / 2) on [-pi, pi] at kCells + 1 equally spaced angles
// (trapezoids: the power is smooth, so 4096 cells hold it to ~1e-7).
constexpr int kSpreadCells = 4096;
std::vector<double> SpreadingCumulative(double s) {
  std::vector<double> c(kSpreadCells + 1, 0.0);
  const double h = 2.0 * kPi / kSpreadCells;
  auto d = [&](double b) { return std::pow(std::cos(0.5 * b), 2.0 * s); };
  for (int i = 0; i < kSpreadCells; ++i) {
    const double b = -kPi + i * h;
    c[i + 1] = c[i] + 0.5 * h * (d(b) + d(b + h));
  }
  return c;
}

// The angle [rad] below which a share u of the weight lies: linear within the cell.
double InvertSpreading(const std::vector<double>& c, double u) {
  const double h = 2.0 * kPi / kSpreadCells;
  const double target = std::clamp(u, 0.0, 1.0) * c.back();
  const auto it = std::lower_bound(c.begin(), c.end(), target);
  const long i = std::clamp<long>(it - c.begin(), 1, kSpreadCells);
  const double f = c[i] > c[i - 1] ? (target - c[i - 1]) / (c[i] - c[i - 1]) : 0.5;
  return -kPi + (i - 1 + f) * h;
}

}  // namespace

double SpreadingAngle(double s, double u) { return InvertSpreading(SpreadingCumulative(s), u); }

SeaComponents SpectrumComponents(const SpectrumSpec& spectrum, const SeaDiscretization& d,
                                 double gravity, double depth) {
  Band band{d.band_lo, d.band_hi};
  if (!(band.hi > band.lo)) band = EnergyBand(spectrum, 1e-3);
  SeaComponents sea;
  const int n = std::max(d.components, 1);
  const double dw = (band.hi - band.lo) / n;  // [rad/s]
  sea.frequency_step = dw;
  sea.repeat_period = 2.0 * kPi / dw;
  std::mt19937_64 rng(d.seed);
  // The spreading's cumulative weight, tabulated once.
  std::vector<double> spread;
  if (d.spreading > 0) spread = SpreadingCumulative(d.spreading);
  for (int i = 0; i < n; ++i) {
    // Three draws a component, always in this order (the same seed: the same sea).
    const double u_frequency = Uniform(rng), u_phase = Uniform(rng), u_direction = Uniform(rng);
    const double lo = band.lo + i * dw, hi = lo + dw;
    const double variance = SpectrumArea(spectrum, lo, hi, 16);  // int_bin S [m^2]
    if (!(variance > 0)) continue;
    const double w = lo + u_frequency * dw;
    double heading = d.heading;
    if (!spread.empty()) heading += InvertSpreading(spread, u_direction);
    sea.Add(std::sqrt(2.0 * variance), w, 2.0 * kPi * u_phase, heading, gravity, depth);
  }
  return sea;
}

}  // namespace cablefilm
