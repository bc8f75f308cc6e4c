#pragma once
// The statistics of a tension record (one end of a line over a run's rows): its moments, its
// mean up-crossings and the most probable maximum they imply, and the integral of its spectrum.
// What run_report.toml, results.nc and sweep.csv give of each line end.
#include <limits>

namespace cablefilm {

struct TensionStatistics {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  long samples = 0;        // the rows
  double mean = kNaN;      // [N]
  double sigma = kNaN;     // standard deviation (population: over n) [N]
  double min = kNaN;       // [N]
  double max = kNaN;       // [N]
  long upcrossings = 0;    // upward crossings of the mean (zero up-crossings of T - mean)
  double mpm = kNaN;       // the most probable maximum (RayleighMpm) [N]
  double psd_m0 = kNaN;    // the integral of the one-sided Welch spectrum [N^2]; NaN: none made
  bool known() const { return samples > 0; }
};

// The most probable maximum of N cycles of a narrow-banded Gaussian process of mean `mean` [N]
// and standard deviation `sigma` [N]: its peaks are Rayleigh distributed, and the mode of the
// largest of N of them is mean + sigma sqrt(2 ln N). NaN for N < 1 (no cycle).
double RayleighMpm(double mean, double sigma, long upcrossings);

// Counts the upward crossings of `level` in a stream of numbers: x[i-1] < level <= x[i].
class UpcrossingCounter {
 public:
  explicit UpcrossingCounter(double level) : level_(level) {}
  void Add(double x) {
    if (started_ && previous_ < level_ && x >= level_) ++count_;
    previous_ = x;
    started_ = true;
  }
  long count() const { return count_; }

 private:
  double level_;
  double previous_ = 0;
  bool started_ = false;
  long count_ = 0;
};

}  // namespace cablefilm
