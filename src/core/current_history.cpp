#include "core/current_history.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {

double CurrentHistory::At(const std::vector<double>& v, double time) const {
  if (!(time > t.front())) return v.front();
  if (!(time < t.back())) return v.back();
  const std::size_t i = static_cast<std::size_t>(
      std::upper_bound(t.begin(), t.end(), time) - t.begin() - 1);  // t_i <= time < t_i+1
  const double f = (time - t[i]) / (t[i + 1] - t[i]);
  return v[i] + f * (v[i + 1] - v[i]);
}

double CurrentHistory::LargestFactor() const {
  double largest = 0;
  for (double f : factor) largest = std::max(largest, std::abs(f));
  return largest;
}

}  // namespace cablefilm
