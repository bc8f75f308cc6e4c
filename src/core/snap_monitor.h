#pragma once
// Watches the steps an integrator takes for what makes a result untrustworthy: a link snapping
// taut (slack at the start of a step, taut at its end) within a step too long to resolve the
// snap. A snap load rises over about half the period of the link's own axial oscillation,
//   tau_{j+1/2} = pi / omega_{j+1/2},  omega^2 = sigma E / l (1/m_j + 1/m_{j+1})
// (the link's stiffness between its two stations' masses, with their prisms' but without the
// normal added mass, which does not act along the link). A step longer than
// kResolvedSnapFraction tau jumps over the rise: the peak tension it reports depends on where
// the steps fall, not on the physics, and shrinking the step or the tolerance changes it.
// The monitor also keeps the smallest and largest step. O(s) per step, no allocation.
#include <Eigen/Core>

#include "core/line_model.h"

namespace cablefilm {

// A snap is resolved when the step is at most this fraction of the link's tau.
constexpr double kResolvedSnapFraction = 0.1;
// A link is slack (a snap may follow) once it is shorter than its rest length by more than
// this strain; within it, a link at zero tension flips between taut and slack on round-off
// and Newton's tolerance (1e-9 of the shortest link, on each station) alone, with no load to
// speak of (an axial wobble of that amplitude closes at most at 1e-6 l omega, a snap load of
// 1e-6 EA): a line of a MoorDyn file lying at zero strain warned of 9 unresolved snaps of
// 1e-11 N, a float's slack links at the surface of one at 1e-9.
constexpr double kSlackStrain = 1e-6;

struct StepRecord {
  double smallest_step = 0;      // [s], of the steps taken (0: none yet)
  double largest_step = 0;       // [s]
  long snaps = 0;                // links snapping taut, in all
  long unresolved_snaps = 0;     // ... within a step longer than kResolvedSnapFraction tau
  double worst_snap_ratio = 0;   // the largest step / tau at a snap
  double first_unresolved_time = -1;  // [s], -1: none
  int first_unresolved_link = -1;
};

class SnapMonitor {
 public:
  SnapMonitor() = default;
  explicit SnapMonitor(const LineModel& m);
  // The state the steps start from: which links are taut (stretched beyond their rest length,
  // or short of it by no more than kSlackStrain; with axial damping a stretched link's tension
  // can be 0 for a moment).
  void Start(const Eigen::VectorXd& length);
  // A step of h [s] taken, ending at t_end [s] with these link lengths [m].
  void Observe(double t_end, double h, const Eigen::VectorXd& length);
  // Only the step's length (a scheme without slack links: the inextensible one).
  void ObserveStep(double h);
  const StepRecord& record() const { return record_; }
  // Whether link j was taut at the last state observed: stretched beyond its rest length, or
  // within kSlackStrain of it since it last was.
  bool taut(int j) const { return taut_[j]; }
  // tau_{j+1/2} [s] of every link (infinite for a link of zero stiffness).
  const Eigen::VectorXd& snap_times() const { return tau_; }

 private:
  Eigen::VectorXd rest_length_;  // [m]
  Eigen::VectorXd tau_;
  Eigen::Array<bool, Eigen::Dynamic, 1> taut_;
  StepRecord record_;
};

}  // namespace cablefilm
