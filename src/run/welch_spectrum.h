#pragma once
// The one-sided power spectral density of an evenly sampled record by Welch's method: segments
// of L samples overlapping by half, each less a given mean, Hann-windowed and transformed
// (FFTW), their periodograms averaged. Streaming: a sample at a time, L + a window in memory
// (the record is never held); the samples after the last whole segment are not used.
//
// Scaling: S(f_k) = c |X_k|^2 dt / sum(w^2), c = 2 but at f = 0 and at Nyquist (c = 1), with
// f_k = k / (L dt), k = 0..L/2: S in [units^2/Hz], and its integral m0 = sum S df (df = 1 / (L
// dt)) equals the windowed segments' mean square (Parseval), the record's variance about the
// mean subtracted up to the window's weighting of the segments.
#include <vector>

namespace cablefilm {

class WelchSpectrum {
 public:
  // Segments of `segment` samples (a power of two, at least 4) spaced `dt` [s] apart, each less
  // `mean` [units] before its window. Throws Error on a bad segment length.
  WelchSpectrum(int segment, double dt, double mean);
  ~WelchSpectrum();
  WelchSpectrum(const WelchSpectrum&) = delete;
  WelchSpectrum& operator=(const WelchSpectrum&) = delete;

  // The next sample [units]. No allocation; a transform every segment / 2 samples.
  void Add(double x);

  int segments() const { return segments_; }   // averaged so far
  int bins() const { return segment_ / 2 + 1; }
  double frequency(int k) const;                // f_k [Hz]
  // The averaged density at bin k [units^2/Hz] (0 before the first segment).
  double density(int k) const;
  // m0 = sum_k S_k df [units^2]: the spectrum's integral (0 before the first segment).
  double m0() const;

  // The segment length for a record of `samples` rows: the largest power of two at most
  // samples / 8 (with half overlap about 15 segments at least, so each bin's estimate has about
  // a quarter of its value as its standard error), at least 16 (or the largest power of two in
  // the record when shorter), at most kMaxSegment (a spectrum file of at most kMaxSegment / 2 + 1
  // rows: at 0.1 s a 1638 s segment, 6e-4 Hz apart). 0: fewer than 8 samples, no spectrum.
  static constexpr int kMaxSegment = 16384;
  static int SegmentFor(long samples);

 private:
  void Transform();
  int segment_;
  double dt_, mean_;
  std::vector<double> window_;   // Hann, w_j = 0.5 (1 - cos(2 pi j / L)) (periodic)
  double window_power_ = 0;      // sum w_j^2
  std::vector<double> ring_;     // the last L samples less the mean, ring_[next_ % L] oldest
  long added_ = 0;
  double* in_ = nullptr;         // FFTW's arrays and plan
  void* out_ = nullptr;          // fftw_complex[L/2 + 1]
  void* plan_ = nullptr;
  std::vector<double> sum_;      // sum over segments of |X_k|^2
  int segments_ = 0;
};

}  // namespace cablefilm
