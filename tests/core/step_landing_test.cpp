// How the adaptive steps land on the end of the interval asked of them (core/step_landing.h):
// no step a rounding long, which a Newmark-type scheme turns into accelerations of rounding
// over h^2.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/line_equilibrium.h"
#include "core/step_landing.h"
#include "test_support.h"

namespace cablefilm {
namespace {

TEST(StepLanding, AStepAFewRoundingsShortOfTheEndTakesItWhole) {
  // The controller's step that came out 1.6e-11 short of the 0.5 ms row (doubling 0.25 ms
  // times a growth of 0.99999999998): the whole row, not the step and a sliver of 8e-15 s.
  const double t = 7.1, t_end = 7.1 + 0.0005, proposed = 0.00049999999999172928;
  EXPECT_EQ(StepToward(t, t_end, proposed), t_end - t);
  // A step half a percent short still takes the rest with it (a step grows by at most 1 %);
  // 2 % short is taken as proposed, leaving a fiftieth of a step, a step like any other.
  EXPECT_EQ(StepToward(t, t_end, 0.995 * 0.0005), t_end - t);
  EXPECT_EQ(StepToward(t, t_end, 0.98 * 0.0005), 0.98 * 0.0005);
  // Far from the end: the step as proposed.
  EXPECT_EQ(StepToward(0.0, 1.0, 0.25), 0.25);
}

TEST(StepLanding, ATimeARoundingShortOfTheEndHasLanded) {
  // Three hours in, a row's end is a few units in the last place (1.8e-12 s each) from where
  // the steps summed to: landed, not a step of 1.8e-12 s still to take.
  const double t_end = 10800.0005, ulp = 10800.0 * std::numeric_limits<double>::epsilon();
  EXPECT_TRUE(Landed(t_end - 4 * ulp, t_end, 0.0005));
  // A billionth of the step left is landed; a millionth is not (a step to take).
  EXPECT_TRUE(Landed(1.0 - 0.5e-9 * 0.0005, 1.0, 0.0005));
  EXPECT_FALSE(Landed(1.0 - 1e-6 * 0.0005, 1.0, 0.0005));
  EXPECT_FALSE(Landed(0.5, 1.0, 0.0005));
}

// A moving line: 20 links of wire hanging in water between a fixed anchor and an end driven on
// a circle (eq. 3), stepped at 2 ms by the implicit scheme from its statics. Before every step
// the proposed step is set a rounding short of it, as a controller's growth factor leaves it;
// the run must be the run of whole steps, step for step. The old loop took the step and then a
// sliver of 1e-14 s whose accelerations, rounding over 1e-28 s^2, wrecked the steps after it.
TEST(StepLanding, ARowProposedARoundingShortIsSteppedAsTheRow) {
  EnvironmentSpec env;
  env.fluid_density = 1025;
  const double omega = 2 * M_PI / 1.5;  // [rad/s]
  const LineModel m = testing::UniformCable(
      20, 20.0, 2.0, 2.5e-4, 2e11, env, EndMotion::Fixed(InPlane(0, 0)),
      EndMotion::Trochoid(InPlane(14, 12), Vec(0.5, 0, 0), Vec(0, 0.5, 0), omega, 1.5), 0.02, 1.2,
      1.0);
  State s0;
  s0.x = SolveLineEquilibrium(m).x;
  s0.v = Points::Zero(kDim, m.stations());
  const double row = 0.002;  // [s]
  testing::Stepper whole(Scheme::kImplicit), short_by_rounding(Scheme::kImplicit);
  whole.Initialize(m, s0);
  short_by_rounding.Initialize(m, s0);
  State a = s0, b = s0;
  double largest_gap = 0;
  for (int i = 0; i < 500; ++i) {  // 1 s: the end at full speed, 2 m/s
    short_by_rounding.data().proposed_step = row * (1 - 1.6e-11);
    whole.Step(m, a, row);
    short_by_rounding.Step(m, b, row);
    largest_gap = std::max(largest_gap, (a.x - b.x).cwiseAbs().maxCoeff());
  }
  // One step a row: no slivers.
  EXPECT_EQ(short_by_rounding.stats().steps, whole.stats().steps);
  EXPECT_EQ(short_by_rounding.stats().steps, 500);
  // The same steps to a rounding: a step 1.6e-11 shorter moves a station by v h 1.6e-11 (2e-14
  // m at 2 m/s and 2 ms), which Newton's tolerance (1e-9 of a link, 1e-9 m) covers; 1e-8 m is
  // ten of those and 1e-6 of the end's stroke. A sliver's accelerations put metres between them.
  EXPECT_LT(largest_gap, 1e-8);
}

}  // namespace
}  // namespace cablefilm
