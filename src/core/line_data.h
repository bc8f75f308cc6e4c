#pragma once
// What changes while a model runs (MuJoCo's mjData): the state, the tensions of the state, the
// memory the time-stepping scheme carries from step to step, the water of the last step, and
// the statistics. A complete checkpoint: a copy of a LineData, stepped with the same model and
// inputs, goes on exactly as the original would (a restart, a film frame, a continuation).
// Its scratch memory is sized once (MakeLineData), so that stepping allocates nothing.
#include <Eigen/Core>
#include <string>

#include "core/block_tridiagonal.h"
#include "core/constraints.h"
#include "core/error.h"
#include "core/forces.h"
#include "core/inputs.h"
#include "core/line_model.h"
#include "core/snap_monitor.h"
#include "core/vec.h"

namespace cablefilm {

enum class Scheme {
  kExplicit,      // central differences (velocity Verlet form), second order, below the limit
  kImplicit,      // generalized-alpha, second order, unconditionally stable, Newton per step
  kInextensible,  // constraint tensions, links at rest length (reference [1] of the paper)
};

// How the scheme steps (a scene's [simulation]; the run layer's time grid chooses them).
struct StepOptions {
  Scheme scheme = Scheme::kImplicit;
  double rho_inf = 0.5;        // implicit: spectral radius at infinite frequency, [0, 1]
  double tolerance = 0;        // implicit, inextensible: local position error per step [m];
                               // 0: the steps asked of StepLine() (inextensible: split below the
                               // transverse-wave limit)
  // Implicit, with a tolerance: the stricter one [m] that holds while the motion starts, until
  // start_end [s] (the run layer's StartDuration): the start excites the line's free axial
  // oscillations, whose phase error accumulates cycle after cycle, where the forced motion's
  // does not (docs/model.md, "Start-up"). 0: the tolerance throughout.
  double start_tolerance = 0;
  double start_end = 0;
  double ToleranceAt(double t) const {
    return tolerance > 0 && start_tolerance > 0 && t < start_end ? start_tolerance : tolerance;
  }
  double safety_factor = 0;    // explicit: > 0, automatic substeps of at most this fraction of
                               // the stability limit, refined where links snap
                               // (explicit_step.h); 0: the steps asked, as they are; implicit
                               // with explicit_snaps: the same, for the steps through snaps
  // Implicit: a step that snaps a link taut too fast for it is left to explicit steps, a
  // line's or its coupled island's (explicit_snaps.h; needs safety_factor > 0).
  bool explicit_snaps = false;
  // Implicit: the steps, accepted and rejected, that one call of the adaptive loop may take
  // before it gives up with an Error (0: no bound). Work with a bound of its own (the statics'
  // relaxation) sets it: a motion whose steps fall below a nanosecond would otherwise take
  // millions of them within one span, between its looks at the bound.
  long most_steps = 0;
};

struct State {
  double t = 0;  // time [s]
  Points x;      // station positions x_j [m] (kDim x s+1)
  Points v;      // station velocities [m/s] (kDim x s+1)
};

struct StepStats {
  long steps = 0;              // steps taken (accepted)
  long rejected = 0;           // steps rejected and retried shorter (explicit: refined)
  long newton_iterations = 0;  // in all (the implicit scheme)
  int finest_refinement = 0;   // explicit, automatic: the finest k of 2^k substeps a step
  long snap_windows = 0;       // implicit: times it left a snap to explicit steps
  long explicit_steps = 0;     // ... and the explicit steps taken in those windows (in steps)
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

// Scratch memory of the schemes: trial values of a step, the Newton system, the constraint
// solver's; no meaning between steps.
struct Scratch {
  Points x, v, a, abar;     // a trial step's x_{n+1}, v_{n+1} (explicit: v_{n+1/2}), a_{n+1},
                            // abar_{n+1}
  Points v_pred;            // explicit, inextensible: the predicted v_{n+1} of the drag [m/s]
  ForceWorkspace trial;     // inextensible: the forces of the trial step
  BlockTridiagonal system;  // implicit: Newton's matrix; its right-hand side
  std::vector<char> matrix_taut;  // implicit: which links were taut when that matrix was made
  std::vector<char> snapping;     // implicit: slack links that Newton's model takes as taut
                                  // (implicit_stages.h, FindSnappingLinks): 1 marked, 2 in
                                  // the matrix
  std::vector<Vec> residual;      // implicit: the residual of the iterate, kept for re-solves
  ConstraintSolver constraints;  // inextensible: the constraints' tridiagonal system
  // Constants of the model and the options, computed once:
  Eigen::VectorXd least_inertia;  // explicit: m_j + min(m^x_j, m^y_j), station j's least
                                  // inertia in any direction [kg]
  double max_substep = 0;         // explicit, automatic (and implicit's steps through snaps):
                                  // safety x the stability limit [s]
  double snap_window = 0;         // implicit, explicit_snaps: the window after a snap [s]
  double newton_tolerance = 0;    // implicit: Newton has converged when |dx| is below it [m]
};

struct LineData {
  StepOptions options;
  State state;
  ForceWorkspace forces;  // of the state: link geometry, tensions T_{j+1/2} [N], station forces
  Water water;            // the water of the last step (the waves' phase carries over)
  // The scheme's memory.
  Points a;               // a_n [m/s^2]
  Points abar;            // implicit: generalized-alpha's pseudo-acceleration abar_n [m/s^2]
  Points abar_before;     // implicit: abar_{n-1}, for the predictor's slope [m/s^2]
  double last_step = 0;   // implicit: h_{n-1}, the last step taken (0: none yet) [s]
  bool smooth = false;    // implicit: at the last step's end every link had tension and no
                          // station touched the seabed (the predictor's slope holds)
  double proposed_step = 0;  // adaptive schemes: the next step to try [s]
  int refinement = 0;     // explicit, automatic: k, steps asked are cut into 2^k substeps
  double quiet_time = 0;  // explicit, automatic: since a link last went slack or taut [s]
  double start_time = 0;  // the state's time when the LineData was made [s]
  double explicit_until = -1;  // implicit: explicit steps through a snap until then [s]
                               // (explicit_snaps.h); below the time: none
  SnapMonitor snaps;      // which links are taut; the steps' record
  StepStats stats;
  Scratch scratch;

  const Eigen::VectorXd& tension() const { return forces.tension; }  // [N]
  StepStats step_stats() const {
    StepStats s = stats;
    s.record = snaps.record();
    return s;
  }
};

// The options line m takes of a model's (a run's, one for all its lines): an inextensible line
// the inextensible scheme (with the model's tolerance; the implicit scheme's start, snaps and
// explicit substeps are not its), an elastic one the model's explicit or implicit scheme.
StepOptions LineStepOptions(const StepOptions& model, const LineModel& m);

// The LineData of `state` under `options`: its accelerations and tensions computed (in the water of
// the inputs at state.t), the scratch sized. Throws BlowUpError if the state is not finite or
// a link is stretched beyond any physical meaning.
// `friction_anchor` (optional): a restart's stick-slip anchors (where its stations last slid);
// without, every anchor is where its station is (at rest on the bed).
LineData MakeLineData(const LineModel& m, const Inputs& in, const StepOptions& options,
                      const State& state, const Points* friction_anchor = nullptr);

// The scheme's name, as a run reports it ("implicit (generalized-alpha, rho_inf = 0.5)").
std::string SchemeName(const LineModel& m, const StepOptions& options);

// Throws BlowUpError naming the time and the first station with a non-finite position or
// velocity, or the first link stretched beyond twice its rest length.
void CheckStateSane(const LineModel& m, const State& state, const Eigen::VectorXd& length);

}  // namespace cablefilm
