#pragma once
// A time trace thinned as it grows, so that a plot of any number of samples costs a bounded
// amount: time is cut into spans of `span` seconds from t = 0 and, of the samples in a span,
// only those holding the smallest or the largest value of a channel are kept (in time order),
// with the span's last sample. Every extreme survives thinning: the largest value kept is the
// largest added, at its time (so a plot's peak is the data's peak). span = 0 keeps every sample.
// Plain C++; used for the film's time plot (a channel a line) and for max_tension.png.
#include <cstddef>
#include <vector>

namespace cablefilm {

class ThinnedTrace {
 public:
  // `channels`: values per sample (e.g. one a line), >= 1; `span` [s], >= 0.
  explicit ThinnedTrace(int channels = 1, double span = 0);

  // A sample at t [s] (times non-decreasing) with one value per channel (NaN: no value, a gap).
  void Add(double t, const double* values);
  void Add(double t, double value) { Add(t, &value); }

  std::size_t size() const { return times_.size(); }
  const std::vector<double>& times() const { return times_; }                      // [s]
  const std::vector<double>& values(int channel = 0) const { return values_[channel]; }
  // Every channel's values, each one per time.
  const std::vector<std::vector<double>>& all_values() const { return values_; }
  long added() const { return added_; }  // samples added (before thinning)
  double span() const { return span_; }

 private:
  // The open span's candidates: for each channel its smallest (2 c) and largest (2 c + 1)
  // sample, then its last (2 channels); their values in candidate_values_, `channels` each.
  struct Candidate {
    long seq = -1;  // order of arrival
    double t = 0;
  };
  void Take(int candidate, long seq, double t, const double* values);
  double CandidateValue(int candidate, int channel) const {
    return candidate_values_[static_cast<std::size_t>(candidate) * channels_ + channel];
  }
  int channels_;
  double span_;
  long added_ = 0;
  long open_span_ = 0;          // index of the span being filled
  std::size_t open_points_ = 0; // points of that span at the end of the vectors
  std::vector<Candidate> candidates_;
  std::vector<double> candidate_values_;
  std::vector<int> order_;      // the candidates by arrival, each once (no allocation per Add)
  std::vector<double> times_;
  std::vector<std::vector<double>> values_;
};

}  // namespace cablefilm
