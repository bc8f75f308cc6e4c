// Issue 21: the tangential (axial) drag and added mass of a line, MoorDyn's CdAx and CaAx
// (material.tangential_drag_coefficient C^T, material.tangential_added_mass_coefficient k^t),
// against closed forms of the continuous line:
//
// 1. A straight weightless line held at one end in a uniform current along it: its tension is
//    the axial drag of the line beyond, T(x) = (1/2) rho C^T pi d U^2 (L - x), linear in the
//    arc length x and the whole line's drag (1/2) rho C^T pi d L U^2 at the held end. Statics
//    (SolveLineEquilibrium), and the implicit and explicit schemes started from the straight line
//    at rest.
// 2. The axial vibration of a taut line between fixed ends in still water: the tangential added
//    mass k^t rho sigma joins the line's mass mu along it, and the first axial mode of the
//    lumped line has the discrete closed form below, with and without k^t (explicit: velocity
//    Verlet; implicit: generalized-alpha at rho_inf = 1, the trapezoidal rule).
// 3. An inextensible line towed along itself by one end: a rigid line, so every station has the
//    end's velocity v and acceleration a, and the tension at x is
//    T(x) = -[(mu + k^t rho sigma) a + (1/2) rho C^T pi d |v| v] (L - x) at every instant.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "core/line_equilibrium.h"
#include "core/forces.h"
#include "core/stability.h"
#include "test_support.h"

namespace cablefilm {
namespace {

constexpr double kL = 100, kD = 0.05, kRho = 1025;  // [m], [m], [kg/m^3]
constexpr double kMu = 2.0, kE = 5e8;               // [kg/m], [Pa]: EA = 9.8e5 N
constexpr double kCt = 0.5, kKt = 1.0;               // C^T, k^t
constexpr int kLinks = 20;
const double kArea = M_PI * kD * kD / 4;  // sigma [m^2]

// A uniform line of kLinks links, with the normal drag and added mass of a rope (which a line
// along the flow and moving along itself never feels: the part across it is exactly 0) and the
// given tangential coefficients; no gravity, so it stays straight.
LineModel AxialLine(double current, EndMotion start, EndMotion end, double ct, double kt,
                LinkLaw law = LinkLaw::kElastic, double damping_ratio = 0) {
  SectionSpec s;
  s.length = kL;
  s.segments = kLinks;
  s.diameter = kD;
  s.area = kArea;
  s.mass_per_length = kMu;
  s.youngs_modulus = kE;
  s.drag_coefficient = 1.2;
  s.added_mass_coefficient = 1.0;
  s.tangential_drag_coefficient = ct;
  s.tangential_added_mass_coefficient = kt;
  s.axial_damping_ratio = damping_ratio;
  EnvironmentSpec env;
  env.gravity = 0;
  env.fluid_density = kRho;
  env.current = current;  // along +x
  return MakeLineModel({s}, {}, env, std::move(start), std::move(end), law);
}

// The continuous line's axial drag per metre in a flow U along it [N/m].
double AxialDragPerMetre(double U) { return 0.5 * kRho * kCt * M_PI * kD * U * U; }

// The links' tensions of state x [N].
Eigen::VectorXd Tensions(const LineModel& m, const Points& x) {
  ForceWorkspace ws(m.line.links);
  ComputeGeometry(x, ws.geometry);
  ComputeHookeTensions(m, ws.geometry, ws.tension);
  return ws.tension;
}

// The largest difference between the links' tensions and T(x) = f (L - x) at their midpoints
// x = (k + 1/2) l, as a fraction of the whole line's drag f L.
double WorstAgainstLinear(const Eigen::VectorXd& T, double f) {
  const double l = kL / kLinks;
  double worst = 0;
  for (int k = 0; k < kLinks; ++k)
    worst = std::max(worst, std::abs(T[k] - f * (kL - (k + 0.5) * l)) / (f * kL));
  return worst;
}

TEST(AxialDrag, HeldLineInACurrentAlongItCarriesTheAxialDrag) {
  const double U = 1.0;  // [m/s]
  const LineModel m = AxialLine(U, EndMotion::Fixed(Vec::Zero()), EndMotion::Free(Vec(kL, 0, 0)),
                            kCt, kKt);
  // From the line laid along the current (the solver's own guess hangs it across, and along
  // the current only the normal drag, quadratic in the angle, turns it back: it stops within
  // an angle of the square root of its tolerance).
  Points guess = Points::Zero(kDim, m.stations());
  for (int j = 0; j <= kLinks; ++j) guess(0, j) = j * kL / kLinks;
  LineEquilibriumReport rep;
  const State st = SolveLineEquilibrium(m, guess, &rep);
  const Eigen::VectorXd T = Tensions(m, st.x);
  const double f = AxialDragPerMetre(U), l = kL / kLinks;
  // The held station's reaction: the first link's tension and its own half link's drag.
  const double held = T[0] + 0.5 * f * l;
  double off_axis = 0;
  for (int j = 0; j <= kLinks; ++j) off_axis = std::max(off_axis, st.x.col(j).tail<2>().norm());
  const double worst = WorstAgainstLinear(T, f);
  std::printf("[ axial ] statics, %.1f m/s along a %g m line: %d iterations; the held end "
              "carries %.9g N against (1/2) rho C^T pi d L U^2 = %.9g N; every link's tension "
              "within %.2e of f L of f (L - x); the line within %.1e m of the axis\n",
              U, kL, rep.iterations, held, f * kL, worst, off_axis);
  // The solver stops at an out-of-balance force of up to 1e-9 of its scale (the drags as if
  // broadside and along, 1.76 f L here) on each station, which adds up over the 20 stations
  // beyond a link to at most 20 x 1.76e-9 = 3.5e-8 of f L: 1e-7 holds it. A missing half link
  // or a drag on d l instead of pi d l is an error of 2.5 % or a factor of pi.
  EXPECT_LT(worst, 1e-7);
  EXPECT_NEAR(held, f * kL, 1e-7 * f * kL);
  EXPECT_EQ(off_axis, 0.0);  // along the current, nothing pushes it off the axis
  // Without the tangential coefficient there is nothing to hold: the line carries no tension.
  const LineModel plain = AxialLine(U, EndMotion::Fixed(Vec::Zero()), EndMotion::Free(Vec(kL, 0, 0)),
                                0.0, 0.0);
  EXPECT_EQ(Tensions(plain, SolveLineEquilibrium(plain, guess).x).maxCoeff(), 0.0);
}

// The same line started straight and unstretched at rest in the current: the drag stretches it
// and, overdamped, it settles in the equilibrium above. The linearised axial drag 2 f U per
// metre (80 N s/m^2) against the fundamental's stiffness EA (pi / 2 L)^2 (240 N/m^2) sets the
// slowest decay, exp(-3 t): after 12 s nothing is left of the start at 1e-15. The drag takes
// a link's mean velocity, which the link-scale sawtooth (neighbours moving opposite) does not
// have: the implicit scheme damps it (rho_inf = 0.5), the explicit one needs the axial damping
// (a ratio of 0.5 of critical, which changes nothing at rest).
TEST(AxialDrag, SchemesSettleOnTheAxialDragFromTheStraightLine) {
  const double U = 1.0;
  const LineModel m = AxialLine(U, EndMotion::Fixed(Vec::Zero()), EndMotion::Free(Vec(kL, 0, 0)),
                            kCt, kKt, LinkLaw::kElastic, 0.5);
  const double f = AxialDragPerMetre(U);
  const double limit = ComputeStabilityLimit(m).time_step;
  struct Case {
    const char* name;
    Scheme scheme;
    double dt;
  };
  for (const Case& c : {Case{"implicit", Scheme::kImplicit, 0.02},
                        Case{"explicit", Scheme::kExplicit, 0.5 * limit}}) {
    State st = testing::AtRest(Points::Zero(kDim, m.stations()));
    for (int j = 0; j <= kLinks; ++j) st.x(0, j) = j * kL / kLinks;
    testing::Stepper stepper(c.scheme);
    stepper.Initialize(m, st);
    const int steps = static_cast<int>(std::ceil(12.0 / c.dt));
    for (int k = 0; k < steps; ++k) stepper.Step(m, st, c.dt);
    const double worst = WorstAgainstLinear(stepper.tensions(), f);
    std::printf("[ axial ] %s, %d steps of %.3g s to %.3g s: every link's tension within %.2e "
                "of f L of f (L - x)\n",
                c.name, steps, c.dt, st.t, worst);
    // At rest in the current the state is the scheme's fixed point, the discrete equilibrium:
    // round-off of the tensions (EA times 1e-16 strains, 1e-10 N) is all that is left.
    EXPECT_LT(worst, 1e-9) << c.name;
  }
}

// The first axial mode of the lumped line between fixed ends, stretched by `strain`: s links of
// stiffness k = EA / l, interior stations of mass m = (mu + k^t rho sigma) l moving along the
// line (the normal added mass acts across it only). Its shapes u_j = sin(n pi j / s) give
// omega_n = 2 sqrt(k / m) sin(n pi / (2 s)).
double AxialModeFrequency(double kt) {
  const double l = kL / kLinks, k = kE * kArea / l, mass = (kMu + kt * kRho * kArea) * l;
  return 2.0 * std::sqrt(k / mass) * std::sin(M_PI / (2.0 * kLinks));
}

// The period of station kLinks/2's axial motion about its rest position, from `crossings` zero
// crossings (linear interpolation: at a crossing the acceleration vanishes, an O(dt^3) error).
double AxialPeriod(const LineModel& m, Scheme scheme, double dt, double amplitude, double strain) {
  const double l = kL / kLinks;
  State s;
  s.x = Points::Zero(kDim, m.stations());
  s.v = Points::Zero(kDim, m.stations());
  for (int j = 0; j <= kLinks; ++j)
    s.x(0, j) = j * l * (1 + strain) + amplitude * std::sin(M_PI * j / kLinks);
  testing::Stepper integ(scheme, 1.0);  // rho_inf = 1: the trapezoidal rule
  integ.Initialize(m, s);
  const int mid = kLinks / 2;
  const double rest = mid * l * (1 + strain);
  std::vector<double> times;
  double q_prev = s.x(0, mid) - rest, t_prev = 0;
  while (times.size() < 21) {
    integ.Step(m, s, dt);
    const double q = s.x(0, mid) - rest;
    if ((q_prev < 0) != (q < 0)) times.push_back(t_prev + dt * q_prev / (q_prev - q));
    q_prev = q;
    t_prev = s.t;
  }
  return 2.0 * (times.back() - times.front()) / (times.size() - 1);
}

TEST(AxialAddedMass, AxialModeOfATautLineSlowsByTheAddedMass) {
  const double strain = 0.01;
  // A 1 % stretch, and a mode whose strain (amplitude x pi / L) is a tenth of it: every link
  // stays taut, the motion is exactly linear (Hooke's law along x, nothing across).
  const double amplitude = 0.1 * strain * kL / M_PI;
  const Vec a(0, 0, 0), b(kL * (1 + strain), 0, 0);
  for (double kt : {0.0, kKt}) {
    const LineModel m = AxialLine(0.0, EndMotion::Fixed(a), EndMotion::Fixed(b), 0.0, kt);
    const double w = AxialModeFrequency(kt);
    // Steps of 1/400 of the period: each scheme's own frequency error is (w dt)^2 / 24
    // (Verlet: 2 asin(w dt / 2) / dt) or (w dt)^2 / 12 (trapezoidal: 2 atan(w dt / 2) / dt),
    // 1e-5 and 2e-5, removed exactly below.
    const double dt = 2 * M_PI / w / 400;
    const double verlet = 2.0 / dt * std::asin(0.5 * w * dt);
    const double trapezoidal = 2.0 / dt * std::atan(0.5 * w * dt);
    const double explicit_period = AxialPeriod(m, Scheme::kExplicit, dt, amplitude, strain);
    const double implicit_period = AxialPeriod(m, Scheme::kImplicit, dt, amplitude, strain);
    const double e_explicit = explicit_period * verlet / (2 * M_PI) - 1;
    const double e_implicit = implicit_period * trapezoidal / (2 * M_PI) - 1;
    std::printf("[ axial ] k^t = %.1f: first axial mode %.6f rad/s (closed form, mass %.4f kg/m); "
                "periods measured explicit %.3e, implicit %.3e off the schemes' own\n",
                kt, w, kMu + kt * kRho * kArea, e_explicit, e_implicit);
    // The interpolation of the crossings, O((w dt)^3) = 1e-6 of a period at each of the two
    // ends of the 10 periods measured: 1e-6 of the period holds it. Without the added mass
    // along the line the period would be sqrt(mu / (mu + k^t rho sigma)) = 0.70 of this.
    EXPECT_LT(std::abs(e_explicit), 1e-6) << kt;
    EXPECT_LT(std::abs(e_implicit), 1e-6) << kt;
  }
}

// An inextensible line towed along itself (the start moved along x by eq. (3), the end free):
// its tension at every row against T(x) = -[(mu + k^t rho sigma) a + f |v| v] (L - x), f the
// axial drag per metre at 1 m/s. An amplitude of 0.1 m over 8 s makes the inertia and the drag
// parts alike (f A / (mu + k^t rho sigma) = 1 m/s^2 per m/s^2).
TEST(AxialAddedMass, InextensibleLineTowedAlongItselfMatchesTheRigidLine) {
  const double omega = 2 * M_PI / 8.0, nu = 0.5, amplitude = 0.1;  // [rad/s], [1/s], [m]
  const LineModel m = AxialLine(
      0.0,
      EndMotion::Trochoid(Vec::Zero(), Vec(amplitude, 0, 0), Vec(0.5 * amplitude, 0, 0), omega, nu),
      EndMotion::Free(Vec(kL, 0, 0)), kCt, kKt, LinkLaw::kInextensible);
  State st;
  st.x = Points::Zero(kDim, m.stations());
  st.v = Points::Zero(kDim, m.stations());
  for (int j = 0; j <= kLinks; ++j) st.x(0, j) = j * kL / kLinks;
  testing::Stepper integ(Scheme::kInextensible);
  integ.Initialize(m, st);
  const double mass = kMu + kKt * kRho * kArea, f = AxialDragPerMetre(1.0), l = kL / kLinks;
  const double h = 0.01;  // [s]
  double worst = 0, peak = 0, inertia_part = 0, drag_part = 0, lag = 0;
  for (int row = 1; row <= 2000; ++row) {  // 20 s
    integ.Step(m, st, h);
    const Vec v = m.ends.start.Velocity(st.t), a = m.ends.start.Acceleration(st.t);
    const double e = 1e-4;  // [s]: the jerk by central differences of the exact acceleration
    const double jerk =
        (m.ends.start.Acceleration(st.t + e).x() - m.ends.start.Acceleration(st.t - e).x()) / (2 * e);
    const Eigen::VectorXd& T = integ.tensions();
    for (int k = 0; k < kLinks; ++k) {
      const double beyond = kL - (k + 0.5) * l;  // [m]
      const double exact = -(mass * a.x() + f * std::abs(v.x()) * v.x()) * beyond;
      worst = std::max(worst, std::abs(T[k] - exact));
      peak = std::max(peak, std::abs(exact));
      inertia_part = std::max(inertia_part, std::abs(mass * a.x()) * beyond);
      drag_part = std::max(drag_part, f * v.x() * v.x() * beyond);
      lag = std::max(lag, std::abs(f * beyond * std::abs(v.x()) * h * h * jerk));
    }
  }
  std::printf("[ axial ] inextensible tow along itself, 20 s in steps of %g s: tensions within "
              "%.2e N of the rigid line's (peak %.6g N: inertia with the added mass up to "
              "%.6g N, axial drag up to %.6g N; the scheme's velocity lag accounts for %.2e N)\n",
              h, worst, peak, inertia_part, drag_part, lag);
  // The line stays straight (nothing acts across it), its lengths are projected to 1e-13 and
  // every station moves with the end. The scheme's forces take the predicted velocity
  // v_n + h a_n (model.md, Integrators), short of v by h^2 j / 2 (j the jerk): the drag's
  // part of the tension is off by f (L - x) |v| h^2 j, at most `lag` (measured: the error
  // follows it to within 4 %, and shrinks as h^2). 1.5 lag bounds it; a missing added mass
  // along the line would be 13 N off, the drag on d l instead of pi d l 20 N.
  EXPECT_LT(worst, 1.5 * lag + 1e-12 * peak);
  EXPECT_GT(inertia_part, 0.3 * peak);  // both parts count
  EXPECT_GT(drag_part, 0.3 * peak);
}

}  // namespace
}  // namespace cablefilm
