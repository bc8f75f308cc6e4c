#pragma once
// The spectral density S(omega) [m^2 s/rad] of an irregular sea's surface elevation, one-sided in
// the angular frequency omega [rad/s], so that its area m0 = int S d omega is the elevation's
// variance and Hs = 4 sqrt(m0). Not in the paper. The two forms of DNV-RP-C205 (2010, 3.5.5):
//
//   Pierson-Moskowitz  S_PM(omega) = 5/16 Hs^2 omega_p^4 omega^-5 exp(-5/4 (omega / omega_p)^-4)
//   JONSWAP            S_J(omega)  = A_gamma S_PM(omega) gamma^exp(-(omega - omega_p)^2 /
//                                                               (2 sigma^2 omega_p^2))
//
// omega_p = 2 pi / Tp, sigma = 0.07 for omega <= omega_p and 0.09 above, and DNV's normalising
// factor A_gamma = 1 - 0.287 ln(gamma) (which keeps 4 sqrt(m0) within about 1 % of Hs for gamma
// from 1 to 7); or a table of (omega, S) joined linearly, zero outside it.
#include <vector>

namespace cablefilm {

enum class SpectrumKind { kJonswap, kPiersonMoskowitz, kTable };

struct SpectrumSpec {
  SpectrumKind kind = SpectrumKind::kJonswap;
  double hs = 0;     // significant wave height Hs [m] (the formulas')
  double tp = 1;     // peak period Tp [s] (the formulas')
  double gamma = 1;  // the JONSWAP peak enhancement gamma [1]
  std::vector<double> omega;    // a table's frequencies [rad/s], increasing
  std::vector<double> density;  // and its S [m^2 s/rad] at them, >= 0
};

// DNV-RP-C205's gamma for a JONSWAP sea of Hs [m] and Tp [s] (3.5.5.5): 5 for Tp / sqrt(Hs)
// <= 3.6, exp(5.75 - 1.15 Tp / sqrt(Hs)) up to 5, and 1 beyond (Pierson-Moskowitz).
double DnvJonswapGamma(double hs, double tp);

// S(omega) [m^2 s/rad]; 0 for omega <= 0.
double SpectralDensity(const SpectrumSpec& s, double omega);

// The spectrum's area from omega lo to hi [rad/s] (m^2), by composite Simpson's rule on
// `intervals` (even) intervals.
double SpectrumArea(const SpectrumSpec& s, double lo, double hi, int intervals = 2000);

// The band [lo, hi] [rad/s] that holds all but `tail` of the spectrum's area, `tail` / 2 on
// each side (a table's: where its density is not zero, cut the same way).
struct Band {
  double lo = 0, hi = 0;
};
Band EnergyBand(const SpectrumSpec& s, double tail);

}  // namespace cablefilm
