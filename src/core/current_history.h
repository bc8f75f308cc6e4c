#pragma once
// The current over time (not in the paper): a table of times t_i [s], factors f_i and headings
// beta_i [rad], joined linearly and held at the first and last rows. The current at time t and
// elevation y is f(t) (c + profile(y)) along Horizontal(beta(t)): the scene's current scaled (a
// speed column is a factor on a current of 1 m/s) and turned. Shared, never changed once made.
// Its rate in time adds no inertia force: a tidal or storm current changes over minutes, so its
// acceleration (1e-3 m/s^2 for 1 m/s in a quarter of an hour) is far below the waves'.
#include <vector>

namespace cablefilm {

struct CurrentHistory {
  std::vector<double> t;        // [s], strictly increasing, at least one row
  std::vector<double> factor;   // f: times the scene's current (uniform and profile) [1]
  std::vector<double> heading;  // beta: the direction it flows [rad] from +x towards +z, joined
                                // linearly as given (350 to 370 degrees turns by 20)

  double FactorAt(double time) const { return At(factor, time); }
  double HeadingAt(double time) const { return At(heading, time); }
  double LargestFactor() const;  // max |f_i| (the extremes of a piecewise linear f are its rows)

 private:
  double At(const std::vector<double>& v, double time) const;
};

}  // namespace cablefilm
