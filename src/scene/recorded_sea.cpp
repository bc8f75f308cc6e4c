#include "scene/recorded_sea.h"

#include <fftw3.h>

#include <cmath>
#include <memory>
#include <string>

#include "core/error.h"
#include "core/waves.h"

namespace cablefilm {
namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

SeaComponents RecordComponents(const std::vector<double>& times, const std::vector<double>& eta,
                               double x0, double z0, double heading, double gravity,
                               double depth, double band_lo, double band_hi) {
  const int n = static_cast<int>(times.size());
  if (n < 4 || eta.size() != times.size())
    throw Error("a recorded elevation needs at least 4 rows, got " + std::to_string(n));
  const double dt = (times.back() - times.front()) / (n - 1);  // [s]
  for (int i = 1; i < n; ++i)
    if (!(std::abs(times[i] - times[i - 1] - dt) <= 1e-6 * dt))
      throw Error("a recorded elevation needs equally spaced times: rows " + std::to_string(i) +
                  " and " + std::to_string(i + 1) + " are " +
                  std::to_string(times[i] - times[i - 1]) + " s apart, the record's mean step " +
                  std::to_string(dt) + " s");
  // X_j = sum_n (eta_n - mean) e^{-2 pi i j n / N}: eta_n - mean = sum_j A_j cos(omega_j (t_n -
  // t_0) + psi_j), omega_j = 2 pi j / (N dt), A_j = 2 |X_j| / N (|X_j| / N at Nyquist).
  double mean = 0;
  for (double e : eta) mean += e;
  mean /= n;
  std::vector<double> in(eta);
  for (double& e : in) e -= mean;
  const int m = n / 2 + 1;
  std::unique_ptr<fftw_complex, decltype(&fftw_free)> out(
      static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * m)), &fftw_free);
  if (!out) throw Error("no memory for the record's Fourier transform");
  fftw_plan plan = fftw_plan_dft_r2c_1d(n, in.data(), out.get(), FFTW_ESTIMATE);
  fftw_execute(plan);
  fftw_destroy_plan(plan);
  SeaComponents sea;
  const double span = n * dt;  // the period of the sum [s]
  sea.frequency_step = 2.0 * kPi / span;
  sea.repeat_period = span;
  double largest = 0;
  std::vector<double> amplitude(m, 0.0), psi(m, 0.0);
  for (int j = 1; j < m; ++j) {
    const double re = out.get()[j][0], im = out.get()[j][1];
    const bool nyquist = n % 2 == 0 && j == n / 2;
    amplitude[j] = (nyquist ? 1.0 : 2.0) * std::hypot(re, im) / n;
    psi[j] = std::atan2(im, re);
    largest = std::max(largest, amplitude[j]);
  }
  const double along = std::cos(heading) * x0 + std::sin(heading) * z0;  // e . x0 [m]
  const auto kept = [&](int j) {
    const double w = j * sea.frequency_step;
    return amplitude[j] > 1e-9 * largest && (band_hi <= 0 || (w >= band_lo && w <= band_hi));
  };
  int count = 0;
  for (int j = 1; j < m; ++j) count += kept(j);
  if (count > kMaxSeaComponents)
    throw Error("the record makes " + std::to_string(count) + " components (one every " +
                std::to_string(sea.frequency_step) + " rad/s up to " +
                std::to_string((m - 1) * sea.frequency_step) + " rad/s), more than " +
                std::to_string(kMaxSeaComponents) +
                "; expected a band = [lowest, highest] (rad/s) that keeps at most that many, "
                "or a shorter or coarser record");
  for (int j = 1; j < m; ++j) {
    if (!kept(j)) continue;
    // a cos(k e.x0 - omega t + phi) = A cos(omega (t - t0) + psi) at x0 for every t:
    // phi = omega t0 - psi - k e . x0.
    const double w = j * sea.frequency_step;
    const double k = WaveNumber(w, gravity, depth);
    sea.Add(amplitude[j], w, w * times.front() - psi[j] - k * along, heading, gravity, depth);
  }
  return sea;
}

}  // namespace cablefilm
