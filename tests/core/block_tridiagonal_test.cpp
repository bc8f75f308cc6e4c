// The block Thomas solver (from both ends towards the middle row) against a dense LU solve of
// the same system.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "core/block_tridiagonal.h"
#include "core/vec.h"

namespace cablefilm {
namespace {

// The pivots as inverses (the integrators'), through their LU factors, and those written over
// the matrix (the statics').
enum class Pivots { kInverse, kFactored, kInPlace };
void Use(Pivots p, BlockTridiagonal& sys) {
  sys.factored_pivots = p != Pivots::kInverse;
  sys.in_place = p == Pivots::kInPlace;
}

TEST(BlockTridiagonal, MatchesDenseSolve) {
  for (Pivots pivots : {Pivots::kInverse, Pivots::kFactored, Pivots::kInPlace}) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n : {1, 2, 3, 7, 8, 50}) {  // odd and even: the two chains of equal length or not
    BlockTridiagonal sys(n);
    Use(pivots, sys);
    sys.SetZero();
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(kDim * n, kDim * n);
    Eigen::VectorXd b(kDim * n);
    for (int i = 0; i < n; ++i) {
      for (int r = 0; r < kDim; ++r)
        for (int c = 0; c < kDim; ++c) {
          if (i > 0) sys.lower[i](r, c) = u(rng);
          if (i + 1 < n) sys.upper[i](r, c) = u(rng);
          sys.diag[i](r, c) = u(rng);
        }
      // Block diagonally dominant: the diagonal outweighs the off-diagonal row sums.
      sys.diag[i] += 6.0 * Mat::Identity();
      for (int r = 0; r < kDim; ++r) sys.rhs[i](r) = u(rng);  // drawn in order, one a statement
      A.block<kDim, kDim>(kDim * i, kDim * i) = sys.diag[i];
      if (i > 0) A.block<kDim, kDim>(kDim * i, kDim * (i - 1)) = sys.lower[i];
      if (i + 1 < n) A.block<kDim, kDim>(kDim * i, kDim * (i + 1)) = sys.upper[i];
      b.segment<kDim>(kDim * i) = sys.rhs[i];
    }
    const Eigen::VectorXd x = A.fullPivLu().solve(b);
    ASSERT_TRUE(sys.Solve());
    double err = 0;
    for (int i = 0; i < n; ++i) err = std::max(err, (sys.rhs[i] - x.segment<kDim>(kDim * i)).norm());
    // Both are backward stable on a well-conditioned (dominant) system: ~1e-15.
    EXPECT_LT(err, 1e-13 * x.norm()) << "n = " << n << ", pivots " << int(pivots);
  }
  }
}

// A range of the rows factored alone (a coupled line's interior, coupled_step.h) and solved for
// kDim right-hand sides at once, against the dense solve of that range's blocks.
TEST(BlockTridiagonal, RangeWithMatrixRightHandSidesMatchesDenseSolve) {
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 12, first = 2, last = 9, m = last - first + 1;
  BlockTridiagonal sys(n);
  sys.SetZero();
  for (int i = 0; i < n; ++i) {
    for (int r = 0; r < kDim; ++r)
      for (int c = 0; c < kDim; ++c) {
        sys.lower[i](r, c) = u(rng);
        sys.upper[i](r, c) = u(rng);
        sys.diag[i](r, c) = u(rng);
      }
    sys.diag[i] += 6.0 * Mat::Identity();
  }
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(kDim * m, kDim * m);
  Eigen::MatrixXd B(kDim * m, kDim);
  std::vector<Mat> b(n, Mat::Zero());
  for (int i = first; i <= last; ++i) {
    const int k = i - first;
    A.block<kDim, kDim>(kDim * k, kDim * k) = sys.diag[i];
    if (i > first) A.block<kDim, kDim>(kDim * k, kDim * (k - 1)) = sys.lower[i];
    if (i < last) A.block<kDim, kDim>(kDim * k, kDim * (k + 1)) = sys.upper[i];
    for (int r = 0; r < kDim; ++r)
      for (int c = 0; c < kDim; ++c) b[i](r, c) = u(rng);
    B.block<kDim, kDim>(kDim * k, 0) = b[i];
  }
  const Eigen::MatrixXd X = A.fullPivLu().solve(B);
  ASSERT_TRUE(sys.Factor(first, last));
  sys.SolveFactored(b);
  double err = 0;
  for (int i = first; i <= last; ++i)
    err = std::max(err, (b[i] - X.block<kDim, kDim>(kDim * (i - first), 0)).norm());
  EXPECT_LT(err, 1e-13 * X.norm());  // as above
  for (int i : {0, 1, 10, 11}) EXPECT_EQ(b[i], Mat::Zero()) << i;  // rows outside untouched
}

// No rows (a line whose stations are all prescribed): nothing to do, and nothing read (the
// fuzzer's regression: the middle row of an empty range was read).
TEST(BlockTridiagonal, EmptySystemSolves) {
  BlockTridiagonal sys(0);
  EXPECT_TRUE(sys.Solve());
  EXPECT_TRUE(sys.rhs.empty());
}

TEST(BlockTridiagonal, ReportsSingularPivot) {
  for (Pivots pivots : {Pivots::kInverse, Pivots::kFactored, Pivots::kInPlace}) {
  BlockTridiagonal sys(2);
  Use(pivots, sys);
  sys.SetZero();
  sys.diag[0] << 1, 2, 0, 2, 4, 0, 0, 0, 1;  // singular: the first two rows are parallel
  sys.diag[1].setIdentity();
  EXPECT_FALSE(sys.Solve());
  // In the chain from the top, from the bottom, and in the middle row of five.
  for (int singular : {0, 2, 4}) {
    BlockTridiagonal five(5);
    Use(pivots, five);
    five.SetZero();
    for (int i = 0; i < 5; ++i) five.diag[i].setIdentity();
    five.diag[singular] << 1, 2, 0, 2, 4, 0, 0, 0, 1;
    EXPECT_FALSE(five.Solve()) << singular << ", pivots " << int(pivots);
  }
  }
}

// Newton's matrix of a chain at rest where it curves: each link's stiffness EA / l along it and
// T / l across it (EA = 4.93e8 N, T = 1e4 N: the 76 mm chain near its touchdown, 2.75 mm links),
// its direction turning by l / c a link (c = 9.5 m, the catenary's radius there), both ends
// held; loads of a link's weight (2.7 N) at every station. A pivot of it is cond EA / T = 5e4.
// The truth is the system itself: the residual b - A x of the solution, each row's three
// products summed apart from the solve. Applied as their inverses the pivots leave a residual
// that grows with the line (a backward error of cond(P) eps |P| a row, cond(P) times the
// factors'): at 2 x 10^5 links Newton's step left several newtons out of balance where the line
// bends, and the statics crawled (42 iterations; 6 with the factors).
TEST(BlockTridiagonal, FactoredPivotsAreBackwardStableOnAStiffCurvedChain) {
  const int n = 20000;                                       // free stations
  const double EA = 4.93e8, T = 1e4, l = 2.75e-3, c = 9.5;  // [N], [N], [m], [m]
  std::vector<Mat> K(n + 1);  // link k joins stations k - 1 and k (0 and n + 1 held)
  for (int k = 0; k <= n; ++k) {
    const double angle = k * l / c;
    const Vec t(std::cos(angle), std::sin(angle), 0.0);
    K[k] = (EA / l) * t * t.transpose() + (T / l) * (Mat::Identity() - t * t.transpose());
  }
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec> b(n);
  for (Vec& v : b) v = 2.7 * Vec(u(rng), u(rng), u(rng));  // [N]
  double residual[3] = {0, 0, 0};
  std::vector<Vec> solution[3];
  for (Pivots pivots : {Pivots::kInverse, Pivots::kFactored, Pivots::kInPlace}) {
    BlockTridiagonal sys(n);
    Use(pivots, sys);
    for (int i = 0; i < n; ++i) {
      sys.diag[i] = K[i] + K[i + 1];
      sys.upper[i] = -K[i + 1];
      sys.lower[i] = -K[i];
      sys.rhs[i] = b[i];
    }
    ASSERT_TRUE(sys.Solve());
    const int p = static_cast<int>(pivots);
    for (int i = 0; i < n; ++i) {
      Vec r = b[i] - (K[i] + K[i + 1]) * sys.rhs[i];
      if (i > 0) r += K[i] * sys.rhs[i - 1];
      if (i + 1 < n) r += K[i + 1] * sys.rhs[i + 1];
      residual[p] = std::max(residual[p], r.lpNorm<Eigen::Infinity>());
    }
    solution[p] = sys.rhs;
  }
  RecordProperty("residual_inverse_N", testing::PrintToString(residual[0]));
  RecordProperty("residual_factored_N", testing::PrintToString(residual[1]));
  std::printf("[ pivots ] curved chain of %d stations: largest out-of-balance force of the "
              "solution %.2e N with the pivots' inverses, %.2e N with their factors (loads "
              "2.7 N)\n", n, residual[0], residual[1]);
  // Backward stable: a row's residual some eps |A| |x|, |A| = 4 EA / l (its three blocks) and
  // |x| the largest displacement (0.3 m); 16 of them leave room for the rows' sums of 9
  // products (7.8e-4 N; measured 3.8e-6 N with the factors, 2.2e-2 N with the inverses).
  double reach = 0;  // [m]
  for (const Vec& x : solution[1]) reach = std::max(reach, x.lpNorm<Eigen::Infinity>());
  const double bound = 16 * std::numeric_limits<double>::epsilon() * (4 * EA / l) * reach;
  RecordProperty("backward_bound_N", testing::PrintToString(bound));
  EXPECT_LT(residual[1], bound);
  EXPECT_GT(residual[0], 10 * bound);  // the case it is about
  // In place the same arithmetic, to the last bit.
  for (int i = 0; i < n; ++i) ASSERT_EQ(solution[1][i], solution[2][i]) << i;
}

}  // namespace
}  // namespace cablefilm
