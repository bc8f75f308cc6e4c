#include "core/block_tridiagonal.h"

#include <Eigen/LU>
#include <cmath>

namespace cablefilm {

void BlockTridiagonal::Resize(int n) {
  lower.resize(n);
  diag.resize(n);
  upper.resize(n);
  rhs.resize(n);
  c_prime_.resize(n);
}

void BlockTridiagonal::SetZero() {
  for (int i = 0; i < size(); ++i) {
    lower[i].setZero();
    diag[i].setZero();
    upper[i].setZero();
    rhs[i].setZero();
  }
}

bool BlockTridiagonal::Solve() {
  const int n = size();
  for (int i = 0; i < n; ++i) {
    Mat pivot = diag[i];
    if (i > 0) {
      pivot.noalias() -= lower[i] * c_prime_[i - 1];
      rhs[i].noalias() -= lower[i] * rhs[i - 1];
    }
    Mat inv;
    double det;
    bool invertible;
    pivot.computeInverseAndDetWithCheck(inv, det, invertible, 0.0);  // one cofactor pass
    const double scale = pivot.cwiseAbs().maxCoeff();
    static_assert(kDim == 3, "det scales as scale^kDim");
    if (!invertible || !(std::abs(det) > 1e-14 * scale * scale * scale)) return false;
    if (i + 1 < n) c_prime_[i].noalias() = inv * upper[i];
    rhs[i] = inv * rhs[i];
  }
  for (int i = n - 2; i >= 0; --i) rhs[i].noalias() -= c_prime_[i] * rhs[i + 1];
  return true;
}

}  // namespace cablefilm
