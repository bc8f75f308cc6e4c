#include "run/gumbel_fit.h"

#include <cmath>

namespace cablefilm {
namespace {

constexpr double kEulerGamma = 0.57721566490153286;

}  // namespace

double GumbelFit::Quantile(double p) const { return mu - beta * std::log(-std::log(p)); }

bool FitGumbel(const std::vector<double>& maxima, GumbelFit* fit) {
  double sum = 0;
  int n = 0;
  for (double x : maxima)
    if (std::isfinite(x)) {
      sum += x;
      ++n;
    }
  if (n < kMinGumbelMaxima) return false;
  const double mean = sum / n;
  double squares = 0;
  for (double x : maxima)
    if (std::isfinite(x)) squares += (x - mean) * (x - mean);
  GumbelFit g;
  g.maxima = n;
  g.mean = mean;
  g.std = std::sqrt(squares / (n - 1));
  g.beta = g.std * std::sqrt(6.0) / M_PI;
  g.mu = mean - kEulerGamma * g.beta;
  g.p90 = g.Quantile(0.9);
  *fit = g;
  return true;
}

}  // namespace cablefilm
