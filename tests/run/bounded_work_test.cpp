// Every loop of the solvers ends (issue 11, defect 2): a current too small to split into
// continuation steps, an end motion faster than any step can follow, and a signal raised while
// the equilibrium, the implicit steps or the output loop run. Each case hung before.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "run/driver.h"
#include "run/initial_state.h"
#include "run/time_grid.h"
#include "core/line_equilibrium.h"
#include "core/step.h"
#include "scene/build_model.h"
#include "scene/scene_loader.h"
#include "drive_support.h"
#include "scene_line.h"

namespace cablefilm {
namespace {

SceneDef P63() { return LoadScene(std::string(CABLEFILM_SOURCE_DIR) + "/scenes/polachek1963.toml"); }

// 5e-324 m/s is the smallest double: a quarter of it underflows to zero, so the continuation
// in the current never advanced. It now goes in at once, and the answer is still water's.
TEST(BoundedWork, AnUnderflowingCurrentStillReachesItsEquilibrium) {
  SceneDef scene = P63();
  LineModel still = LineOf(scene);
  LineModel tiny = still;
  tiny.env.current = 5e-324;
  LineEquilibriumReport report;
  const State a = SolveLineEquilibrium(tiny, &report);
  const State b = SolveLineEquilibrium(still);
  EXPECT_LE(report.current_steps, LineEquilibriumOptions().max_current_steps);
  // The drag of 5e-324 m/s is below any representable force: the same shape to round-off.
  EXPECT_LT((a.x - b.x).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(BoundedWork, ARaisedFlagStopsTheEquilibriumAtItsFirstIteration) {
  LineModel m = LineOf(P63());
  CancelFlag flag{2};
  LineEquilibriumOptions options;
  options.cancel = &flag;
  EXPECT_THROW(SolveLineEquilibrium(m, StraightChord(m), nullptr, options), CancelledError);
}

TEST(BoundedWork, ARaisedFlagStopsTheImplicitStepAndTheOutputLoop) {
  const SceneDef scene = P63();
  const LineModel m = LineOf(scene);
  const TimeGrid grid = ChooseLineGrid(m, scene.simulation, 1.0 / 30);
  auto integrator = testing::MakeStepper(m, grid);
  LineEquilibriumReport report;
  State s = InitialStateOf(scene, &report);
  CancelFlag flag{0};
  int outputs = 0;
  // Raised by the third output: Simulate returns false with the rows so far.
  const bool finished = testing::Simulate(m, *integrator, s, grid,
                                 [&](const State&, const Eigen::VectorXd&) {
                                   if (++outputs == 3) flag = 15;
                                   return true;
                                 },
                                 &flag);
  EXPECT_FALSE(finished);
  EXPECT_EQ(outputs, 3);
  // And a Step asked of a raised flag throws before it moves the state.
  const double t = s.t;
  integrator->set_cancel(&flag);
  EXPECT_THROW(integrator->Step(m, s, 1.0), CancelledError);
  EXPECT_EQ(s.t, t);
}

// A fairlead table with two rows 1 ns apart asks for a 1 m jump in a nanosecond: 1e9 m/s. The
// implicit steps shrank without end (memory growing with the rejected attempts); now the step
// has a floor, a billionth of the interval, and the run ends with a blow-up that says why.
TEST(BoundedWork, AMotionFasterThanAnyStepEndsInAClearError) {
  SceneDef scene = P63();
  scene.points[1].motion.motion = EndMotionKind::kTable;
  scene.points[1].motion.table = {{0, 0, 0}, {1e-9, 1, 0}, {0.2, 0, 0}};
  const LineModel m = LineOf(scene);
  const TimeGrid grid = ChooseLineGrid(m, scene.simulation, 1.0 / 30);
  auto integrator = testing::MakeStepper(m, grid);
  LineEquilibriumReport report;
  State s = InitialStateOf(scene, &report);
  try {
    testing::Simulate(m, *integrator, s, grid, [](const State&, const Eigen::VectorXd&) { return true; });
    FAIL() << "a 1e9 m/s end motion ran to the end";
  } catch (const BlowUpError& e) {
    EXPECT_NE(std::string(e.what()).find("faster than the scheme can follow"), std::string::npos)
        << e.what();
    EXPECT_LT(e.time, 0.2);
  }
}

// Work with a bound of its own (the statics' relaxation, core/relaxation.cpp) bounds
// the implicit steps of one call: P63's first second takes 120 (105 and 15 rejected: its start's
// tolerance), so a bound of 5 ends it with an Error that says so, before a sixth; a bound it
// does not reach changes nothing.
TEST(BoundedWork, TheImplicitStepsOfACallStopAtTheirBound) {
  const SceneDef scene = P63();
  const LineModel m = LineOf(scene);
  TimeGrid grid = ChooseLineGrid(m, scene.simulation, 1.0 / 30);
  LineEquilibriumReport report;
  const State start = InitialStateOf(scene, &report);
  auto free_run = testing::MakeStepper(m, grid);
  State a = start;
  free_run->Initialize(m, a);
  free_run->Step(m, a, 1.0);
  const StepStats taken = free_run->stats();
  std::printf("[ bound ] P63's first second: %ld steps, %ld rejected\n", taken.steps,
              taken.rejected);
  EXPECT_GT(taken.steps + taken.rejected, 5);  // (else the bound below would not bind)
  grid.options.most_steps = 5;
  auto bounded = testing::MakeStepper(m, grid);
  State b = start;
  bounded->Initialize(m, b);
  try {
    bounded->Step(m, b, 1.0);
    FAIL() << "a second of P63 in at most 5 steps";
  } catch (const CancelledError&) {
    FAIL() << "not a cancellation";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bound of 5 steps"), std::string::npos) << e.what();
  }
  grid.options.most_steps = 100000;
  auto loose = testing::MakeStepper(m, grid);
  State c = start;
  loose->Initialize(m, c);
  loose->Step(m, c, 1.0);
  EXPECT_EQ(c.x, a.x);  // bit for bit
}

}  // namespace
}  // namespace cablefilm
