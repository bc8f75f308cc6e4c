#pragma once
// The constraints of the inextensible cable (the paper's reference [1], Walton & Polachek
// 1960): every link keeps its rest length l exactly and its tension is the constraint force.
// With the per-station inertia of eq. (1), the second time derivative of each length constraint
// couples a link's tension only to its neighbours':
//   t_k . (a_{k+1} - a_k) = -|v_{k+1} - v_k|^2 / L_k,   a_j = M_j^-1 (T_j t_j - T_{j-1} t_{j-1} + F_j)
// so the tensions come from one scalar tridiagonal solve per evaluation: O(s). The same forces
// F (weight, buoyancy, drag, current, prisms) and inertia as the elastic model are used.
// A constraint force that comes out negative is a compression the model lets happen; it is
// reported as a negative tension.
#include <Eigen/Core>
#include <vector>

#include "core/forces.h"
#include "core/inputs.h"
#include "core/line_model.h"

namespace cablefilm {

// Solves the scalar tridiagonal systems of the constraints, allocation-free once sized.
class ConstraintSolver {
 public:
  ConstraintSolver() = default;
  explicit ConstraintSolver(const LineModel& m);

  // Tensions T and accelerations a at (x, v, t). Fills ws (geometry, force with tension).
  void Accelerations(const LineModel& m, const Inputs& in, const Water& water, double t,
                     const Points& x, const Points& v, ForceWorkspace& ws, Points& a);
  // Moves the free stations of x (mass-weighted, least motion) until every link has its rest
  // length to `tolerance` relative. Returns false if it cannot (ends pulled too far apart).
  bool ProjectPositions(const LineModel& m, Points& x, double tolerance);
  // Removes the velocity components that would change link lengths.
  void ProjectVelocities(const LineModel& m, const Points& x, Points& v);

 private:
  // Assembles the constraint matrix for tangents t (from ws geometry) with inverse inertias.
  void Assemble(const LineModel& m, const LinkGeometry& g);
  // Thomas algorithm on (lower_, diag_, upper_) with rhs_ -> rhs_.
  bool Solve();
  // dx_j = W_j (lambda_j t_j - lambda_{j-1} t_{j-1}) for the free stations.
  void Distribute(const LineModel& m, const LinkGeometry& g, const Eigen::VectorXd& lambda,
                  Points& dx) const;

  std::vector<Mat> inverse_inertia_;  // W_j = M_j^-1 [1/kg]
  Eigen::VectorXd lower_, diag_, upper_, rhs_, c_prime_;
  LinkGeometry geometry_;
  Points correction_;
};

}  // namespace cablefilm
