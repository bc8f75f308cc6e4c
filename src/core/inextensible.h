#pragma once
// The inextensible cable of the paper's reference [1] (Walton & Polachek 1960): every link keeps
// its rest length l exactly and its tension is the constraint force. With the per-station 2x2
// inertia of eq. (1), the second time derivative of each length constraint couples a link's
// tension only to its neighbours':
//   t_k . (a_{k+1} - a_k) = -|v_{k+1} - v_k|^2 / L_k,   a_j = M_j^-1 (T_j t_j - T_{j-1} t_{j-1} + F_j)
// so the tensions come from one scalar tridiagonal solve per evaluation: O(s). The same forces
// F (weight, buoyancy, drag, current, prisms) and inertia as the elastic model are used.
// A constraint force that comes out negative is a compression the model lets happen; it is
// reported as a negative tension.
#include <Eigen/Core>

#include "core/equilibrium.h"
#include "core/forces.h"
#include "core/integrator.h"

namespace cablefilm {

// Solves the scalar tridiagonal systems of the constraints, allocation-free once sized.
class ConstraintSolver {
 public:
  explicit ConstraintSolver(const CableModel& m);

  // Tensions T and accelerations a at (x, v, t). Fills ws (geometry, force with tension).
  void Accelerations(const CableModel& m, double t, const Eigen::Matrix2Xd& x,
                     const Eigen::Matrix2Xd& v, ForceWorkspace& ws, Eigen::Matrix2Xd& a);
  // Moves the free stations of x (mass-weighted, least motion) until every link has its rest
  // length to `tolerance` relative. Returns false if it cannot (ends pulled too far apart).
  bool ProjectPositions(const CableModel& m, Eigen::Matrix2Xd& x, double tolerance);
  // Removes the velocity components that would change link lengths.
  void ProjectVelocities(const CableModel& m, const Eigen::Matrix2Xd& x, Eigen::Matrix2Xd& v);

 private:
  // Assembles the constraint matrix for tangents t (from ws geometry) with inverse inertias.
  void Assemble(const CableModel& m, const LinkGeometry& g);
  // Thomas algorithm on (lower_, diag_, upper_) with rhs_ -> rhs_.
  bool Solve();
  // dx_j = W_j (lambda_j t_j - lambda_{j-1} t_{j-1}) for the free stations.
  void Distribute(const CableModel& m, const LinkGeometry& g, const Eigen::VectorXd& lambda,
                  Eigen::Matrix2Xd& dx) const;

  std::vector<Eigen::Matrix2d> inverse_inertia_;  // W_j = M_j^-1 [1/kg]
  Eigen::VectorXd lower_, diag_, upper_, rhs_, c_prime_;
  LinkGeometry geometry_;
  Eigen::Matrix2Xd correction_;
};

// Explicit second-order stepping of the constrained system (velocity Verlet form, as the
// elastic explicit scheme) with projection of positions and velocities back onto the
// constraints after each step, so link lengths stay at rest length to 1e-12 relative. Each
// requested step is split into substeps below the stability limit of the transverse waves,
// recomputed from the current tensions.
//
// With an error tolerance (time_step = "auto") the substeps also follow a local error estimate,
// as the implicit scheme's do: the position update x_n + h v_n + h^2/2 a_n misses the cubic term
// h^3/6 a', estimated from the accelerations at both ends of the step as
//   err = h^2/6 max_j |a_{n+1,j} - a_{n,j}|_inf   [m],
// and a substep whose err exceeds the tolerance (or whose projection fails) is rejected and
// retried shorter; the next substep is 0.9 (tol/err)^(1/3) times the last (err ~ h^3), at most
// twice it and at least a fifth, and never above the transverse-wave limit or the step asked.
// The transverse-wave limit is unbounded while the tensions are near zero (a chain released
// from a horizontal line), which the error estimate is not. A substep below kSmallestSubstep of
// the step asked, or kMaxRejections rejections in a row, ends the run with a BlowUpError.
class InextensibleIntegrator : public Integrator {
 public:
  // error_tolerance: the largest local position error per substep [m]; 0 = substeps only below
  // the transverse-wave limit.
  explicit InextensibleIntegrator(const CableModel& m, double error_tolerance = 0);
  std::string name() const override;
  void Initialize(const CableModel& m, const CableState& state) override;
  void Step(const CableModel& m, CableState& state, double dt) override;
  const Eigen::VectorXd& tensions() const override { return ws_.tension; }
  IntegratorStats stats() const override {
    IntegratorStats s = stats_;
    s.record = steps_.record();
    return s;
  }

  // The largest stable substep for the current tensions [s].
  double StableSubstep(const CableModel& m) const;

  static constexpr double kSmallestSubstep = 1e-9;  // of the step asked of Step()
  static constexpr int kMaxRejections = 40;

 private:
  // One substep of h from s into the trial buffers; false if the positions cannot be projected
  // back onto the rest lengths.
  bool Trial(const CableModel& m, const CableState& s, double h);
  // The trial's local position error estimate [m].
  double LocalError(const CableModel& m, double h) const;
  // Makes the trial the state.
  void Accept(CableState& s, double h);

  ConstraintSolver solver_;
  ForceWorkspace ws_, trial_ws_;
  Eigen::Matrix2Xd a_, v_pred_;
  Eigen::Matrix2Xd trial_x_, trial_v_, trial_a_;  // the substep being tried
  double error_tolerance_ = 0;  // [m]; 0: substeps from the wave limit only
  double proposed_ = 0;         // the next substep to try (error control) [s]
  IntegratorStats stats_;
  SnapMonitor steps_;  // the step range only: links at rest length do not snap
  bool initialized_ = false;
};

// Static equilibrium of the inextensible cable: the elastic equilibrium with a stiffness so
// high that the stretch is negligible, extrapolated to infinite stiffness, projected exactly
// onto the rest lengths. Throws Error if the ends are further apart than the cable is long.
CableState SolveInextensibleEquilibrium(const CableModel& m, EquilibriumReport* report);

}  // namespace cablefilm
