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
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    Eigen::VectorXd b(2 * n);
    for (int i = 0; i < n; ++i) {
      for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c) {
          if (i > 0) sys.lower[i](r, c) = u(rng);
          if (i + 1 < n) sys.upper[i](r, c) = u(rng);
          sys.diag[i](r, c) = u(rng);
        }
      // Block diagonally dominant: the diagonal outweighs the off-diagonal row sums.
      sys.diag[i] += 6.0 * Mat::Identity();
      const double first = u(rng);  // drawn in order: argument order differs by compiler
      sys.rhs[i] = Vec(first, u(rng));
      A.block<2, 2>(2 * i, 2 * i) = sys.diag[i];
      if (i > 0) A.block<2, 2>(2 * i, 2 * i - 2) = sys.lower[i];
      if (i + 1 < n) A.block<2, 2>(2 * i, 2 * i + 2) = sys.upper[i];
      b.segment<2>(2 * i) = sys.rhs[i];
    }
    const Eigen::VectorXd x = A.fullPivLu().solve(b);
    ASSERT_TRUE(sys.Solve());
    double err = 0;
    for (int i = 0; i < n; ++i) err = std::max(err, (sys.rhs[i] - x.segment<2>(2 * i)).norm());
    // Both are backward stable on a well-conditioned (dominant) system: ~1e-15.
    EXPECT_LT(err, 1e-13 * x.norm()) << "n = " << n;
  }
}

TEST(BlockTridiagonal, ReportsSingularPivot) {
  BlockTridiagonal sys(2);
  sys.SetZero();
  sys.diag[0] << 1, 2, 2, 4;  // singular
  sys.diag[1].setIdentity();
  EXPECT_FALSE(sys.Solve());
}

}  // namespace
}  // namespace cablefilm
