#include "run/welch_spectrum.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <string>

#include "core/error.h"

namespace cablefilm {
namespace {

// FFTW's planner is not thread-safe (fftw_execute is): the Python module's sweep runs cases on
// threads, each making its plans.
std::mutex& PlannerMutex() {
  static std::mutex m;
  return m;
}

}  // namespace

WelchSpectrum::WelchSpectrum(int segment, double dt, double mean)
    : segment_(segment), dt_(dt), mean_(mean) {
  if (segment < 4 || (segment & (segment - 1)) != 0 || segment > kMaxSegment)
    throw Error("internal: a Welch segment of " + std::to_string(segment) +
                " samples; expected a power of two from 4 to " + std::to_string(kMaxSegment));
  const std::size_t n = static_cast<std::size_t>(segment);
  window_.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    window_[j] = 0.5 * (1 - std::cos(2 * M_PI * static_cast<double>(j) / segment));
    window_power_ += window_[j] * window_[j];
  }
  ring_.assign(n, 0.0);
  sum_.assign(n / 2 + 1, 0.0);
  std::lock_guard<std::mutex> lock(PlannerMutex());
  in_ = fftw_alloc_real(n);
  fftw_complex* out = fftw_alloc_complex(n / 2 + 1);
  out_ = out;
  if (in_ && out)
    plan_ = fftw_plan_dft_r2c_1d(segment, in_, out, FFTW_ESTIMATE);
  if (!plan_) {
    fftw_free(in_);
    fftw_free(out);
    throw Error("cannot make an FFT plan of " + std::to_string(segment) + " samples");
  }
}

WelchSpectrum::~WelchSpectrum() {
  std::lock_guard<std::mutex> lock(PlannerMutex());
  fftw_destroy_plan(static_cast<fftw_plan>(plan_));
  fftw_free(in_);
  fftw_free(out_);
}

void WelchSpectrum::Add(double x) {
  ring_[static_cast<std::size_t>(added_ % segment_)] = x - mean_;
  ++added_;
  // A segment ends every L / 2 samples from the L-th on.
  if (added_ >= segment_ && (added_ - segment_) % (segment_ / 2) == 0) Transform();
}

void WelchSpectrum::Transform() {
  const long first = added_ - segment_;  // the segment's first sample, oldest in the ring
  for (int j = 0; j < segment_; ++j)
    in_[j] = window_[static_cast<std::size_t>(j)] *
             ring_[static_cast<std::size_t>((first + j) % segment_)];
  fftw_execute(static_cast<fftw_plan>(plan_));
  const fftw_complex* out = static_cast<const fftw_complex*>(out_);
  for (std::size_t k = 0; k < sum_.size(); ++k)
    sum_[k] += out[k][0] * out[k][0] + out[k][1] * out[k][1];
  ++segments_;
}

double WelchSpectrum::frequency(int k) const { return k / (segment_ * dt_); }

double WelchSpectrum::density(int k) const {
  if (segments_ == 0) return 0;
  const bool edge = k == 0 || k == segment_ / 2;  // f = 0 and Nyquist: no mirror image
  return (edge ? 1.0 : 2.0) * sum_[static_cast<std::size_t>(k)] * dt_ /
         (window_power_ * segments_);
}

double WelchSpectrum::m0() const {
  double m0 = 0;
  for (int k = 0; k < bins(); ++k) m0 += density(k);
  return m0 / (segment_ * dt_);
}

int WelchSpectrum::SegmentFor(long samples) {
  if (samples < 8) return 0;
  const long target = std::max(samples / 8, std::min(16L, samples));
  int segment = 4;
  while (segment * 2L <= target && segment * 2 <= kMaxSegment) segment *= 2;
  return segment;
}

}  // namespace cablefilm
