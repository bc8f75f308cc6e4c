// Static equilibrium of the lumped cable against the exact elastic catenary (Irvine), for a
// uniform line and for case P63 (two materials, a buoyant section, a concentrated weight), plus
// robustness of the Newton solver from poor starts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/line_equilibrium.h"
#include "core/error.h"
#include "core/forces.h"
#include "core/step.h"
#include "scene/build_model.h"
#include "scene/scene_loader.h"
#include "../core/test_support.h"
#include "scene_line.h"

namespace cablefilm {
namespace {

using testing::ExactCatenary;
using testing::UniformCable;
using Vec2 = Eigen::Vector2d;  // the exact catenary lives in the line's vertical plane (x, y)

// A point of the exact catenary's plane as a 3D point (z = 0): comparing in 3D also counts any
// drift of the lumped line out of its plane as error.
Vec Spatial(const Vec2& r) { return Vec(r.x(), r.y(), 0.0); }

constexpr double kG = 9.80665;

struct Errors {
  double position = 0;  // max over stations of |x_j - r(s_j)| [m]
  double tension = 0;   // max over links of |T_{j+1/2} - T(s_{j+1/2})| / max T
};

// Compares a lumped equilibrium with the exact catenary (station 0 at `origin`).
Errors Compare(const LineModel& m, const State& st, const ExactCatenary& exact,
               const Vec& origin) {
  ForceWorkspace ws(m.line.links);
  ComputeGeometry(st.x, ws.geometry);
  ComputeHookeTensions(m, ws.geometry, ws.tension);
  Errors e;
  double tmax = 0;
  for (int j = 0; j <= m.line.links; ++j) {
    Vec2 r;
    exact.Evaluate(exact.H(), exact.V0(), m.line.arc_length[j], &r, nullptr);
    e.position = std::max(e.position, (st.x.col(j) - origin - Spatial(r)).norm());
  }
  for (int j = 0; j < m.line.links; ++j) {
    double T;
    exact.Evaluate(exact.H(), exact.V0(), 0.5 * (m.line.arc_length[j] + m.line.arc_length[j + 1]), nullptr,
                   &T);
    tmax = std::max(tmax, T);
    e.tension = std::max(e.tension, std::abs(ws.tension[j] - T));
  }
  e.tension /= tmax;
  return e;
}

// The lumped model puts each link's force at its midpoint value exactly (the link force is
// F(s_{j+1/2}) of the continuous line with the same anchor forces) and advances the position
// with the midpoint rule: x_{j+1} - x_j = l f(s_{j+1/2}), f = dr/ds. The composite midpoint
// rule on a smooth piece [a, b] errs by -(l^2/24) (f'(b) - f'(a)) + O(l^4); closing the far end
// then shifts the anchor forces p = (H, V0) by dp = J_L^{-1} (l^2/24) D(L), J_s = dr(s)/dp. So
// the lumped station j should sit off the exact line by the leading term
//   e(s_j) = (l^2/24) [J_{s_j} J_L^{-1} D(L) - D(s_j)],  D(s) = sum over pieces of f'(.^-) - f'(.^+)
// computed here from the exact solution alone. This is the 1/N^2 error itself, not a bound.
Vec2 LeadingError(const ExactCatenary& exact, const std::vector<double>& piece_ends,
                  double l, double s) {
  const double H = exact.H(), V0 = exact.V0();
  auto D = [&](double upto) {
    Vec2 d = Vec2::Zero();
    double a = 0;
    for (double b : piece_ends) {
      if (upto <= a) break;
      const double e = std::min(b, upto);
      d += exact.SlopeDerivative(H, V0, e, true) - exact.SlopeDerivative(H, V0, a, false);
      a = b;
    }
    return d;
  };
  auto J = [&](double at) {
    Eigen::Matrix2d j;
    const double dh = 1e-6 * H, dv = 1e-6 * (std::abs(V0) + H);
    Vec2 p, q;
    exact.Evaluate(H + dh, V0, at, &p, nullptr);
    exact.Evaluate(H - dh, V0, at, &q, nullptr);
    j.col(0) = (p - q) / (2 * dh);
    exact.Evaluate(H, V0 + dv, at, &p, nullptr);
    exact.Evaluate(H, V0 - dv, at, &q, nullptr);
    j.col(1) = (p - q) / (2 * dv);
    return j;
  };
  const double L = piece_ends.back();
  const Vec2 dp = J(L).fullPivLu().solve(D(L));
  return (l * l / 24.0) * (J(s) * dp - D(s));
}

// Largest gap between the lumped error and its predicted leading term, relative to the largest
// predicted error.
double LeadingTermMismatch(const LineModel& m, const State& st, const ExactCatenary& exact,
                           const std::vector<double>& piece_ends, const Vec& origin) {
  double gap = 0, size = 0;
  const double l = m.line.rest_length[0];
  for (int j = 0; j <= m.line.links; ++j) {
    Vec2 r;
    exact.Evaluate(exact.H(), exact.V0(), m.line.arc_length[j], &r, nullptr);
    const Vec2 predicted = LeadingError(exact, piece_ends, l, m.line.arc_length[j]);
    gap = std::max(gap, (st.x.col(j) - origin - Spatial(r + predicted)).norm());
    size = std::max(size, predicted.norm());
  }
  return gap / size;
}

struct UniformCase {
  const char* name;
  double length, mu, area, E, rho;  // m, kg/m, m^2, Pa, kg/m^3
  Vec a, b;             // ends [m]
};

class IrvineCatenary : public ::testing::TestWithParam<UniformCase> {};

TEST_P(IrvineCatenary, LumpedEquilibriumConvergesAtSecondOrder) {
  const UniformCase c = GetParam();
  EnvironmentSpec env;
  env.fluid_density = c.rho;
  const double w = (c.mu - c.rho * c.area) * kG;  // net weight per unstretched length [N/m]
  const double EA = c.E * c.area;
  ExactCatenary exact({{c.length, w, EA, 0.0}});
  const Vec2 target = (c.b - c.a).head<2>();
  // Newton from H = wL, V0 = -wL/2 (the guess only picks the root).
  const double miss = exact.Shoot(target, std::abs(w) * c.length, -0.5 * w * c.length);
  ASSERT_LT(miss, 1e-10 * c.length) << "the exact catenary's shooting did not converge";

  Errors prev;
  const int sizes[] = {30, 60, 120};
  for (int N : sizes) {
    const LineModel m = UniformCable(N, c.length, c.mu, c.area, c.E, env, EndMotion::Fixed(c.a),
                                      EndMotion::Fixed(c.b));
    LineEquilibriumReport rep;
    const State st = SolveLineEquilibrium(m, &rep);
    const Errors e = Compare(m, st, exact, c.a);
    const double mismatch = LeadingTermMismatch(m, st, exact, {c.length}, c.a);
    std::printf("[ %s ] N=%d H=%.6g V0=%.6g: max position error %.3e m, off the predicted "
                "leading term by %.2e of it; max tension error %.3e (relative), %d iterations\n",
                c.name, N, exact.H(), exact.V0(), e.position, mismatch, e.tension,
                rep.iterations);
    // The remainder after the leading l^2 term is O(l^4), i.e. O(1/N^2) of the leading term:
    // about 1e-3 at N = 30 for these lines. 1 % still fails on any first-order or wrongly
    // lumped term (those would differ from the prediction by 100 %).
    EXPECT_LT(mismatch, 0.01) << c.name << " N=" << N;
    if (N != sizes[0]) {
      // Second order: doubling N divides the error by 4 (3..5 leaves room for the next term).
      const double rp = prev.position / e.position, rt = prev.tension / e.tension;
      std::printf("[ %s ] ratio N=%d/N=%d: position %.3f, tension %.3f\n", c.name, N / 2, N, rp,
                  rt);
      EXPECT_GT(rp, 3.0) << c.name;
      EXPECT_LT(rp, 5.0) << c.name;
      EXPECT_GT(rt, 3.0) << c.name;
      EXPECT_LT(rt, 5.0) << c.name;
    }
    prev = e;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Uniform, IrvineCatenary,
    ::testing::Values(
        // Slack: 100 m of chain between points 82.5 m apart (sag ~ 25 m), vacuum.
        UniformCase{"slack", 100.0, 2.0, 2.5e-4, 4.0e10, 0.0, {0.0, 0.0, 0.0}, {80.0, 20.0, 0.0}},
        // Nearly taut: the chord is 0.2 % shorter than the line (sag ~ 2.7 m), vacuum.
        UniformCase{"nearly_taut", 100.0, 2.0, 2.5e-4, 4.0e10, 0.0, {0.0, 0.0, 0.0},
                    {99.3, 10.0, 0.0}},
        // Stretched: soft rope (EA = 50 kN) whose chord is 3 % longer than its unstretched
        // length, immersed in sea water (buoyancy enters through w = (mu - rho sigma) g).
        UniformCase{"stretched_buoyancy", 100.0, 2.0, 1.0e-3, 5.0e7, 1025.0, {5.0, -3.0, 0.0},
                    {107.5, 9.0, 0.0}}),
    [](const ::testing::TestParamInfo<UniformCase>& i) { return std::string(i.param.name); });

// ---------------------------------------------------------------------------------------------
// Case P63: the exact piecewise catenary with the weight's force jump.

std::string P63Path() { return std::string(CABLEFILM_SOURCE_DIR) + "/scenes/polachek1963.toml"; }

// P63's data from shared/reference/case-p63.md, typed in here (not read from the model).
ExactCatenary P63Exact() {
  const double rho = 1025.0;
  const double w_wire = (2.75 - rho * 5.067e-4) * kG;    // 21.9 N/m
  const double w_nylon = (1.70 - rho * 2.027e-3) * kG;   // -3.7 N/m: nylon floats
  const double W = (453.6 - rho * 0.0578) * kG;          // the prism's net weight [N]
  const double EA_wire = 5.067e-4 * 9.0e10, EA_nylon = 2.027e-3 * 2.0e9;
  return ExactCatenary({{27.432, w_wire, EA_wire, 0.0},
                        {45.72 - 27.432, w_wire, EA_wire, W},
                        {45.72, w_nylon, EA_nylon, 0.0}});
}

TEST(P63Equilibrium, MatchesExactPiecewiseCatenary) {
  ExactCatenary exact = P63Exact();
  ASSERT_LT(exact.Shoot({80.0, 30.48}, 4000.0, 0.0), 1e-9);
  const std::vector<double> piece_ends = {27.432, 45.72, 91.44};
  std::printf("[ P63 ] exact: H = %.6f N, V0 = %.6f N (anchor tension %.6f N)\n", exact.H(),
              exact.V0(), std::hypot(exact.H(), exact.V0()));

  SceneDef scene = LoadScene(P63Path());
  ASSERT_EQ(scene.lines[0].sections.size(), 2u);
  Errors prev;
  for (int factor : {1, 2, 4}) {  // 60, 120, 240 links
    SceneDef s = scene;
    for (SectionDef& sec : s.lines[0].sections) sec.segments *= factor;
    const LineModel m = LineOf(s);
    LineEquilibriumReport rep;
    const State st = SolveLineEquilibrium(m, &rep);
    const Errors e = Compare(m, st, exact, Vec::Zero());
    const double mismatch = LeadingTermMismatch(m, st, exact, piece_ends, Vec::Zero());
    std::printf("[ P63 ] N=%d: max position error %.3e m, off the predicted leading term by "
                "%.2e of it; max tension error %.3e (relative), %d iterations, residual %.2e N "
                "of %.4g N\n",
                m.line.links, e.position, mismatch, e.tension, rep.iterations, rep.residual,
                rep.force_scale);
    EXPECT_LT(mismatch, 0.01);  // O(1/N^2) remainder, as for the uniform line
    // Absolute accuracy the case needs: station positions within 0.1 mm at the baseline 60.
    EXPECT_LT(e.position, 1e-4);
    if (factor > 1) {
      const double rp = prev.position / e.position, rt = prev.tension / e.tension;
      std::printf("[ P63 ] ratio N=%d/N=%d: position %.3f, tension %.3f\n", m.line.links / 2, m.line.links,
                  rp, rt);
      EXPECT_GT(rp, 3.0);  // second order, as for the uniform line
      EXPECT_LT(rp, 5.0);
      EXPECT_GT(rt, 3.0);
      EXPECT_LT(rt, 5.0);
    }
    prev = e;
  }
}

// ---------------------------------------------------------------------------------------------
// Robustness: from the straight chord (the poorest reasonable start).

// The largest out-of-balance force on a free station, recomputed here from the returned state.
double MaxResidual(const LineModel& m, const State& st) {
  ForceWorkspace ws(m.line.links);
  ComputeGeometry(st.x, ws.geometry);
  ComputeHookeTensions(m, ws.geometry, ws.tension);
  ComputeStationForces(m, SceneWater(m), ws.geometry, ws.tension, Points::Zero(kDim, m.stations()),
                       ws.force);
  double r = 0;
  for (int j = m.first_free(); j <= m.last_free(); ++j)
    r = std::max(r, ws.force.col(j).lpNorm<Eigen::Infinity>());
  return r;
}

void ExpectConvergedFromChord(const LineModel& m, const char* what) {
  LineEquilibriumReport rep;
  State st;
  ASSERT_NO_THROW(st = SolveLineEquilibrium(m, StraightChord(m), &rep)) << what;
  const double r = MaxResidual(m, st);
  std::printf("[ robust ] %s: %d iterations, %d current steps, residual %.2e N (reported %.2e) "
              "of force scale %.4g N\n",
              what, rep.iterations, rep.current_steps, r, rep.residual, rep.force_scale);
  EXPECT_GT(rep.iterations, 0) << what;  // the chord is not an equilibrium
  EXPECT_GT(rep.force_scale, 0) << what;
  // The solver's tolerance is 1e-9 of the force scale; it may stop at its round-off floor, up
  // to 1e3 times that. Both the reported and the recomputed residual must agree with it.
  EXPECT_LE(r, 1e-6 * rep.force_scale) << what;
  EXPECT_NEAR(r, rep.residual, 1e-12 * rep.force_scale) << what;  // same state, same sum
  EXPECT_TRUE(st.x.allFinite()) << what;
  EXPECT_EQ(st.v.cwiseAbs().maxCoeff(), 0.0) << what;
}

TEST(EquilibriumRobustness, FromStraightChord) {
  EnvironmentSpec vacuum;
  vacuum.fluid_density = 0;
  const auto fixed = [](double x, double y) { return EndMotion::Fixed(InPlane(x, y)); };
  // Slack (chord 60 % of the length): the chord has every link compressed, so T = 0 everywhere.
  ExpectConvergedFromChord(
      UniformCable(80, 100.0, 2.0, 2.5e-4, 4e10, vacuum, fixed(0, 0), fixed(50, 30)), "slack");
  // Taut: chord 0.05 % short of the length.
  ExpectConvergedFromChord(
      UniformCable(80, 100.0, 2.0, 2.5e-4, 4e10, vacuum, fixed(0, 0), fixed(99.95, 0)), "taut");
  // Stretched: chord 5 % beyond the length, soft.
  ExpectConvergedFromChord(
      UniformCable(80, 100.0, 2.0, 1e-3, 5e7, vacuum, fixed(0, 0), fixed(105, 0)), "stretched");
  // Vertical-ish and with the far end below the start.
  ExpectConvergedFromChord(
      UniformCable(40, 100.0, 2.0, 2.5e-4, 4e10, vacuum, fixed(0, 0), fixed(10, -60)),
      "slack_downhill");

  // Concentrated weights on a slack line, and a buoy (negative net weight).
  SectionSpec s{60.0, 60, 0.02, 3e-4, 1.5, 1e11, 1.2, 1.0};
  PrismSpec clump;
  clump.station = 20;
  clump.mass = 200;
  PrismSpec buoy;
  buoy.station = 45;
  buoy.mass = 10;
  buoy.volume = 0.1;  // 1025 * 0.1 = 102.5 kg of lift: net buoyant
  EnvironmentSpec sea;
  sea.fluid_density = 1025;
  ExpectConvergedFromChord(MakeLineModel({s}, {clump, buoy}, sea, fixed(0, 0), fixed(45, 5),
                                           LinkLaw::kElastic),
                           "weights_and_buoy");

  // P63 (buoyant nylon), and P63-C with a 0.5 m/s current.
  SceneDef p63 = LoadScene(P63Path());
  ExpectConvergedFromChord(LineOf(p63), "P63");
  p63.environment.current = 0.5;
  const LineModel pc = LineOf(p63);
  ExpectConvergedFromChord(pc, "P63-C");
  // The current pushes the line downstream: the middle moves along +x from still water.
  p63.environment.current = 0.0;
  const State still = SolveLineEquilibrium(LineOf(p63));
  LineEquilibriumReport rep;
  const State drift = SolveLineEquilibrium(pc, &rep);
  EXPECT_GT(rep.current_steps, 0);
  EXPECT_GT(drift.x(0, 30), still.x(0, 30));
}

// A cable with one free end hangs straight down from the fixed one, each link stretched by the
// weight below it: with station 0 free, link j-1/2 carries w l (j - 1/2) (half a link's weight
// at the free station, as the lumped model defines it). Computed here, exactly.
TEST(EquilibriumRobustness, FreeHangingCable) {
  const int N = 50;
  const double L = 20.0, mu = 3.0, area = 4e-4, E = 1e8, rho = 1025.0;
  EnvironmentSpec sea;
  sea.fluid_density = rho;
  // Station 0 free and starting off to the side; station s fixed at the top.
  const LineModel m = UniformCable(N, L, mu, area, E, sea, EndMotion::Free(InPlane(15.0, -5.0)),
                                    EndMotion::Fixed(InPlane(1.0, 2.0)));
  LineEquilibriumReport rep;
  const State st = SolveLineEquilibrium(m, StraightChord(m), &rep);
  const double l = L / N, w = (mu - rho * area) * kG, EA = area * E;
  double y = 2.0, err = 0;
  for (int j = N; j >= 0; --j) {
    err = std::max(err, (st.x.col(j) - InPlane(1.0, y)).norm());
    if (j > 0) {
      const double T = w * l * (j - 0.5);  // weight below link j-1/2 (stations 0..j-1)
      y -= l * (1.0 + T / EA);
    }
  }
  std::printf("[ robust ] free hanging: %d iterations, max position error %.2e m\n",
              rep.iterations, err);
  // The exact lumped answer; the solver's tolerance 1e-9 of the weight moves it by about
  // 1e-9 * L * (EA / (w L)) at worst through the axial compliance: well below 1e-8 m here.
  EXPECT_LT(err, 1e-8);
  EXPECT_LE(MaxResidual(m, st), 1e-6 * rep.force_scale);
}

// A taut tether of 100 000 links of 11 um, as a fuzzed MoorDyn file had it, 0.3 degrees off the
// vertical: EA / l = 2.3e12 N/m, so the tensions' round-off (the floor, 4 eps |x| EA / l =
// 2.9e-3 N) is thousands of times the tolerance asked (1e-9 of the load, 4.8e-7 N). Newton gets
// within the floor in a few iterations and can do no better there; it used to go on for its
// 500 iterations and the fallback's 5 000 (145 s) to the same answer.
// The truth: a taut line's mean tension is EA times its mean strain, its arc over L0 less 1,
// and its arc is the chord D and the sag's 8 delta^2 / (3 D) (a parabola of sag delta = w_n D^2
// / (8 T) under the weight's part across it, w_n): 7.5e-9 of D, 0.19 N of 446 N here, which
// the discrete line must show. Along it the tension grows by the weight's part along it, w_t.
TEST(EquilibriumRobustness, StiffLinksStopAtTheRoundoffFloor) {
  const int N = 100000;
  const double L = 1.11374, mu = 3.8, area = 4.822e-4, EA = 25789847.71, rho = 1025.0;
  // Its ends as the file placed them (the floor grows with |x|).
  const Vec bottom(-0.82037111325625, -1.2840966813934565, 1.4824722198985547);  // [m]
  const Vec top = Vec(-0.8228425527966355, -0.17035212342813671, 1.4773081554316) - bottom;
  EnvironmentSpec sea;
  sea.fluid_density = rho;
  const LineModel m = UniformCable(N, L, mu, area, EA / area, sea, EndMotion::Fixed(bottom),
                               EndMotion::Fixed(bottom + top));
  LineEquilibriumReport rep;
  const State st = SolveLineEquilibrium(m, &rep);
  ForceWorkspace ws(m.line.links);
  ComputeGeometry(st.x, ws.geometry);
  ComputeHookeTensions(m, ws.geometry, ws.tension);
  const double D = top.norm(), w = (mu - rho * area) * kG;  // [m], [N/m]
  const double cos_t = top.y() / D, w_t = w * cos_t, w_n = w * std::sqrt(1 - cos_t * cos_t);
  double T = EA * (D / L - 1);  // [N], then with the sag's arc (a fixed point: 3 rounds)
  for (int i = 0; i < 5; ++i) {
    const double sag = w_n * D * D / (8 * T);
    T = EA * ((D + 8 * sag * sag / (3 * D)) / L - 1);
  }
  const double mean = ws.tension.mean();
  const double growth = (ws.tension[N - 1] - ws.tension[0]) / (L * (N - 1.0) / N);  // [N/m]
  std::printf("[ robust ] stiff links: %d iterations (%d pseudo-transient), residual %.2e N, "
              "floor %.2e N, tolerance %.2e N; mean tension %.4f N (taut line with its sag "
              "%.4f N, without %.4f N), growth %.4f N/m (w_t %.4f N/m)\n",
              rep.iterations, rep.fallback_iterations, rep.residual, rep.roundoff_floor,
              1e-9 * rep.force_scale, mean, T, EA * (D / L - 1), growth, w_t);
  EXPECT_GT(rep.roundoff_floor, 1e3 * 1e-9 * rep.force_scale);  // the case it is about
  EXPECT_LE(rep.residual, rep.roundoff_floor);
  EXPECT_FALSE(rep.fallback);
  EXPECT_LE(rep.iterations, 30);
  EXPECT_NEAR(mean, T, 0.02);
  EXPECT_NEAR(growth, w_t, 1e-3 * w_t);
}

// ---------------------------------------------------------------------------------------------
// A towed cable (issue 11, defect 10): the upper end fixed, the lower end free, in a current.
// Each link's weight and normal drag must have no normal resultant, so every link makes the
// same angle theta with the vertical, the critical angle of the lumped line:
//   w_l sin(theta) = k U^2 cos^2(theta),   w_l = net weight of a link [N], k = (1/2) rho Cd d l,
// a quadratic in sin(theta); the tension of link i (from the top) carries the tangential load of
// the n - i - 1/2 links' worth of stations below it: T_i = w_l cos(theta) (n - i - 1/2).
TEST(EquilibriumTowedCable, EveryLinkAtTheCriticalAngle) {
  const double L = 200, d = 0.02, mu = 2.0, area = 2.5e-4, E = 4e10, rho = 1025, Cd = 1.2;
  EnvironmentSpec sea;
  sea.fluid_density = rho;
  for (int n : {5, 20, 200}) {
    for (double U : {0.25, 1.0, 2.0}) {
      sea.current = U;
      // The first guess: the free end straight below the fixed one.
      const LineModel m = UniformCable(n, L, mu, area, E, sea, EndMotion::Fixed(InPlane(0, 0)),
                                        EndMotion::Free(InPlane(0, -L)), d, Cd);
      LineEquilibriumReport rep;
      State st;
      ASSERT_NO_THROW(st = SolveLineEquilibrium(m, &rep)) << n << " links, " << U << " m/s";
      const double l = L / n, wl = (mu - rho * area) * kG * l, k = 0.5 * rho * Cd * d * l;
      const double a = k * U * U;  // a (1 - s^2) = wl s  ->  a s^2 + wl s - a = 0
      const double sin_theta = (-wl + std::sqrt(wl * wl + 4 * a * a)) / (2 * a);
      const double theta = std::asin(sin_theta);
      ForceWorkspace ws(m.line.links);
      ComputeGeometry(st.x, ws.geometry);
      ComputeHookeTensions(m, ws.geometry, ws.tension);
      double angle_err = 0, tension_err = 0;
      for (int i = 0; i < n; ++i) {
        const Vec t = ws.geometry.tangent.col(i);  // downwards and downstream
        angle_err = std::max(angle_err, std::abs(std::atan2(t.x(), -t.y()) - theta));
        const double T = wl * std::cos(theta) * (n - i - 0.5);
        tension_err = std::max(tension_err, std::abs(ws.tension[i] - T) / (wl * n));
      }
      std::printf("[ towed ] %3d links, %.2f m/s: %3d iterations%s, critical angle %.4f deg "
                  "from the horizontal, angle error %.1e rad, tension error %.1e of the weight\n",
                  n, U, rep.iterations, rep.fallback ? " (fallback)" : "",
                  90.0 - theta * 180.0 / M_PI, angle_err, tension_err);
      // Out of balance by at most r per component on a station (r itself checked against the
      // solver's tolerance), so by sqrt(2) r in length: the tension of link i is off by at most
      // the sum of those below it, sqrt(2) n r < 2 n r, and a link is turned by at most that
      // over the tension it carries, >= w_l / 2 (the lowest link): 4 n r / w_l.
      const double r = MaxResidual(m, st);
      EXPECT_LE(r, 1e-6 * rep.force_scale);  // see ExpectConvergedFromChord
      EXPECT_LT(angle_err, 4 * n * r / wl + 1e-14) << n << " links, " << U << " m/s";
      EXPECT_LT(tension_err * wl * n, 2 * n * r + 1e-12 * wl * n) << n << " links, " << U << " m/s";
    }
  }
}

// A slack line in a current (issue 11, defect 9): 300 m between fixed ends 54 m apart.
LineModel SlackLineInCurrent(int links, double current) {
  EnvironmentSpec sea;
  sea.fluid_density = 1025;
  sea.current = current;
  return UniformCable(links, 300, 2.0, 2.5e-4, 4e10, sea, EndMotion::Fixed(InPlane(0, 0)),
                      EndMotion::Fixed(InPlane(54, 0)), 0.02, 1.2);
}

TEST(EquilibriumSlackLine, ConvergesInEveryCurrent) {
  for (int n : {10, 30, 100, 300}) {
    double previous = 1e-9;
    for (double U : {0.1, 0.3, 1.0, 2.0}) {
      const LineModel m = SlackLineInCurrent(n, U);
      LineEquilibriumReport rep;
      State st;
      ASSERT_NO_THROW(st = SolveLineEquilibrium(m, &rep)) << n << " links, " << U << " m/s";
      std::printf("[ slack ] %3d links, %.1f m/s: %4d iterations%s, residual %.1e N\n", n, U,
                  rep.iterations, rep.fallback ? " (fallback)" : "", MaxResidual(m, st));
      EXPECT_LE(MaxResidual(m, st), 1e-6 * rep.force_scale);  // see ExpectConvergedFromChord
      // The current pushes the line downstream (+x), further the faster it flows: the mean
      // abscissa of the stations grows from 27 m, where symmetry puts it in still water.
      const double downstream = st.x.row(0).mean() - 27.0;
      EXPECT_GT(downstream, previous) << n << " links, " << U << " m/s";
      previous = downstream;
    }
  }
}

// And it is the state the line settles in: started there, the dynamics (implicit scheme, the
// same forces with the stations' velocities in the drag) keep it still. A state that balanced
// but was unstable would drift away within a few of its slowest periods (tens of seconds for
// this 300 m line); a stable one moves only by the integrator's error, far below 1 mm.
TEST(EquilibriumSlackLine, IsTheStateTheDynamicsSettleIn) {
  const LineModel m = SlackLineInCurrent(30, 1.0);
  State st = SolveLineEquilibrium(m);
  const Points start = st.x;
  auto integrator = testing::MakeStepper(Scheme::kImplicit, m, 0.5, 1e-6);
  integrator->Initialize(m, st);
  for (int k = 0; k < 60; ++k) integrator->Step(m, st, 1.0);
  const double moved = (st.x - start).cwiseAbs().maxCoeff();
  std::printf("[ slack ] after 60 s of dynamics: moved %.2e m\n", moved);
  EXPECT_LT(moved, 1e-3);
}

// The fallback alone (Newton allowed 2 iterations) must reach the state Newton reaches: both
// are the equilibrium to 1e-9 of the force scale, and the line is taut (EA / l ~ 1e6 N/m per
// link), so the two states agree to about residual / stiffness of the softest (transverse)
// mode; 1e-4 m is a generous bound on that for a 300 m line.
TEST(EquilibriumSlackLine, PseudoTransientFallbackReachesTheSameState) {
  const LineModel m = SlackLineInCurrent(60, 1.0);
  LineEquilibriumReport newton_report, fallback_report;
  const State newton = SolveLineEquilibrium(m, &newton_report);
  LineEquilibriumOptions starved;
  starved.max_iterations = 2;
  State fallback;
  ASSERT_NO_THROW(fallback = SolveLineEquilibrium(m, &fallback_report, starved));
  EXPECT_FALSE(newton_report.fallback);
  EXPECT_TRUE(fallback_report.fallback);
  const double diff = (newton.x - fallback.x).cwiseAbs().maxCoeff();
  std::printf("[ slack ] fallback: %d iterations, %.2e m from Newton's state\n",
              fallback_report.iterations, diff);
  EXPECT_LT(diff, 1e-4);
}

TEST(EquilibriumRobustness, ReportsNonConvergence) {
  EnvironmentSpec vacuum;
  vacuum.fluid_density = 0;
  const LineModel m = UniformCable(20, 10.0, 1.0, 1e-4, 1e10, vacuum, EndMotion::Fixed(InPlane(0, 0)),
                                    EndMotion::Fixed(InPlane(6, 0)));
  LineEquilibriumOptions opt;
  opt.max_iterations = 1;
  try {
    SolveLineEquilibrium(m, StraightChord(m), nullptr, opt);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("did not converge"), std::string::npos) << msg;
    EXPECT_NE(msg.find("station"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace cablefilm
