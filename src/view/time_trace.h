#pragma once
// A time trace thinned as it grows, so that a plot of any number of samples costs a bounded
// amount: time is cut into spans of `span` seconds from t = 0 and, of the samples in a span,
// only those holding the smallest or the largest value of a channel are kept (in time order),
// with the span's last sample. Every extreme survives thinning: the largest value kept is the
// largest added, at its time (so a plot's peak is the data's peak). span = 0 keeps every sample.
// Plain C++; used for the film's time plot (FilmHistory) and for max_tension.png.
#include <cstddef>
#include <vector>

namespace cablefilm {

class ThinnedTrace {
 public:
  static constexpr int kMaxChannels = 2;
  // `channels`: 1 or 2 values per sample (e.g. a cable and its companion); `span` [s], >= 0.
  explicit ThinnedTrace(int channels = 1, double span = 0);

  // A sample at t [s] (times non-decreasing) with one value per channel (NaN: no value, a gap).
  void Add(double t, const double* values);
  void Add(double t, double value) { Add(t, &value); }

  std::size_t size() const { return times_.size(); }
  const std::vector<double>& times() const { return times_; }                      // [s]
  const std::vector<double>& values(int channel = 0) const { return values_[channel]; }
  long added() const { return added_; }  // samples added (before thinning)
  double span() const { return span_; }

 private:
  struct Sample {
    long seq = -1;  // order of arrival
    double t = 0;
    double v[kMaxChannels] = {};
  };
  int channels_;
  double span_;
  long added_ = 0;
  long open_span_ = 0;          // index of the span being filled
  std::size_t open_points_ = 0; // points of that span at the end of the vectors
  Sample lo_[kMaxChannels], hi_[kMaxChannels], last_;  // its candidates
  std::vector<double> times_;
  std::vector<double> values_[kMaxChannels];
};

}  // namespace cablefilm
