#pragma once
// A Gumbel (type I extreme value) distribution fitted to the maxima of several runs (e.g. one
// storm simulated with several random seeds) by the method of moments: F(x) = exp(-exp(-(x -
// mu) / beta)), whose mean is mu + gamma beta (gamma = 0.5772..., Euler's constant) and whose
// standard deviation is beta pi / sqrt(6).
#include <vector>

namespace cablefilm {

// At least this many maxima to fit.
constexpr int kMinGumbelMaxima = 3;

struct GumbelFit {
  int maxima = 0;      // fitted
  double mean = 0;     // of the maxima [N]
  double std = 0;      // their sample standard deviation (over n - 1) [N]
  double beta = 0;     // scale, std sqrt(6) / pi [N]
  double mu = 0;       // location, mean - gamma beta [N]: the mode, the most probable maximum
  double p90 = 0;      // the 90 % quantile, mu - beta ln(-ln 0.9) [N]
  // The quantile of probability p (0 < p < 1): mu - beta ln(-ln p) [N].
  double Quantile(double p) const;
};

// The fit of `maxima` [N]; false (and `fit` untouched) with fewer than kMinGumbelMaxima finite
// ones. Non-finite values are left out.
bool FitGumbel(const std::vector<double>& maxima, GumbelFit* fit);

}  // namespace cablefilm
