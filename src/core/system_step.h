#pragma once
// The implicit step of a system of lines (system.h): generalized-alpha (implicit_step.h) on
// every line at once, with one step size for all, one Newton iteration for the whole system
// and one error estimate. Each Newton iteration assembles every line's block tridiagonal
// system, eliminates each line's interior (its stations that are not shared) for its
// right-hand side and for the few columns that couple it to its shared end stations, and
// solves the small dense system of the shared stations (their Schur complement, kDim
// unknowns per shared point); then each line's interior follows. O(s) per line and
// iteration, plus (kDim x shared points)^3 for the dense solve.
#include <Eigen/Core>
#include <Eigen/LU>
#include <vector>

#include "core/data.h"
#include "core/system.h"

namespace cablefilm {

struct SystemData {
  std::vector<Data> lines;    // each line's Data (implicit scheme); shared stations in sync
  double t = 0;               // [s]
  double proposed_step = 0;   // the next step to try [s]
  StepStats stats;            // the system's steps and rejections (the lines count their own
                              // Newton iterations)
  // Scratch of the coupled solve, sized once.
  std::vector<std::vector<Mat>> start_columns, end_columns;  // per line: A_II^-1 A_IB
  Eigen::MatrixXd schur;      // the shared stations' system (kDim per shared point)
  Eigen::VectorXd schur_rhs, schur_x;
  Eigen::PartialPivLU<Eigen::MatrixXd> schur_lu;
};

// The system's Data from each line's state (shared stations equal in every line that holds
// them): the accelerations of the shared stations from the sum of their rows. Implicit only:
// throws Error for another scheme.
SystemData MakeSystemData(const SystemModel& sys, const Inputs& in, const StepOptions& options,
                          const std::vector<State>& states);

// Advances the system by dt [s] (adaptive within it with options.tolerance > 0). Throws
// BlowUpError (naming the line in its message), CancelledError as Step() does.
void StepSystem(const SystemModel& sys, SystemData& sd, const Inputs& in, double dt);

// The points' positions [m] and the forces the lines exert on them [N] in a state (column p:
// point p). At a fixed or moved point the force is the sum over its line ends of their end
// stations' forces (the end link's tension, and the station's lumped share of weight,
// buoyancy and drag), less their inertia at a moved point: what an anchor or a fairlead must
// hold, as MoorDyn reports it. At a free point, the pull of its lines' end links (their
// tensions along them). Sized once; Compute allocates nothing.
class PointLoads {
 public:
  explicit PointLoads(const SystemModel& sys);
  void Compute(const SystemModel& sys, const SystemData& sd, const Inputs& in);
  const Points& positions() const { return positions_; }
  const Points& forces() const { return forces_; }

 private:
  std::vector<Points> station_forces_;  // per line
  Points positions_, forces_;
};

}  // namespace cablefilm
