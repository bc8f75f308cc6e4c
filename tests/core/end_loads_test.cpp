// The loads at a line's ends (core/end_loads.h) against independent truths: the exact elastic
// catenary's tension vector at its ends (statics), and Newton's second law for a line moved
// along itself nearly as a rigid body (dynamics).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/end_loads.h"
#include "core/line_equilibrium.h"
#include "core/step.h"
#include "test_support.h"

namespace cablefilm {
namespace {

using testing::ExactCatenary;
using testing::UniformCable;
constexpr double kG = 9.80665;
constexpr double kPi = 3.14159265358979323846;

// A slack catenary between two fixed points (100 m of chain, ends 80 m across and 20 m up, in
// water): the load on each end is the continuous line's tension vector there, (H, V0) pulling
// the lower end up the line and -(H, V(L)) pulling the upper end down it. The lumped end
// station carries the end link's pull, the tension half a link in (O(l) off the end's), plus
// half a link's weight, which brings its vertical part to the end itself: what remains is
// O(l^2), second order. The end link's tension alone stays first order.
TEST(EndLoads, CatenaryEndsCarryTheContinuousLinesTension) {
  const double L = 100.0, mu = 2.0, area = 2.5e-4, E = 4e10, rho = 1025.0;
  EnvironmentSpec sea;
  sea.fluid_density = rho;
  const double w = (mu - rho * area) * kG;  // net weight per unstretched length [N/m]
  ExactCatenary exact({{L, w, E * area, 0.0}});
  ASSERT_LT(exact.Shoot({80.0, 20.0}, w * L, -0.5 * w * L), 1e-10 * L);
  const double H = exact.H(), V0 = exact.V0(), VL = V0 + w * L;
  const Vec exact_start(H, V0, 0.0), exact_end(-H, -VL, 0.0);
  const double scale = std::hypot(H, VL);  // the larger end's tension [N]

  double prev_load = 0, prev_link = 0;
  for (int n : {25, 50, 100}) {
    const LineModel m = UniformCable(n, L, mu, area, E, sea, EndMotion::Fixed(InPlane(0, 0)),
                                 EndMotion::Fixed(InPlane(80.0, 20.0)));
    LineEquilibriumReport rep;
    const State st = SolveLineEquilibrium(m, &rep);
    const LineData d = testing::StartData(m, st, Scheme::kImplicit);
    EndLoads ends(m);
    ends.Compute(m, d, SceneInputs(m));
    const double load_error =
        std::max((ends.at(0) - exact_start).norm(), (ends.at(1) - exact_end).norm()) / scale;
    const double link_error = std::max(std::abs(d.tension()[0] - exact_start.norm()),
                                       std::abs(d.tension()[n - 1] - exact_end.norm())) /
                              scale;
    std::printf("[ end loads ] %d links: end load error %.3e, end link tension error %.3e (of "
                "%.6g N); angles %.4f and %.4f deg (exact %.4f, %.4f)\n",
                n, load_error, link_error, scale, ElevationDegrees(ends.at(0)),
                ElevationDegrees(ends.at(1)), ElevationDegrees(exact_start),
                ElevationDegrees(exact_end));
    // Without the half link's share the load would be as far off as the end link's tension
    // (first order, 2.4e-2 at 25 links): a tenth of it shows that term gone, the ratios below
    // that what remains is second order.
    EXPECT_LT(load_error, 0.1 * link_error) << n;
    if (n > 25) {
      // Second order: doubling the links divides the error by 4 (3.5..4.5: the next term is
      // O(l^4)); the end link's tension halves it (first order).
      EXPECT_NEAR(prev_load / load_error, 4.0, 0.5) << n;
      EXPECT_NEAR(prev_link / link_error, 2.0, 0.2) << n;
    }
    prev_load = load_error;
    prev_link = link_error;
  }
}

// A 100 m chain hanging in water from a top moved up and down at a 10 s period (eq. 3's
// ramp), its bottom free. Its first axial mode is at c / 4L = 2.5 Hz (c = sqrt(EA / mu)
// = 1000 m/s), 25 times the motion's: the chain moves as a rigid body to (1/25)^2 = 1.6e-3 of
// the dynamic part, so the top carries what Newton's second law gives that body, the submerged
// weight plus the mass times the top's acceleration, mu L (g + a) - rho A L g, upward (the
// line pulls its top down). No drag or added mass acts along a line (the normal ones act
// across it), so nothing else enters.
TEST(EndLoads, TopOfAHangingChainCarriesItsWeightAndInertia) {
  const int n = 40;
  const double L = 100.0, mu = 100.0, area = 0.0127, E = 1e10 / 1.27, rho = 1025.0;
  const double amplitude = 2.0, period = 10.0, omega = 2 * kPi / period;  // [m], [s], [1/s]
  EnvironmentSpec sea;
  sea.fluid_density = rho;
  const Vec top = InPlane(0.0, 0.0);
  SectionSpec chain;
  chain.length = L;
  chain.segments = n;
  chain.diameter = 0.1;
  chain.area = area;
  chain.mass_per_length = mu;
  chain.youngs_modulus = E;
  chain.drag_coefficient = 1.2;
  chain.added_mass_coefficient = 1.0;
  // The ramp's start (a jump of the jerk, 3 nu^2 b omega) rings the first axial mode at about
  // mu L jerk / omega_1 = 600 N: damped in each link (half critical), it has died out (to
  // e^-6) by t = 20 s, where the comparison starts. Internal forces cancel in the sum over the
  // chain: the damping changes nothing in the law compared against.
  chain.axial_damping_ratio = 0.5;
  const LineModel m = MakeLineModel(
      {chain}, {}, sea, EndMotion::Trochoid(top, Vec(0, 0, 0), Vec(0, amplitude, 0), omega, 0.5),
      EndMotion::Free(InPlane(0.0, -L)), LinkLaw::kElastic);
  LineEquilibriumReport rep;
  State st = SolveLineEquilibrium(m, StraightChord(m), &rep);
  testing::Stepper stepper(Scheme::kImplicit, 0.5, 1e-7);
  stepper.Initialize(m, st);
  EndLoads ends(m);
  const double weight = (mu - rho * area) * L * kG;  // submerged [N]
  const double inertia = mu * L;                     // [kg]
  double worst = 0, swing = 0;
  const double dt = 0.05;
  for (int k = 1; k * dt <= 40.0 + 1e-9; ++k) {
    stepper.Step(m, st, dt);
    if (k * dt < 20.0) continue;  // the ramp's start-up and its ringing past
    ends.Compute(m, stepper.data(), stepper.inputs());
    const double a = EndAcceleration(m, stepper.inputs(), 0, st.t)[1];
    const Vec expected(0.0, -(weight + inertia * a), 0.0);  // the line's pull on its top
    worst = std::max(worst, (ends.at(0) - expected).norm());
    swing = std::max(swing, std::abs(inertia * a));
  }
  std::printf("[ end loads ] hanging chain: top load off Newton's law by %.3e N, %.3e of the "
              "inertia's swing (%.6g N) and %.3e of the weight (%.6g N)\n",
              worst, worst / swing, swing, worst / weight, weight);
  // The quasi-rigid motion's error is (omega / omega_1)^2 = 1.6e-3 of the inertia's swing
  // (measured 1.8e-3); 3e-3 leaves room for the steps' error. A load without the inertia term
  // would be off by the whole swing, one without the end station's half-link share of weight
  // by 1/(2n) of the weight (13 % of the swing).
  EXPECT_LT(worst, 3e-3 * swing);
  EXPECT_GT(swing, 0.5 * inertia * amplitude * omega * omega);  // the motion was there
}

}  // namespace
}  // namespace cablefilm
