#pragma once
// Central differences in velocity-Verlet form (the paper's scheme), second order:
//   v_{n+1/2} = v_n + dt/2 a_n,  x_{n+1} = x_n + dt v_{n+1/2},
//   a_{n+1} = a(x_{n+1}, v_n + dt a_n, t_{n+1}),  v_{n+1} = v_{n+1/2} + dt/2 a_{n+1}.
// The velocity in the drag terms is predicted to O(dt^2), which keeps the scheme second order
// with drag; without velocity-dependent forces it is exactly velocity Verlet (symplectic: the
// energy error stays bounded, O(dt^2), with no drift). Stable for dt below 2 / omega_max.
#include "core/forces.h"
#include "core/integrator.h"

namespace cablefilm {

class ExplicitIntegrator : public Integrator {
 public:
  explicit ExplicitIntegrator(const CableModel& m);
  std::string name() const override { return "explicit (central differences)"; }
  void Initialize(const CableModel& m, const CableState& state) override;
  void Step(const CableModel& m, CableState& state, double dt) override;
  const Eigen::VectorXd& tensions() const override { return ws_.tension; }
  IntegratorStats stats() const override { return stats_; }

 private:
  ForceWorkspace ws_;
  Eigen::Matrix2Xd a_;       // a_n [m/s^2]
  Eigen::Matrix2Xd v_pred_;  // predicted v_{n+1} for the drag terms [m/s]
  IntegratorStats stats_;
  bool initialized_ = false;
};

}  // namespace cablefilm
