#include "core/relaxation.h"

#include <algorithm>
#include <string>

#include "core/cancel.h"
#include "core/error.h"
#include "core/step.h"

namespace cablefilm {
namespace {

constexpr double kSpan = 0.1;    // s of motion between looks at the clock [s]
constexpr double kTry = 5.0;     // s of motion between tries of Newton [s]
// Newton's iterations from a state the motion has brought near: it converges in a few or the
// motion is not near yet (the last try has them all). Each failed try costs as much as the
// first failure did otherwise, and there are twelve.
constexpr int kNearIterations = 20;
// The first Newton from the scene's guess gives way to the motion once this many iterations
// in a row gain less than 1 % (a stall: Broyden's steps cannot get out of where it is); so do
// the tries from the motion's states.
constexpr int kStallIterations = 20;

// The relaxation's steps: the run's scheme and tolerance, with the most numerical damping of
// the frequencies the steps do not resolve (rho_inf = 0). The motion is a way to rest, not a
// result: its stiff, unresolved oscillations (a short stiff tether between a float and its
// bridles ringing at kilohertz) have nothing to give it, and what the steps keep of them (the
// run's rho_inf = 0.5 keeps half a step) sets Newton's iterations cycling. Without the start's
// stricter tolerance: the clock stands at t = 0, where it would hold throughout.
StepOptions RelaxationSteps(StepOptions step) {
  step.rho_inf = 0;
  step.start_tolerance = 0;
  step.start_end = 0;
  return step;
}

}  // namespace

std::vector<State> SolveCoupledEquilibriumRelaxing(Model& sys, const Inputs& in,
                                                   const StepOptions& step,
                                                   EquilibriumReport* report,
                                                   const EquilibriumOptions& options) {
  EquilibriumOptions first_try = options;
  first_try.stall_iterations = kStallIterations;
  // The tries from the motion's states share one bound on their lines' work, the first try's
  // own besides: the relaxation ends when they have used it.
  double tries_work = 0;
  try {
    return SolveCoupledEquilibriumInPlace(sys, sys.lines, report, first_try);
  } catch (const CancelledError&) {
    throw;
  } catch (const StaticsWorkError&) {
    throw;  // a line too large for the statics' bound: its motion would cost more still
  } catch (const Error& first) {
    std::string motion_failure;  // how the motion itself failed, if it did
    try {
      const HeldFirstGuess guess = HoldAtFirstGuessInPlace(sys, sys.lines, options);
      Model let_go = sys;  // its free bodies start where the first guess has them
      let_go.body_poses = guess.body_poses;
      Data sd = MakeData(let_go, in, RelaxationSteps(step), guess.states);
      std::vector<State> states(sys.lines.size());
      double stations = 0;
      for (const LineModel& m : sys.lines) stations += m.stations();
      std::vector<Vec6> poses = guess.body_poses;
      for (int span = 1; span * kSpan <= kLongestRelaxation + 1e-9; ++span) {
        ThrowIfCancelled(options.cancel, "the system's static equilibrium");
        // What is left of the bounds, for this span's steps too: where the steps fall below a
        // nanosecond (a fuzzed file's 0.1 mm chain of 20 links held a 5 t clump: 7e-10 s) one
        // span would take millions (the motion then fails: caught below).
        const StepStats stats = ModelStepStats(let_go, sd);
        const long tried = stats.steps + stats.rejected;
        const long left = std::min(kMostRelaxationSteps - tried,
                                   static_cast<long>(kMostRelaxationStationSteps / stations) - tried);
        if (left <= 0) break;
        for (LineData& d : sd.lines) d.options.most_steps = left;
        try {
          Step(let_go, sd, in, kSpan);
        } catch (const CancelledError&) {
          throw;
        } catch (const Error& e) {
          motion_failure = e.what();  // a blow-up, or steps too short to end within the bounds
          break;
        }
        // Rejected steps cost as much as accepted ones (a float's relaxation rejects 40 %).
        const StepStats done = ModelStepStats(let_go, sd);
        const double work = double(done.steps + done.rejected) * stations / kMostRelaxationStationSteps;
        if (done.steps > kMostRelaxationSteps || work > 1) break;
        if (options.relaxing)
          options.relaxing(std::max({span * kSpan / kLongestRelaxation,
                                     double(done.steps) / kMostRelaxationSteps, work}));
        // The clock back to t = 0: the ends and the sea as the statics have them.
        sd.t = 0;
        for (LineData& d : sd.lines) d.state.t = 0;
        if (span % static_cast<int>(kTry / kSpan + 0.5) != 0) continue;
        for (std::size_t i = 0; i < states.size(); ++i) states[i] = sd.lines[i].state;
        for (std::size_t k = 0; k < sys.free_bodies.size(); ++k)
          poses[sys.free_bodies[k]] = sd.bodies[k].q;
        EquilibriumOptions from_here = options;
        from_here.stall_iterations = kStallIterations;
        from_here.line_work = &tries_work;
        from_here.solving = nullptr;  // the relaxation's own progress goes on meanwhile
        if ((span + 1) * kSpan <= kLongestRelaxation + 1e-9)
          from_here.max_iterations = std::min(options.max_iterations, kNearIterations);
        from_here.guess = &states;
        from_here.guess_poses = poses.data();
        try {
          std::vector<State> rest =
              SolveCoupledEquilibriumInPlace(sys, sys.lines, report, from_here);
          if (report) report->relaxed = span * kSpan;
          return rest;
        } catch (const CancelledError&) {
          throw;
        } catch (const StaticsWorkError&) {
          throw;
        } catch (const Error&) {
          if (tries_work > options.max_line_work) break;  // no more tries
          // More motion, and again.
        }
      }
    } catch (const CancelledError&) {
      throw;
    } catch (const StaticsWorkError&) {
      throw;
    } catch (const Error&) {
      // The lines not held at the first guess (the first error says why).
    }
    throw Error(std::string(first.what()) + "; nor from where the system's own motion, damped "
                "by its fluid, brought it (at most " +
                std::to_string(int(kLongestRelaxation)) + " s, " +
                std::to_string(kMostRelaxationSteps) + " steps, " +
                std::to_string(static_cast<long>(kMostRelaxationStationSteps)) +
                " steps x stations)" +
                (motion_failure.empty() ? "" : "; the motion failed: " + motion_failure));
  }
}

}  // namespace cablefilm
