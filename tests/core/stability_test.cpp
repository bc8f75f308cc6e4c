// The explicit scheme's stability limit (src/core/stability.*), computed once from the model at
// rest, against the exact highest frequency of the linearised cable in states far from rest:
// stretched by up to 10 % (the geometric stiffness T/L), curved, partly slack, in water (the
// normal added mass of the links) and with a prism. The exact frequency comes from the
// generalised eigenproblem K phi = omega^2 M phi, with K = -dF/dx by central differences of the
// station forces and M the stations' 2x2 inertia at that state, solved densely here.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/forces.h"
#include "core/stability.h"

namespace cablefilm {
namespace {

// Two sections (wire and a softer, lighter rope) in sea water, a heavy prism at station 7, both
// ends fixed.
LineModel Line(int links) {
  SectionSpec wire{20.0, links / 2, 0.0254, 5.067e-4, 2.75, 9.0e10, 1.2, 1.0};
  SectionSpec rope{20.0, links - links / 2, 0.0508, 2.027e-3, 1.70, 2.0e9, 1.2, 1.0};
  PrismSpec weight;
  weight.station = 7;
  weight.mass = 450;
  weight.volume = 0.06;
  weight.added_volume = Vec(0.06, 0.03, 0.06);
  weight.drag_coefficient = Vec(1, 1, 1);
  weight.drag_area = Vec(0.16, 0.16, 0.16);
  EnvironmentSpec env;
  env.fluid_density = 1025;
  return MakeLineModel({wire, rope}, {weight}, env, EndMotion::Fixed(InPlane(0, 0)),
                         EndMotion::Fixed(InPlane(40, 0)), LinkLaw::kElastic);
}

// omega_max^2 of the linearised free stations at x (v = 0: no drag, so the forces are the
// tensions and the weights, and K is the Hessian of the potential).
double HighestEigenvalue(const LineModel& m, const Points& x) {
  const int j0 = m.first_free(), n = m.last_free() - j0 + 1;
  ForceWorkspace ws(m.line.links);
  const Points v = Points::Zero(kDim, m.stations());
  auto forces = [&](const Points& y) {
    ComputeGeometry(y, ws.geometry);
    ComputeHookeTensions(m, ws.geometry, ws.tension);
    ComputeStationForces(m, SceneWater(m), ws.geometry, ws.tension, v, ws.force);
    return Points(ws.force);
  };
  Eigen::MatrixXd K(kDim * n, kDim * n), M = Eigen::MatrixXd::Zero(kDim * n, kDim * n);
  const double h = 1e-7 * m.line.rest_length.minCoeff();
  for (int c = 0; c < kDim * n; ++c) {
    Points xp = x, xm = x;
    xp(c % kDim, j0 + c / kDim) += h;
    xm(c % kDim, j0 + c / kDim) -= h;
    const Points df = (forces(xp) - forces(xm)) / (2 * h);
    for (int r = 0; r < kDim * n; ++r) K(r, c) = -df(r % kDim, j0 + r / kDim);
  }
  K = 0.5 * (K + K.transpose()).eval();
  ComputeGeometry(x, ws.geometry);
  for (int i = 0; i < n; ++i) M.block<kDim, kDim>(kDim * i, kDim * i) = StationInertia(m, ws.geometry, j0 + i);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M, Eigen::EigenvaluesOnly);
  return es.eigenvalues().maxCoeff();
}

// Stations along a wave winding up and down (elevation a cos(0.7 j)) and sideways (azimuth
// a/2 sin(0.9 j)), link j stretched by strain[j] (negative: slack).
Points WavyState(const LineModel& m, double amplitude, const std::vector<double>& strain) {
  Points x(kDim, m.stations());
  x.col(0).setZero();
  for (int j = 0; j < m.line.links; ++j) {
    const double up = amplitude * std::cos(0.7 * j), side = 0.5 * amplitude * std::sin(0.9 * j);
    x.col(j + 1) = x.col(j) + m.line.rest_length[j] * (1 + strain[j]) *
                                  Vec(std::cos(up) * std::cos(side), std::sin(up),
                                      std::cos(up) * std::sin(side));
  }
  return x;
}

TEST(StabilityLimit, HoldsInStretchedCurvedSlackStatesWithAddedMass) {
  const LineModel m = Line(16);
  const StabilityLimit limit = ComputeStabilityLimit(m);
  const double bound = limit.omega_max * limit.omega_max;
  struct Case {
    const char* what;
    double amplitude;
    std::vector<double> strain;
  };
  std::vector<Case> cases;
  cases.push_back({"straight, strain 1e-4", 0.0, std::vector<double>(16, 1e-4)});
  cases.push_back({"curved (0.6 rad), strain 1e-3", 0.6, std::vector<double>(16, 1e-3)});
  std::vector<double> big(16), mixed(16);
  for (int j = 0; j < 16; ++j) {
    big[j] = 0.1 * (1 + j % 3) / 3;                // 3 % to 10 %
    mixed[j] = j % 4 == 1 ? -0.02 : 0.05 * (j % 2);  // slack, unstrained-ish, 5 %
  }
  mixed[3] = 0.1;
  cases.push_back({"curved (1.2 rad), strain 3 % to 10 %", 1.2, big});
  cases.push_back({"curved (0.9 rad), some links slack, others to 10 %", 0.9, mixed});
  for (const Case& c : cases) {
    Points x = WavyState(m, c.amplitude, c.strain);
    // The far end fixed where the state puts it.
    LineModel at = m;
    at.ends.end = EndMotion::Fixed(x.col(m.line.links));
    const double lambda = HighestEigenvalue(at, x);
    std::printf("[ stability ] %s: omega_max^2 %.6e, Gershgorin bound %.6e, ratio %.4f\n", c.what,
                lambda, bound, lambda / bound);
    // The bound holds in every state: a taut link's stiffness (sigma E / l) t t^T +
    // (T / L)(I - t t^T) has norm sigma E / l, since T / L < sigma E / l at any strain, and the
    // station inertia only grows with the added mass. 1e-6 covers the differencing.
    EXPECT_LE(lambda, bound * (1 + 1e-6)) << c.what;
  }
  // And it is close (not a vacuous bound): for the straight, taut line the highest frequency is
  // within 15 % of it in omega^2 (the discrete axial spectrum of the stiffest section; its end
  // stations couple to the softer rope and the fixed end).
  const double straight = HighestEigenvalue(m, WavyState(m, 0.0, std::vector<double>(16, 1e-4)));
  EXPECT_GT(straight / bound, 0.85);
}

}  // namespace
}  // namespace cablefilm
