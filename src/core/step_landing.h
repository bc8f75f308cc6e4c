#pragma once
// How an adaptive loop lands on the end of the interval it was asked to step, t_end [s].
//
// A step-size controller proposes steps in floating point: a step that doubles to just under
// the interval (0.00049999999999173 s of a 0.0005 s row) leaves a sliver of 1e-14 s, and t + h
// rounds a few units in the last place short of t_end. A sliver taken as a step is poison to a
// Newmark-type scheme: its pseudo-acceleration abar = (x - x_predicted) / (beta h^2) [m/s^2] is
// the positions' rounding (1e-15 m on a 30 m line) and Newton's tolerance over h^2 (1e-28 s^2),
// some 1e14 m/s^2, which the next steps carry and which threw a grounded chain 37 times its
// length within a millisecond (or shrank its steps below 1e-15 s: "the step fell to").
#include <algorithm>
#include <cmath>
#include <limits>

namespace cablefilm {

// The time left to t_end below which t has reached it [s]: a billionth of the longest step
// `largest` [s] (the state then lags t_end by |v| times that: 5e-13 m at 1 m/s and 0.5 ms
// steps), and at least a few units in the last place of t_end (1e-12 s after three hours).
inline double LandingSlack(double t_end, double largest) {
  return std::max(1e-9 * largest, 16.0 * std::numeric_limits<double>::epsilon() * std::abs(t_end));
}

// Whether t [s] has reached t_end (within LandingSlack).
inline bool Landed(double t, double t_end, double largest) {
  return !(t < t_end - LandingSlack(t_end, largest));
}

// The step to try from t: `proposed` [s], or all that is left to t_end when that is less
// than a hundredth longer (the step grows by at most 1 %, its error, as h^3, by 3 %: within
// the controllers' safety factors; the next step would otherwise be a sliver).
inline double StepToward(double t, double t_end, double proposed) {
  const double left = t_end - t;
  return left <= 1.01 * proposed ? left : proposed;
}

}  // namespace cablefilm
