#pragma once
// An irregular sea as a sum of linear (Airy) components, each a regular wave of its own
// amplitude, frequency, phase and direction (not in the paper):
//
//   eta(x, t) = R(t) sum_i a_i cos(theta_i),  theta_i = k_i e_i . x - omega_i t + phi_i
//
// with omega_i^2 = g k_i tanh(k_i h) (waves.h). Made from a spectrum (sea_spectrum.h) with a
// seed (here), or from a recorded elevation at a reference point (scene/recorded_sea.h). Held by the waves (Wave::sea) and
// shared, never changed once made: the kinematics sum over it (waves.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include "core/sea_spectrum.h"

namespace cablefilm {

// The most components a sea may hold: each costs a cosine, a sine and an exponential per
// station evaluated (waves.components' range; a record's are counted after its band).
constexpr int kMaxSeaComponents = 20000;

struct SeaComponents {
  // One entry per component, as arrays (the kinematics' loop reads them in order).
  std::vector<double> amplitude;  // a_i [m]
  std::vector<double> omega;      // omega_i [rad/s]
  std::vector<double> k;          // k_i [1/m], of the dispersion relation at the depth
  std::vector<double> phase;      // phi_i [rad]
  std::vector<double> dir_x;      // e_i = (dir_x, 0, dir_z): the direction it travels
  std::vector<double> dir_z;
  std::vector<double> decay;      // e^{-2 k_i h} and 1 - e^{-2 k_i h}: the depth profiles'
  std::vector<double> decay_gap;  // constants (as Wave's)
  double frequency_step = 0;      // the bins' width d omega [rad/s] (a record's 2 pi / its span)
  double repeat_period = 0;       // [s]: 2 pi / d omega, after which equally spaced components
                                  // repeat (the drawn frequencies do not; a record's does)
  int size() const { return static_cast<int>(amplitude.size()); }
  double Variance() const;        // m0 = sum a_i^2 / 2 [m^2]
  double SignificantHeight() const;  // Hs = 4 sqrt(m0) [m]
  double ShortestLength() const;  // 2 pi / max k_i [m]: the shortest component's wave length
  double max_omega = 0;           // the largest omega_i [rad/s] and k_i [1/m] (Add keeps them)
  double max_k = 0;
  // Adds a component: amplitude a [m], omega [rad/s], phase [rad], heading [rad] from +x
  // towards +z; its k from the dispersion relation at depth h [m] and gravity g [m/s^2].
  void Add(double a, double omega, double phase, double heading, double g, double h);
};

struct SeaDiscretization {
  int components = 200;      // N: bins of equal width over the band
  double band_lo = 0;        // the band [rad/s]; 0, 0: the spectrum's own, all but 1e-3 of
  double band_hi = 0;        // its area (EnergyBand)
  std::uint64_t seed = 1;    // of the phases, the frequencies within their bins, the directions
  double heading = 0;        // the mean direction [rad] from +x towards +z
  double spreading = 0;      // s of the cos-2s spreading function; 0: long-crested
};

// The components of a spectrum: N bins of equal width d omega over the band; in each, one
// component at a frequency drawn uniformly within the bin (so that the sum does not repeat),
// its amplitude sqrt(2 int_bin S d omega) (the bin's variance exactly), its phase drawn uniformly
// in [0, 2 pi), and with spreading, its direction drawn from D(beta) proportional to
// cos^{2s}((beta - heading) / 2) (one direction per frequency, so that no two components are
// locked in phase). The same seed gives the same components on every machine (mt19937_64 and
// our own mapping to doubles).
SeaComponents SpectrumComponents(const SpectrumSpec& spectrum, const SeaDiscretization& d,
                                 double gravity, double depth);

// The spreading function's inverse distribution: the angle beta - heading [rad] in [-pi, pi]
// below which a share u in [0, 1] of D's weight lies (cos-2s with s > 0).
double SpreadingAngle(double s, double u);

}  // namespace cablefilm
