#include "core/sea_spectrum.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {
namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

double DnvJonswapGamma(double hs, double tp) {
  const double r = tp / std::sqrt(hs);  // [s / m^0.5]
  if (r <= 3.6) return 5.0;
  if (r >= 5.0) return 1.0;
  return std::exp(5.75 - 1.15 * r);
}

double SpectralDensity(const SpectrumSpec& s, double omega) {
  if (!(omega > 0)) return 0.0;
  if (s.kind == SpectrumKind::kTable) {
    const std::vector<double>& w = s.omega;
    if (w.empty() || omega < w.front() || omega > w.back()) return 0.0;
    const auto it = std::upper_bound(w.begin(), w.end(), omega);
    if (it == w.end()) return s.density.back();
    const std::size_t i = static_cast<std::size_t>(it - w.begin());  // w[i-1] <= omega < w[i]
    const double f = (omega - w[i - 1]) / (w[i] - w[i - 1]);
    return s.density[i - 1] + f * (s.density[i] - s.density[i - 1]);
  }
  const double wp = 2.0 * kPi / s.tp;  // omega_p [rad/s]
  const double r = wp / omega, r4 = r * r * r * r;
  // S_PM = 5/16 Hs^2 omega_p^4 omega^-5 exp(-5/4 (omega_p / omega)^4): written as
  // 5/16 Hs^2 r^4 / omega e^{..} (no omega^-5 overflow at small omega: the exponential wins).
  const double pm = 5.0 / 16.0 * s.hs * s.hs * r4 / omega * std::exp(-1.25 * r4);
  if (s.kind == SpectrumKind::kPiersonMoskowitz || s.gamma == 1.0) return pm;
  const double sigma = omega <= wp ? 0.07 : 0.09;
  const double d = (omega - wp) / (sigma * wp);
  const double a_gamma = 1.0 - 0.287 * std::log(s.gamma);
  return a_gamma * pm * std::pow(s.gamma, std::exp(-0.5 * d * d));
}

double SpectrumArea(const SpectrumSpec& s, double lo, double hi, int intervals) {
  if (!(hi > lo)) return 0.0;
  intervals += intervals % 2;
  const double h = (hi - lo) / intervals;
  double sum = SpectralDensity(s, lo) + SpectralDensity(s, hi);
  for (int i = 1; i < intervals; ++i) sum += (i % 2 ? 4.0 : 2.0) * SpectralDensity(s, lo + i * h);
  return sum * h / 3.0;
}

Band EnergyBand(const SpectrumSpec& s, double tail) {
  // The cumulative area on a fine grid over where the density lives: a table's span, or for the
  // formulas 0.1 to 20 omega_p (below 0.3 omega_p S_PM is under e^-150 of its peak, above
  // 20 omega_p the omega^-5 tail holds 2e-6 of m0).
  double lo, hi;
  if (s.kind == SpectrumKind::kTable) {
    lo = s.omega.front();
    hi = s.omega.back();
  } else {
    const double wp = 2.0 * kPi / s.tp;
    lo = 0.1 * wp;
    hi = 20.0 * wp;
  }
  constexpr int kCells = 20000;
  std::vector<double> cumulative(kCells + 1, 0.0);
  const double h = (hi - lo) / kCells;
  for (int i = 0; i < kCells; ++i)
    cumulative[i + 1] = cumulative[i] + SpectrumArea(s, lo + i * h, lo + (i + 1) * h, 2);
  const double total = cumulative.back();
  Band band{lo, hi};
  if (!(total > 0)) return band;
  // Linear within the cell where the cumulative area crosses each quantile.
  auto at = [&](double q) {
    const double target = q * total;
    const auto it = std::lower_bound(cumulative.begin(), cumulative.end(), target);
    const long i = std::clamp<long>(it - cumulative.begin(), 1, kCells);
    const double c0 = cumulative[i - 1], c1 = cumulative[i];
    const double f = c1 > c0 ? (target - c0) / (c1 - c0) : 0.0;
    return lo + (i - 1 + f) * h;
  };
  band.lo = at(0.5 * tail);
  band.hi = at(1.0 - 0.5 * tail);
  return band;
}

}  // namespace cablefilm
