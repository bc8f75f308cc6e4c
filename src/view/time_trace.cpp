#include "view/time_trace.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace cablefilm {

ThinnedTrace::ThinnedTrace(int channels, double span) : channels_(channels), span_(span) {
  if (channels < 1)
    throw Error("thinned trace: " + std::to_string(channels) + " channels; expected 1 or more");
  if (!(span >= 0) || !std::isfinite(span))
    throw Error("thinned trace: span " + std::to_string(span) + " s; expected a finite span >= 0");
  const std::size_t n = 2 * static_cast<std::size_t>(channels) + 1;
  candidates_.resize(n);
  candidate_values_.resize(n * channels);
  order_.resize(n);
  values_.resize(channels);
}

void ThinnedTrace::Take(int candidate, long seq, double t, const double* values) {
  candidates_[candidate] = {seq, t};
  std::copy(values, values + channels_,
            candidate_values_.begin() + static_cast<std::ptrdiff_t>(candidate) * channels_);
}

void ThinnedTrace::Add(double t, const double* values) {
  const long seq = added_++;
  const int last = 2 * channels_;
  // The span of the sample: with span 0 (or a time the span cannot index) each its own.
  const double index = span_ > 0 ? std::floor(t / span_) : NAN;
  const long span_index = std::isfinite(index) && std::fabs(index) < 1e15
                              ? static_cast<long>(index)
                              : -1 - seq;
  if (seq == 0 || span_index != open_span_ || span_index < 0) {
    open_span_ = span_index;
    open_points_ = 0;  // the points of the previous span stay as they are
    for (int c = 0; c < last; ++c) Take(c, seq, t, values);
  } else {
    for (int c = 0; c < channels_; ++c) {
      const double v = values[c];
      if (std::isnan(v)) continue;
      const double lo = CandidateValue(2 * c, c), hi = CandidateValue(2 * c + 1, c);
      if (std::isnan(lo) || v < lo) Take(2 * c, seq, t, values);
      if (std::isnan(hi) || v > hi) Take(2 * c + 1, seq, t, values);
    }
  }
  Take(last, seq, t, values);
  // Rewrite the open span's points: its candidates, each once, in order of arrival.
  for (int i = 0; i <= last; ++i) order_[i] = i;
  std::sort(order_.begin(), order_.end(),
            [&](int a, int b) { return candidates_[a].seq < candidates_[b].seq; });
  const int n = static_cast<int>(
      std::unique(order_.begin(), order_.end(),
                  [&](int a, int b) { return candidates_[a].seq == candidates_[b].seq; }) -
      order_.begin());
  times_.resize(times_.size() - open_points_);
  for (int c = 0; c < channels_; ++c) values_[c].resize(times_.size());
  for (int i = 0; i < n; ++i) {
    times_.push_back(candidates_[order_[i]].t);
    for (int c = 0; c < channels_; ++c) values_[c].push_back(CandidateValue(order_[i], c));
  }
  open_points_ = static_cast<std::size_t>(n);
}

}  // namespace cablefilm
