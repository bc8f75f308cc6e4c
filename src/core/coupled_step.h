#pragma once
// The implicit step of a system of lines (model.h): generalized-alpha (implicit_step.h) on
// every line at once, with one step size for all, one Newton iteration for the whole system
// and one error estimate. Each Newton iteration assembles every line's block tridiagonal
// system, eliminates each line's interior (its stations that are not shared) for its
// right-hand side and for the few columns that couple it to its shared end stations, and
// solves the small dense system of the shared stations (their Schur complement, kDim
// unknowns per shared point); then each line's interior follows. O(s) per line and
// iteration, plus (kDim x shared points)^3 for the dense solve.
//
// A free body (body.h) is 6 more unknowns of that dense system: the line ends at its points
// are free stations of their lines whose corrections follow the body's (dx = T dq, T the
// point's 3x6 Jacobian), so its rows are the sum of T^T times theirs (the stations' mass and
// forces carried by the body) plus its own: its mass and added mass, damping, weight,
// buoyancy, waterplane and constant loads. Its pose steps by the same generalized-alpha.
#include <Eigen/Core>
#include <Eigen/LU>
#include <array>
#include <vector>

#include "core/line_data.h"
#include "core/model.h"

namespace cablefilm {

// A free body's motion in the generalized-alpha scheme: pose q, its rate, its acceleration and
// pseudo-acceleration, committed and trial.
struct BodyMotion {
  Vec6 q = Vec6::Zero(), v = Vec6::Zero(), a = Vec6::Zero(), abar = Vec6::Zero();
  Vec6 tq = Vec6::Zero(), tv = Vec6::Zero(), ta = Vec6::Zero(), tabar = Vec6::Zero();
  double arm = 1;  // its farthest point from its reference, >= 1 [m]: a turn's reach
};

// How a line end takes part in the dense system: its unknowns' offset and count (3 for a
// shared point, 6 for a free body; 0: not coupled), the free body (index among the free
// bodies) and the point's local position on it.
struct EndCoupling {
  int offset = 0, size = 0;
  int body = -1;
  Vec local = Vec::Zero();
};

struct Data {
  std::vector<LineData> lines;    // each line's LineData (implicit scheme); shared stations in sync
  std::vector<BodyMotion> bodies;  // the free bodies' (in the order of sys.free_bodies)
  std::vector<std::array<EndCoupling, 2>> couplings;  // per line, its two ends'
  std::vector<std::array<Eigen::Matrix<double, 3, 6>, 2>> end_maps;  // their T at the trial
  double t = 0;               // [s]
  double proposed_step = 0;   // the next step to try [s]
  double newton_tolerance = 0;  // a body's Newton iteration has converged below it [m]
  StepStats stats;            // the system's steps and rejections (the lines count their own
                              // Newton iterations)
  // Scratch of the coupled solve, sized once.
  std::vector<std::vector<Mat>> start_columns, end_columns;  // per line: A_II^-1 A_IB
  Eigen::MatrixXd schur;      // the shared stations' system (kDim per shared point)
  // Each line's share of `schur` and the free bodies' own rows, as last assembled: a line whose
  // kept matrix still serves keeps its share while another's is made anew.
  std::vector<Eigen::MatrixXd> line_schur;
  Eigen::MatrixXd body_schur;
  std::vector<char> fresh;              // per line: its Newton matrix made anew this iteration
  std::vector<double> last_correction;  // per line: its last correction over its tolerance
  Eigen::VectorXd schur_rhs, schur_x;
  Eigen::PartialPivLU<Eigen::MatrixXd> schur_lu;
};

// The system's LineData from each line's state (shared stations equal in every line that holds
// them; the free bodies at their rest poses, at rest): the accelerations of the shared
// stations and the free bodies from the sum of their rows. Implicit only: throws Error for
// another scheme.
Data MakeData(const Model& sys, const Inputs& in, const StepOptions& options,
                          const std::vector<State>& states);

// Advances the system by dt [s] (adaptive within it with options.tolerance > 0). Throws
// BlowUpError (naming the line in its message), CancelledError as StepLine() does.
void Step(const Model& sys, Data& sd, const Inputs& in, double dt);

// The points' positions [m] and the forces the lines exert on them [N] in a state (column p:
// point p). At a fixed or moved point, or a point on a body, the force is the sum over its
// line ends of their end stations' forces (the end link's tension, and the station's lumped
// share of weight, buoyancy and drag), less their inertia where the point moves: what an
// anchor or a fairlead must hold, as MoorDyn reports it. At a free point, the pull of its
// lines' end links (their tensions along them). Each body's pose and the lines' load on it
// (force [N], moment about its reference point [N m]). Sized once; Compute allocates nothing.
class PointLoads {
 public:
  explicit PointLoads(const Model& sys);
  void Compute(const Model& sys, const Data& sd, const Inputs& in);
  const Points& positions() const { return positions_; }
  const Points& forces() const { return forces_; }
  const std::vector<Vec6>& body_poses() const { return body_poses_; }
  const std::vector<Vec6>& body_loads() const { return body_loads_; }

 private:
  std::vector<Points> station_forces_;  // per line
  Points positions_, forces_;
  std::vector<Vec6> body_poses_, body_loads_;
};

}  // namespace cablefilm
