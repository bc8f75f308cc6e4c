#pragma once
// The mean, variance, least and largest value of a stream of numbers in O(1) memory, by
// Welford's update (exact to rounding however long the stream: no sum of squares that cancels
// against the squared mean). What the run keeps of each end tension as its rows come.
#include <cmath>
#include <limits>

namespace cablefilm {

class RunningMoments {
 public:
  void Add(double x) {
    ++n_;
    const double delta = x - mean_;
    mean_ += delta / static_cast<double>(n_);
    m2_ += delta * (x - mean_);
    if (n_ == 1 || x < min_) min_ = x;
    if (n_ == 1 || x > max_) max_ = x;
  }
  long count() const { return n_; }
  double mean() const { return n_ > 0 ? mean_ : kNaN; }
  // The population variance, sum (x - mean)^2 / n (the variance of the record itself, as the
  // integral of its spectrum has it); NaN before the first value.
  double variance() const { return n_ > 0 ? m2_ / static_cast<double>(n_) : kNaN; }
  double sigma() const { return std::sqrt(variance()); }
  double min() const { return n_ > 0 ? min_ : kNaN; }
  double max() const { return n_ > 0 ? max_ : kNaN; }

 private:
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  long n_ = 0;
  double mean_ = 0, m2_ = 0, min_ = 0, max_ = 0;
};

}  // namespace cablefilm
