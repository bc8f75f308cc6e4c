// Internal axial damping (not in the paper; MoorDyn's BA): a taut link's tension gains
// c dL/dt. Checked against the damped oscillator's closed form, in both schemes, and the
// coefficient of a damping ratio against its definition.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "core/line_model.h"
#include "test_support.h"
#include "core/step.h"
#include "core/stability.h"

namespace cablefilm {
namespace {

constexpr double kG = 9.80665;

// A 1 m link (EA 1e4 N) hanging in vacuum from a fixed point with a 10 kg weight at its free
// end: the end is a mass m on a spring k = EA / l with a dashpot c. It stays taut (displaced
// by 0.3 of its static stretch), so its height is the damped oscillator's
//   y(t) = y_eq - d0 e^(-zeta w t) (cos(w_d t) + zeta / sqrt(1 - zeta^2) sin(w_d t)),
// w^2 = k / m, zeta = c / (2 sqrt(k m)), w_d = w sqrt(1 - zeta^2).
struct DampedLink {
  double l = 1.0, area = 1e-4, E = 1e8, mu = 0.1, M = 10.0, zeta = 0.05;
  LineModel model;
  double k = 0, m = 0, c = 0, y_eq = 0, d0 = 0;
  DampedLink() {
    SectionSpec s;
    s.length = l;
    s.segments = 1;
    s.diameter = 0.01;
    s.area = area;
    s.mass_per_length = mu;
    s.youngs_modulus = E;
    k = E * area / l;
    m = 0.5 * mu * l + M;
    c = 2 * zeta * std::sqrt(k * m);
    s.axial_damping = c * l / area;  // BA [Pa s]
    PrismSpec p;
    p.station = 1;
    p.mass = M;
    EnvironmentSpec vacuum;
    vacuum.fluid_density = 0;
    model = MakeLineModel({s}, {p}, vacuum, EndMotion::Fixed(InPlane(0, 0)),
                            EndMotion::Free(InPlane(0, -l)), LinkLaw::kElastic);
    const double stretch = m * kG / k;  // static [m]
    y_eq = -(l + stretch);
    d0 = 0.3 * stretch;
  }
  double Exact(double t) const {
    const double w = std::sqrt(k / m), wd = w * std::sqrt(1 - zeta * zeta);
    return y_eq - d0 * std::exp(-zeta * w * t) *
                      (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t));
  }
  // Largest |y - exact| over five periods, with steps of a thousandth of a period.
  double MaxError(Scheme kind) const {
    auto integrator = testing::MakeStepper(kind, model);
    State s;
    s.t = 0;
    s.x = Points::Zero(kDim, 2);
    s.x(1, 1) = y_eq - d0;
    s.v = Points::Zero(kDim, 2);
    integrator->Initialize(model, s);
    const double period = 2 * M_PI / std::sqrt(k / m), h = period / 1000;
    double err = 0;
    for (int n = 1; n <= 5000; ++n) {
      integrator->Step(model, s, h);
      err = std::max(err, std::abs(s.x(1, 1) - Exact(n * h)));
      EXPECT_GT(integrator->tensions()[0], 0) << "the link must stay taut";
    }
    return err;
  }
};

TEST(AxialDamping, LinkDecaysAsTheDampedOscillator) {
  const DampedLink link;
  EXPECT_NEAR(link.model.line.axial_damping[0], link.c, 1e-9 * link.c);
  // Second-order schemes at w h = 2 pi / 1000: phase error ~ (w h)^2 / 12 = 3e-6 per radian,
  // 1e-4 over the 31 radians of five periods, i.e. 1e-4 d0; 1e-3 d0 leaves a factor 10. Without
  // the damping term the error would be the whole decay, d0 (1 - e^(-zeta w t)) ~ 0.8 d0.
  for (Scheme kind : {Scheme::kImplicit, Scheme::kExplicit}) {
    const double err = link.MaxError(kind);
    std::printf("[ damping ] %s: largest error %.2e of the displacement\n",
                kind == Scheme::kImplicit ? "implicit" : "explicit", err / link.d0);
    EXPECT_LT(err, 1e-3 * link.d0);
  }
}

// zeta -> c = 2 zeta sqrt(k m_a m_b / (m_a + m_b)), with each station's cable and prism mass.
TEST(AxialDamping, RatioIsOfTheLinksOwnAxialMode) {
  SectionSpec s;
  s.length = 4.0;
  s.segments = 2;
  s.diameter = 0.02;
  s.area = 2e-4;
  s.mass_per_length = 3.0;
  s.youngs_modulus = 5e9;
  s.axial_damping_ratio = 0.7;
  PrismSpec p;
  p.station = 2;
  p.mass = 5.0;
  p.added_volume = Vec(0.001, 0.002, 0.001);  // the smaller axis's added mass counts: rho 1e-3
  EnvironmentSpec sea;
  sea.fluid_density = 1000;
  const LineModel m = MakeLineModel({s}, {p}, sea, EndMotion::Fixed(InPlane(0, 0)),
                                       EndMotion::Free(InPlane(0, -4)), LinkLaw::kElastic);
  const double k = 2e-4 * 5e9 / 2.0;
  const double m0 = 3.0, m1 = 6.0, m2 = 3.0 + 5.0 + 1.0;  // [kg]: half links, prism, added
  EXPECT_NEAR(m.line.axial_damping[0], 1.4 * std::sqrt(k * m0 * m1 / (m0 + m1)), 1e-9);
  EXPECT_NEAR(m.line.axial_damping[1], 1.4 * std::sqrt(k * m1 * m2 / (m1 + m2)), 1e-9);
}

// MoorDyn's BA/-zeta (its Line.cpp, and its documentation's "damping ratio"): BA = zeta l
// sqrt(EA w) [N s] with l the line's segment length and w its mass per length, whatever the
// prisms, and the tension BA / l dL/dt. On every link c = zeta sqrt(EA w) [N s/m], for links of
// 2 m and 0.5 m alike: an inner link of a uniform line gets 1 / sqrt(2) of the damping of
// `axial_damping_ratio`, whose mode is the link's two stations (reduced mass w l / 2).
TEST(AxialDamping, MoorDynsRatioGivesMoorDynsDampingPerLink) {
  for (const int links : {2, 8}) {
    SectionSpec s;
    s.length = 4.0;
    s.segments = links;
    s.diameter = 0.02;
    s.area = 2e-4;
    s.mass_per_length = 3.0;
    s.youngs_modulus = 5e9;
    s.moordyn_axial_damping_ratio = 0.8;
    PrismSpec p;
    p.station = 1;
    p.mass = 5.0;  // MoorDyn's BA does not see it
    EnvironmentSpec sea;
    sea.fluid_density = 1000;
    const LineModel m = MakeLineModel({s}, {p}, sea, EndMotion::Fixed(InPlane(0, 0)),
                                      EndMotion::Free(InPlane(0, -4)), LinkLaw::kElastic);
    const double EA = 2e-4 * 5e9, l = 4.0 / links;
    const double BA = 0.8 * l * std::sqrt(EA * 3.0);  // MoorDyn's [N s]
    for (int k = 0; k < links; ++k)
      EXPECT_NEAR(m.line.axial_damping[k], BA / l, 1e-12 * BA / l) << links << " links, " << k;
    if (links == 8) {
      SectionSpec own = s;
      own.moordyn_axial_damping_ratio = 0;
      own.axial_damping_ratio = 0.8;
      const LineModel n = MakeLineModel({own}, {}, sea, EndMotion::Fixed(InPlane(0, 0)),
                                        EndMotion::Free(InPlane(0, -4)), LinkLaw::kElastic);
      EXPECT_NEAR(n.line.axial_damping[4] / m.line.axial_damping[4], std::sqrt(2.0), 1e-12);
    }
  }
}

// The explicit limit shrinks by sqrt(1 + 4 zeta^2) - 2 zeta for the bound's zeta, and the scheme
// is stable there: a critically damped link run at 0.95 of it settles without overshoot, where
// 0.95 of the undamped limit grows.
TEST(AxialDamping, ExplicitLimitAccountsForTheDamping) {
  DampedLink undamped, damped;
  undamped.model.line.axial_damping.setZero();
  const StabilityLimit a = ComputeStabilityLimit(undamped.model);
  const StabilityLimit b = ComputeStabilityLimit(damped.model);
  const double gamma = damped.c / damped.m, zeta = gamma / (2 * a.omega_max);
  EXPECT_NEAR(b.time_step / a.time_step, std::sqrt(1 + 4 * zeta * zeta) - 2 * zeta, 1e-12);

  damped.model.line.axial_damping[0] = 2 * std::sqrt(damped.k * damped.m);  // critical
  const double limit = ComputeStabilityLimit(damped.model).time_step;
  auto run = [&](double fraction) {
    auto integrator = testing::MakeStepper(Scheme::kExplicit, damped.model);
    State s;
    s.t = 0;
    s.x = Points::Zero(kDim, 2);
    s.x(1, 1) = damped.y_eq - damped.d0;  // small enough to stay taut: a linear oscillator
    s.v = Points::Zero(kDim, 2);
    integrator->Initialize(damped.model, s);
    double largest = 0;
    for (int n = 0; n < 4000; ++n) {
      integrator->Step(damped.model, s, fraction * limit);
      largest = std::max(largest, std::abs(s.x(1, 1) - damped.y_eq));
      if (largest > 10 * damped.d0) break;
    }
    return std::make_pair(largest, std::abs(s.x(1, 1) - damped.y_eq));
  };
  const auto below = run(0.95);
  EXPECT_LE(below.first, 1.0001 * damped.d0);         // never further than it started
  EXPECT_LT(below.second, 1e-6 * damped.d0);          // and settled
  // The undamped limit is not safe with the damping: 0.95 of it (2 of the damped one) grows
  // until the link goes slack.
  EXPECT_GT(run(0.95 * a.time_step / limit).first, 1.5 * damped.d0);
}

}  // namespace
}  // namespace cablefilm
