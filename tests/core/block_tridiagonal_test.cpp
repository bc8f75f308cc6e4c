// The block Thomas solver (from both ends towards the middle row) against a dense LU solve of
// the same system.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "core/block_tridiagonal.h"
#include "core/vec.h"

namespace cablefilm {
namespace {

TEST(BlockTridiagonal, MatchesDenseSolve) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n : {1, 2, 3, 7, 8, 50}) {  // odd and even: the two chains of equal length or not
    BlockTridiagonal sys(n);
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
    EXPECT_LT(err, 1e-13 * x.norm()) << "n = " << n;
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
  BlockTridiagonal sys(2);
  sys.SetZero();
  sys.diag[0] << 1, 2, 0, 2, 4, 0, 0, 0, 1;  // singular: the first two rows are parallel
  sys.diag[1].setIdentity();
  EXPECT_FALSE(sys.Solve());
  // In the chain from the top, from the bottom, and in the middle row of five.
  for (int singular : {0, 2, 4}) {
    BlockTridiagonal five(5);
    five.SetZero();
    for (int i = 0; i < 5; ++i) five.diag[i].setIdentity();
    five.diag[singular] << 1, 2, 0, 2, 4, 0, 0, 0, 1;
    EXPECT_FALSE(five.Solve()) << singular;
  }
}

}  // namespace
}  // namespace cablefilm
