#include "run/tension_statistics.h"

#include <cmath>

namespace cablefilm {

double RayleighMpm(double mean, double sigma, long upcrossings) {
  if (upcrossings < 1) return TensionStatistics::kNaN;
  return mean + sigma * std::sqrt(2.0 * std::log(static_cast<double>(upcrossings)));
}

}  // namespace cablefilm
