// Issue 19: lines in a current that crosses their vertical plane.
//
// 1. A line between two fixed ends with the current perpendicular to the vertical plane through
//    them: its static equilibrium (SolveLineEquilibrium) against a solution of the same discrete
//    equations found here, by a Newton iteration of this file's own (the residual written out
//    from the physics, its Jacobian by central differences, a dense solve), from a guess of its
//    own: the sagging line's plane tilted by the ratio of drag to weight.
// 2. The same line reaches that equilibrium dynamically, started at rest from its equilibrium
//    without current: the current swings it out of its plane and the drag damps it there.
// 3. The towed cable of EquilibriumTowedCable (equilibrium_test.cpp) with the current along any
//    horizontal direction: every link at the critical angle, leaning along the current.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>

#include "core/line_equilibrium.h"
#include "core/forces.h"
#include "test_support.h"

namespace cablefilm {
namespace {

using testing::StartData;

constexpr double kL = 100, kSpan = 90;                 // unstretched length, chord [m]
constexpr double kMu = 2.0, kArea = 2.5e-4, kE = 4e10;  // [kg/m], [m^2], [Pa]: EA = 1e7 N
constexpr double kD = 0.02, kCd = 1.2, kRho = 1025;     // [m], 1, [kg/m^3]
constexpr int kLinks = 30;
constexpr double kG = 9.80665;  // [m/s^2]

LineModel LineAcrossCurrent(double speed) {
  EnvironmentSpec sea;
  sea.fluid_density = kRho;
  sea.current = speed;
  sea.current_direction = Vec(0, 0, 1);  // across the vertical plane z = 0 of the ends
  return testing::UniformCable(kLinks, kL, kMu, kArea, kE, sea, EndMotion::Fixed(InPlane(0, 0)),
                               EndMotion::Fixed(InPlane(kSpan, 0)), kD, kCd);
}

// The discrete equations of eq. (1) at rest, written out here: on free station j,
//   T_j t_j - T_{j-1} t_{j-1} + (D_{j-1} + D_j) / 2 - w_j e_y = 0,
// T_k = EA (|r_{k+1} - r_k| - l) / l (>= 0) along the unit tangent t_k, the drag of link k
// D_k = -(1/2) rho Cd d l |q| q with q the part of the link's relative velocity (here -U, the
// stations at rest) across it, and w_j the net weight of half of each link beside the station.
class OwnEquations {
 public:
  explicit OwnEquations(double speed) : current_(0, 0, speed) {}

  Eigen::VectorXd Residual(const Eigen::VectorXd& free) const {
    Eigen::MatrixXd r(3, kLinks + 1);
    r.col(0) = Eigen::Vector3d(0, 0, 0);
    r.col(kLinks) = Eigen::Vector3d(kSpan, 0, 0);
    for (int j = 1; j < kLinks; ++j) r.col(j) = free.segment<3>(3 * (j - 1));
    const double l = kL / kLinks, EA = kE * kArea;
    const double w = (kMu - kRho * kArea) * 9.80665 * l;  // net weight of a link [N]
    const double f = 0.5 * kRho * kCd * kD * l;           // drag per (m/s)^2 of a link [N s^2/m^2]
    Eigen::MatrixXd link_force(3, kLinks), drag(3, kLinks);
    for (int k = 0; k < kLinks; ++k) {
      const Eigen::Vector3d chord = r.col(k + 1) - r.col(k);
      const Eigen::Vector3d t = chord / chord.norm();
      link_force.col(k) = std::max(0.0, EA * (chord.norm() - l) / l) * t;
      const Eigen::Vector3d rel = -current_;
      const Eigen::Vector3d q = rel - t.dot(rel) * t;
      drag.col(k) = -f * q.norm() * q;
    }
    Eigen::VectorXd out(3 * (kLinks - 1));
    for (int j = 1; j < kLinks; ++j)
      out.segment<3>(3 * (j - 1)) = link_force.col(j) - link_force.col(j - 1) +
                                    0.5 * (drag.col(j - 1) + drag.col(j)) -
                                    Eigen::Vector3d(0, w, 0);
    return out;
  }

  Eigen::MatrixXd Jacobian(const Eigen::VectorXd& free) const {
    const double h = 1e-6;  // [m]: central differences, error ~ h^2 f''' of a smooth residual
    Eigen::MatrixXd J(free.size(), free.size());
    for (int i = 0; i < free.size(); ++i) {
      Eigen::VectorXd a = free, b = free;
      a[i] += h;
      b[i] -= h;
      J.col(i) = (Residual(a) - Residual(b)) / (2 * h);
    }
    return J;
  }

  // The residual's rounding floor: the stiffness EA / l = 3e6 N/m times the positions'
  // rounding, a few 1e-16 of 100 m, is about 1e-7 N.
  static constexpr double kOwnFloor = 1e-6;  // [N]

  // Newton with halving of the step until the residual drops.
  Eigen::VectorXd Solve(Eigen::VectorXd x) const {
    for (int it = 0; it < 200; ++it) {
      const Eigen::VectorXd R = Residual(x);
      if (R.lpNorm<Eigen::Infinity>() < kOwnFloor) break;
      const Eigen::VectorXd dx = Jacobian(x).partialPivLu().solve(-R);
      double step = 1;
      while (step > 1e-6 && Residual(x + step * dx).norm() >= R.norm()) step *= 0.5;
      x += step * dx;
    }
    return x;
  }

 private:
  Eigen::Vector3d current_;
};

// A circular arc between the ends, 2 % longer than the line so that every link starts
// stretched (equal angles: equal chords), in the plane through the chord tilted from the
// vertical towards +z by the angle of the drag's load to the weight's.
Eigen::VectorXd OwnGuess(double speed) {
  const double w = (kMu - kRho * kArea) * 9.80665, k = 0.5 * kRho * kCd * kD * speed * speed;
  const double tilt = std::atan2(k, w);
  // Half-angle a of the arc: sin(a) / a = chord / arc, by bisection (the left side falls).
  double lo = 1e-6, hi = M_PI;
  for (int i = 0; i < 100; ++i) {
    const double a = 0.5 * (lo + hi);
    (std::sin(a) / a > kSpan / (1.02 * kL) ? lo : hi) = a;
  }
  const double a = 0.5 * (lo + hi), R = 0.5 * kSpan / std::sin(a);
  Eigen::VectorXd x(3 * (kLinks - 1));
  for (int j = 1; j < kLinks; ++j) {
    const double angle = -a + 2 * a * j / kLinks;  // from the vertical through the centre
    const double drop = R * std::cos(angle) - R * std::cos(a);
    x.segment<3>(3 * (j - 1)) = Eigen::Vector3d(0.5 * kSpan + R * std::sin(angle),
                                                -drop * std::cos(tilt), drop * std::sin(tilt));
  }
  return x;
}

Eigen::VectorXd FreeStations(const Points& x) {
  Eigen::VectorXd out(3 * (kLinks - 1));
  for (int j = 1; j < kLinks; ++j) out.segment<3>(3 * (j - 1)) = x.col(j);
  return out;
}

TEST(CrossCurrent, EquilibriumSolvesTheDiscreteEquations) {
  for (double U : {0.3, 1.0, 2.5}) {
    const OwnEquations own(U);
    const Eigen::VectorXd truth = own.Solve(OwnGuess(U));
    const double own_residual = own.Residual(truth).lpNorm<Eigen::Infinity>();
    ASSERT_LT(own_residual, OwnEquations::kOwnFloor) << U << " m/s: the test's own Newton did not converge";
    LineEquilibriumReport rep;
    const LineModel m = LineAcrossCurrent(U);
    const State st = SolveLineEquilibrium(m, &rep);
    const Eigen::VectorXd found = FreeStations(st.x);
    // The equilibrium solver stops at a residual R of up to 1e-9 of its force scale: it lies
    // J^-1 R from the root, to first order. The bound is twice that plus the test's own
    // residual's share, 1e-6 N over the stiffness EA / l: a part in 1e12 of the line.
    const Eigen::VectorXd R = own.Residual(found);
    const Eigen::MatrixXd J = own.Jacobian(truth);
    const double predicted = J.partialPivLu().solve(R).lpNorm<Eigen::Infinity>();
    const double diff = (found - truth).lpNorm<Eigen::Infinity>();
    double sideways = 0;
    for (int j = 1; j < kLinks; ++j) sideways = std::max(sideways, st.x(2, j));
    std::printf("[ cross ] %.1f m/s: %d iterations, the line swings %.3f m along the current; "
                "%.2e m from the test's own root (first-order prediction %.2e m), its residual "
                "there %.2e N\n",
                U, rep.iterations, sideways, diff, predicted, R.lpNorm<Eigen::Infinity>());
    EXPECT_LE(diff, 2 * predicted + 1e-12 * kL) << U << " m/s";
    // The line leans downstream by about the tilt of its load (drag over weight):
    // its lowest point's direction from the chord within a few degrees of atan(k / w).
    const double w = (kMu - kRho * kArea) * 9.80665, k = 0.5 * kRho * kCd * kD * U * U;
    const int mid = kLinks / 2;
    const double lean = std::atan2(st.x(2, mid), -st.x(1, mid));
    EXPECT_NEAR(lean, std::atan2(k, w), 5 * M_PI / 180) << U << " m/s";
  }
}

TEST(CrossCurrent, DynamicsSettleInTheEquilibrium) {
  const double U = 1.0;
  const LineModel still = LineAcrossCurrent(0.0), flowing = LineAcrossCurrent(U);
  const Points target = SolveLineEquilibrium(flowing).x;
  State st = SolveLineEquilibrium(still);  // at rest in its vertical plane
  testing::Stepper stepper(Scheme::kImplicit, 0.5, 1e-7);
  stepper.Initialize(flowing, st);
  const double dt = 0.05;
  double at_half = 0;
  const int steps = 4000;  // 200 s: some 25 periods of the line's slowest swing (~8 s)
  for (int k = 1; k <= steps; ++k) {
    stepper.Step(flowing, st, dt);
    if (k == steps / 2) at_half = (st.x - target).cwiseAbs().maxCoeff();
  }
  const double at_end = (st.x - target).cwiseAbs().maxCoeff();
  const double swing = target.row(2).maxCoeff();
  std::printf("[ cross ] dynamics from the still equilibrium: %.2e m from the current's "
              "equilibrium after 100 s, %.2e m after 200 s (the swing is %.2f m)\n",
              at_half, at_end, swing);
  // The drag damps the swing across the current with a rate of order f U / m per link (the
  // linearised quadratic drag): the distance shrinks by orders of magnitude each 100 s, to the
  // integrator's tolerance; 1e-4 m is 1e-4 of the swing, and it must still be shrinking.
  EXPECT_LT(at_end, 1e-4 * swing);
  EXPECT_LT(at_end, at_half);
}

TEST(CrossCurrent, TowedCableLeansAlongAnyHeading) {
  const double L = 200, d = 0.02, mu = 2.0, area = 2.5e-4, E = 4e10, rho = 1025, Cd = 1.2;
  const int n = 20;
  const double U = 1.0;
  for (double heading_deg : {0.0, 30.0, 90.0, 147.0, -100.0}) {
    EnvironmentSpec sea;
    sea.fluid_density = rho;
    sea.current = U;
    sea.current_direction = Horizontal(heading_deg * M_PI / 180);
    const LineModel m = testing::UniformCable(n, L, mu, area, E, sea, EndMotion::Fixed(InPlane(0, 0)),
                                          EndMotion::Free(InPlane(0, -L)), d, Cd);
    LineEquilibriumReport rep;
    State st;
    ASSERT_NO_THROW(st = SolveLineEquilibrium(m, &rep)) << heading_deg << " deg";
    // As in EquilibriumTowedCable: w_l sin(theta) = k U^2 cos^2(theta) for every link.
    const double l = L / n, wl = (mu - rho * area) * kG * l, k = 0.5 * rho * Cd * d * l;
    const double a = k * U * U;
    const double theta = std::asin((-wl + std::sqrt(wl * wl + 4 * a * a)) / (2 * a));
    const Vec along = sea.current_direction;
    ForceWorkspace ws(m.line.links);
    ComputeGeometry(st.x, ws.geometry);
    double angle_err = 0, off_heading = 0;
    for (int i = 0; i < n; ++i) {
      const Vec t = ws.geometry.tangent.col(i);
      const double downstream = t.dot(along), across = t.dot(Vec(0, 1, 0).cross(along));
      angle_err = std::max(angle_err, std::abs(std::atan2(downstream, -t.y()) - theta));
      off_heading = std::max(off_heading, std::abs(across));
    }
    std::printf("[ towed ] current along %6.1f deg: critical angle error %.1e rad, off the "
                "current's vertical plane by %.1e\n",
                heading_deg, angle_err, off_heading);
    // The bound of EquilibriumTowedCable: 4 n r / w_l for a residual r per component; the line
    // stays in the current's vertical plane to the same order.
    const double r = rep.residual;
    EXPECT_LT(angle_err, 4 * n * r / wl + 1e-12) << heading_deg << " deg";
    EXPECT_LT(off_heading, 4 * n * r / wl + 1e-12) << heading_deg << " deg";
  }
}

}  // namespace
}  // namespace cablefilm
