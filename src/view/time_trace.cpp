#include "view/time_trace.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace cablefilm {

ThinnedTrace::ThinnedTrace(int channels, double span) : channels_(channels), span_(span) {
  if (channels < 1 || channels > kMaxChannels)
    throw Error("thinned trace: " + std::to_string(channels) + " channels; expected 1 or 2");
  if (!(span >= 0) || !std::isfinite(span))
    throw Error("thinned trace: span " + std::to_string(span) + " s; expected a finite span >= 0");
}

void ThinnedTrace::Add(double t, const double* values) {
  Sample s;
  s.seq = added_++;
  s.t = t;
  for (int c = 0; c < channels_; ++c) s.v[c] = values[c];
  // The span of the sample: with span 0 (or a time the span cannot index) each its own.
  const double index = span_ > 0 ? std::floor(t / span_) : NAN;
  const long span_index = std::isfinite(index) && std::fabs(index) < 1e15
                              ? static_cast<long>(index)
                              : -1 - s.seq;
  if (s.seq == 0 || span_index != open_span_ || span_index < 0) {
    open_span_ = span_index;
    open_points_ = 0;  // the points of the previous span stay as they are
    for (int c = 0; c < channels_; ++c) lo_[c] = hi_[c] = s;
  } else {
    for (int c = 0; c < channels_; ++c) {
      const double v = s.v[c];
      if (std::isnan(v)) continue;
      if (std::isnan(lo_[c].v[c]) || v < lo_[c].v[c]) lo_[c] = s;
      if (std::isnan(hi_[c].v[c]) || v > hi_[c].v[c]) hi_[c] = s;
    }
  }
  last_ = s;
  // Rewrite the open span's points: its candidates, each once, in order of arrival.
  const Sample* candidates[2 * kMaxChannels + 1];
  int n = 0;
  for (int c = 0; c < channels_; ++c) {
    candidates[n++] = &lo_[c];
    candidates[n++] = &hi_[c];
  }
  candidates[n++] = &last_;
  std::sort(candidates, candidates + n, [](const Sample* a, const Sample* b) { return a->seq < b->seq; });
  n = static_cast<int>(std::unique(candidates, candidates + n,
                                   [](const Sample* a, const Sample* b) { return a->seq == b->seq; }) -
                       candidates);
  times_.resize(times_.size() - open_points_);
  for (int c = 0; c < channels_; ++c) values_[c].resize(times_.size());
  for (int i = 0; i < n; ++i) {
    times_.push_back(candidates[i]->t);
    for (int c = 0; c < channels_; ++c) values_[c].push_back(candidates[i]->v[c]);
  }
  open_points_ = static_cast<std::size_t>(n);
}

}  // namespace cablefilm
