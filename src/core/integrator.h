#pragma once
// Time stepping: one interface for every scheme, Step(model, state, dt), so that an implicit
// scheme slots in beside the explicit one. Each integrator owns its scratch memory, sized once.
#include <Eigen/Core>
#include <memory>
#include <string>

#include "core/cable_model.h"
#include "core/cable_state.h"
#include "core/cancel.h"
#include "core/error.h"
#include "core/snap_monitor.h"

namespace cablefilm {

enum class IntegratorKind {
  kExplicit,  // central differences (velocity Verlet form), second order, step below the limit
  kImplicit,  // generalized-alpha, second order, unconditionally stable, Newton per step
  kInextensible,  // constraint tensions, links at rest length (reference [1] of the paper)
};

struct IntegratorStats {
  long steps = 0;              // steps taken (accepted)
  long rejected = 0;           // steps rejected and retried with half the step
  long newton_iterations = 0;  // in all (implicit schemes)
  StepRecord record;           // step range, and links snapping taut (elastic schemes)
};

// Thrown when the solution stops being finite or physically possible.
class BlowUpError : public Error {
 public:
  BlowUpError(const std::string& what, double t, int station)
      : Error(what), time(t), station(station) {}
  double time;   // [s]
  int station;   // the first station found broken
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string name() const = 0;
  // Prepares for stepping from `state` (computes what the scheme carries between steps).
  virtual void Initialize(const CableModel& m, const CableState& state) = 0;
  // Advances state from t to t + dt. Throws BlowUpError if the new state is not finite or a
  // link is stretched beyond any physical meaning.
  virtual void Step(const CableModel& m, CableState& state, double dt) = 0;
  // Link tensions T_{j+1/2} [N] of the current state (after Initialize or Step).
  virtual const Eigen::VectorXd& tensions() const = 0;
  virtual IntegratorStats stats() const = 0;
  // A flag polled inside Step (between its internal steps): when set, Step throws
  // CancelledError, leaving the state at the last step completed. Null: never.
  void set_cancel(const CancelFlag* flag) { cancel_ = flag; }

 protected:
  const CancelFlag* cancel_ = nullptr;
};

// rho_inf: the implicit scheme's spectral radius at infinite frequency (ignored by the other
// schemes); error_tolerance: the implicit and the inextensible schemes' local position error per
// step [m], 0 for fixed steps (ignored by the explicit scheme).
std::unique_ptr<Integrator> MakeIntegrator(IntegratorKind kind, const CableModel& m,
                                           double rho_inf = 0.5, double error_tolerance = 0);

// Throws BlowUpError naming the time and the first station with a non-finite position or
// velocity, or the first link stretched beyond `max_strain`.
void CheckStateSane(const CableModel& m, const CableState& state, const Eigen::VectorXd& length);

}  // namespace cablefilm
