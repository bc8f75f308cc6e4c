#pragma once
// The simulation loop shared by the commands and the benchmarks: the time grid, the initial
// state, and stepping from output to output.
#include <Eigen/Core>
#include <functional>

#include "core/cable_model.h"
#include "core/cable_state.h"
#include "core/equilibrium.h"
#include "core/integrator.h"
#include "core/stability.h"
#include "scene/scene_def.h"

namespace cablefilm {

// The implicit and the inextensible schemes' local position error per step when time_step =
// "auto" and no tolerance is given, as a fraction of the cable's length: case P63's peak tension
// is then within 0.1 % of the converged value at 60 to 6000 links (see bench_integrators); a
// 5 m inextensible chain released from a horizontal line is within 0.1 mm of the exact N-link
// pendulum over its first second (see tests/core/inextensible_test.cpp).
constexpr double kDefaultRelativeTolerance = 1e-6;

struct TimeGrid {
  IntegratorKind kind = IntegratorKind::kExplicit;
  double rho_inf = 0.5;      // implicit scheme's high-frequency spectral radius
  double error_tolerance = 0;  // implicit, inextensible: local position error per step [m]; 0: fixed
  double interval = 0;       // between outputs [s]
  double dt = 0;             // time step [s], interval / steps_per_output
  int steps_per_output = 1;
  long outputs = 0;          // outputs after t = 0; the run ends at outputs * interval
  bool automatic = true;     // dt chosen by the program (else the scene's time_step)
  StabilityLimit limit;      // of the explicit scheme
  double safety_factor = 0.8;
};

// The largest step not above the requested one that divides the interval. "auto" is, for the
// explicit scheme, the safety factor times its stability limit (which its integrator refines
// where links go slack or snap taut); for the implicit and the inextensible schemes an adaptive
// step below the output interval, chosen by a local error estimate (independent of the
// stations; the inextensible one also below its transverse-wave limit).
TimeGrid ChooseTimeGrid(const CableModel& m, const SimulationDef& sim, double interval);

// The integrator the grid asks for (the explicit scheme's "auto": ExplicitIntegrator with the
// grid's safety factor).
std::unique_ptr<Integrator> MakeIntegrator(const CableModel& m, const TimeGrid& grid);

// The scene's initial state: static equilibrium (the report is filled) or the straight chord.
CableState MakeInitialState(const SceneDef& scene, const CableModel& m,
                            EquilibriumReport* report, const CancelFlag* cancel = nullptr);

// Called at t = 0 and after every interval with the state and its link tensions [N]; return
// false to stop early.
using OutputCallback = std::function<bool(const CableState&, const Eigen::VectorXd& tension)>;

// Returns true if the run reached its end, false if the callback stopped it or `cancel` was
// raised (seen within a step). Throws BlowUpError.
bool Simulate(const CableModel& m, Integrator& integrator, CableState& state,
              const TimeGrid& grid, const OutputCallback& on_output,
              const CancelFlag* cancel = nullptr);

}  // namespace cablefilm
