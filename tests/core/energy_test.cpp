// Energy conservation of the explicit scheme without fluid (no drag, no added mass): velocity
// Verlet is symplectic, so kinetic + elastic + gravity energy stays within O(dt^2) of its start
// for all time, with no drift.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/explicit_step.h"
#include "core/forces.h"
#include "core/stability.h"
#include "test_support.h"

namespace cablefilm {
namespace {

struct EnergyRun {
  double max_error = 0;     // max |E(t) - E(0)| [J]
  double first_mean = 0;    // mean E(t) - E(0) over the first quarter [J]
  double last_mean = 0;     // ... over the last quarter [J]
  double min_tension = 0;   // smallest link tension seen [N]
  double swing = 0;         // max |E_kinetic| seen: the energy being exchanged [J]
};

// A 10 m line stretched 1 % between fixed ends (T0 = 1 kN) released straight in gravity: it
// sags and swings, every link stays taut (the slack switch T = max(0, .) is not smooth and
// would cost the scheme its order), the axial modes ring too.
EnergyRun RunReleasedLine(double dt_fraction, double duration) {
  EnvironmentSpec env;
  env.fluid_density = 0;  // vacuum: no drag, no buoyancy, no added mass
  const int N = 20;
  const LineModel m = testing::UniformCable(N, 10.0, 1.0, 1e-4, 1e9, env,
                                             EndMotion::Fixed(InPlane(0, 0)), EndMotion::Fixed(InPlane(10.1, 0)));
  const double dt = dt_fraction * ComputeStabilityLimit(m).time_step;
  Points x(kDim, N + 1);
  for (int j = 0; j <= N; ++j) x.col(j) = InPlane(10.1 * j / N, 0.0);
  LineData d = testing::StartData(m, testing::AtRest(x), Scheme::kExplicit);
  const State& s = d.state;
  const Inputs in = SceneInputs(m);
  LinkGeometry g;
  g.length.resize(N);
  g.tangent.resize(kDim, N);
  auto energy = [&](double* kinetic) {
    ComputeGeometry(s.x, g);
    *kinetic = KineticEnergy(m, g, s.v);
    return *kinetic + ElasticEnergy(m, g) + PotentialEnergy(m, s.x);
  };
  double ke;
  const double e0 = energy(&ke);
  const long steps = std::lround(duration / dt);
  EnergyRun r;
  r.min_tension = d.tension().minCoeff();
  long n_first = 0, n_last = 0;
  for (long k = 1; k <= steps; ++k) {
    StepLine(m, d, in, dt);
    const double err = energy(&ke) - e0;
    r.max_error = std::max(r.max_error, std::abs(err));
    r.swing = std::max(r.swing, ke);
    r.min_tension = std::min(r.min_tension, d.tension().minCoeff());
    if (k <= steps / 4) {
      r.first_mean += err;
      ++n_first;
    }
    if (k > steps - steps / 4) {
      r.last_mean += err;
      ++n_last;
    }
  }
  r.first_mean /= n_first;
  r.last_mean /= n_last;
  return r;
}

TEST(EnergyConservation, SecondOrderBoundedErrorWithoutDrift) {
  const double duration = 6.0;  // ~10 periods of the fundamental (0.63 s)
  const EnergyRun a = RunReleasedLine(0.2, duration), b = RunReleasedLine(0.1, duration);
  for (const EnergyRun* r : {&a, &b})
    std::printf("[ energy ] dt = %.1f x limit: max |E - E0| %.3e J of %.3e J exchanged; mean "
                "error first quarter %.3e J, last quarter %.3e J; min tension %.1f N\n",
                r == &a ? 0.2 : 0.1, r->max_error, r->swing, r->first_mean, r->last_mean,
                r->min_tension);
  const double ratio = a.max_error / b.max_error;
  std::printf("[ energy ] ratio of max errors (dt halved): %.3f\n", ratio);
  // The set-up keeps every link taut (else the scheme's order argument does not apply).
  EXPECT_GT(a.min_tension, 0.0);
  EXPECT_GT(b.min_tension, 0.0);
  // Second order: halving dt divides the error by 4 (3..5 for the higher-order terms).
  EXPECT_GT(ratio, 3.0);
  EXPECT_LT(ratio, 5.0);
  // Small against the energy that sloshes between kinetic and potential forms: (omega dt)^2
  // ~ 0.1 for the fastest mode at 0.2 x the limit bounds it, with room.
  EXPECT_LT(a.max_error, 0.1 * a.swing);
  // No drift: a symplectic scheme conserves a nearby energy exactly, so the error oscillates
  // about a fixed offset; the quarter means agree to a fraction of the oscillation. A drift
  // of even 1/4 of the error bound over the run fails this.
  for (const EnergyRun* r : {&a, &b})
    EXPECT_LT(std::abs(r->last_mean - r->first_mean), 0.2 * r->max_error);
}

}  // namespace
}  // namespace cablefilm
