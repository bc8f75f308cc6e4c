// The block Thomas solver against a dense LU solve of the same system.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "core/block_tridiagonal.h"
#include "core/vec.h"

namespace cablefilm {
namespace {

TEST(BlockTridiagonal, MatchesDenseSolve) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n : {1, 2, 7, 50}) {
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

TEST(BlockTridiagonal, ReportsSingularPivot) {
  BlockTridiagonal sys(2);
  sys.SetZero();
  sys.diag[0] << 1, 2, 0, 2, 4, 0, 0, 0, 1;  // singular: the first two rows are parallel
  sys.diag[1].setIdentity();
  EXPECT_FALSE(sys.Solve());
}

}  // namespace
}  // namespace cablefilm
