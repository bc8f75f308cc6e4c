#pragma once
// An implicit, second-order, unconditionally stable scheme: generalized-alpha (Chung & Hulbert
// 1993) in the form of Arnold & Bruels (2007), where eq. (1) holds exactly at the end of each
// step and a pseudo-acceleration abar carries the method's memory:
//   (1 - am) abar_{n+1} + am abar_n = (1 - af) a_{n+1} + af a_n
//   x_{n+1} = x_n + h v_n + h^2 (1/2 - beta) abar_n + h^2 beta abar_{n+1}
//   v_{n+1} = v_n + h (1 - gamma) abar_n + h gamma abar_{n+1}
// rho_inf in [0, 1] is the spectral radius at infinite frequency: 1 keeps every mode (the
// trapezoidal rule), smaller values damp the unresolved axial modes; low frequencies are
// damped only at third order in omega h. Each step solves M(x) a - F(x, v, t) = 0 for x_{n+1}
// by Newton's method with the analytic Jacobian, block tridiagonal, O(s) per iteration. A step
// whose Newton iteration fails is rejected and retried in halves. With an error tolerance the
// step adapts to a local error estimate (never above the step asked of Step()); without one
// the step asked for is taken.
#include "core/block_tridiagonal.h"
#include "core/forces.h"
#include "core/integrator.h"

namespace cablefilm {

class GeneralizedAlphaIntegrator : public Integrator {
 public:
  // error_tolerance: the largest local position error per step [m]; 0 = fixed steps.
  GeneralizedAlphaIntegrator(const CableModel& m, double rho_inf, double error_tolerance = 0);
  std::string name() const override;
  void Initialize(const CableModel& m, const CableState& state) override;
  void Step(const CableModel& m, CableState& state, double dt) override;
  const Eigen::VectorXd& tensions() const override { return ws_.tension; }
  IntegratorStats stats() const override {
    IntegratorStats s = stats_;
    s.record = snaps_.record();
    return s;
  }

 private:
  // Solves one step of size h into the trial buffers; false if Newton did not converge.
  bool Solve(const CableModel& m, const CableState& s, double h);
  // The local position error of the solved step [m].
  double LocalError(const CableModel& m, double h) const;
  // Brings to rest (vertically) the stations that landed on the seabed in the solved step.
  void SettleLandings(const CableModel& m, const CableState& s, double h);
  // Makes the solved step the state.
  void Commit(const CableModel& m, CableState& s, double h);
  // a_{n+1}, v_{n+1} and abar_{n+1} implied by the positions x (free stations).
  void Kinematics(const CableModel& m, const CableState& s, double h, const Eigen::Matrix2Xd& x);

  double rho_inf_, am_, af_, beta_, gamma_;
  ForceWorkspace ws_;
  BlockTridiagonal system_;
  Eigen::Matrix2Xd a_, abar_;           // a_n, abar_n [m/s^2]
  Eigen::Matrix2Xd x_, v_, a1_, abar1_;  // trial values at n+1
  double error_tolerance_ = 0;           // local position error per step [m]; 0 = fixed steps
  double proposed_ = 0;                  // the next step to try [s]
  double newton_tolerance_ = 0;          // Newton converges when |dx| < this [m]
  IntegratorStats stats_;
  SnapMonitor snaps_;
  bool initialized_ = false;
};

}  // namespace cablefilm
