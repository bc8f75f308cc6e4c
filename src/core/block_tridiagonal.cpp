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
  inverse_.resize(n);
}

void BlockTridiagonal::SetZero() {
  for (int i = 0; i < size(); ++i) {
    lower[i].setZero();
    diag[i].setZero();
    upper[i].setZero();
    rhs[i].setZero();
  }
}

bool BlockTridiagonal::Factor(int first, int last) {
  first_ = first;
  last_ = last;
  for (int i = first; i <= last; ++i) {
    Mat pivot = diag[i];
    if (i > first) pivot.noalias() -= lower[i] * c_prime_[i - 1];
    double det;
    bool invertible;
    pivot.computeInverseAndDetWithCheck(inverse_[i], det, invertible, 0.0);  // one cofactor pass
    const double scale = pivot.cwiseAbs().maxCoeff();
    static_assert(kDim == 3, "det scales as scale^kDim");
    if (!invertible || !(std::abs(det) > 1e-14 * scale * scale * scale)) return false;
    if (i < last) c_prime_[i].noalias() = inverse_[i] * upper[i];
  }
  return true;
}

template <class Block>
void BlockTridiagonal::SolveRange(std::vector<Block>& b) const {
  for (int i = first_; i <= last_; ++i) {
    if (i > first_) b[i].noalias() -= lower[i] * b[i - 1];
    b[i] = (inverse_[i] * b[i]).eval();
  }
  for (int i = last_ - 1; i >= first_; --i) b[i].noalias() -= c_prime_[i] * b[i + 1];
}

template void BlockTridiagonal::SolveRange<Vec>(std::vector<Vec>&) const;
template void BlockTridiagonal::SolveRange<Mat>(std::vector<Mat>&) const;

bool BlockTridiagonal::Solve() {
  if (!Factor(0, size() - 1)) return false;
  SolveFactored(rhs);
  return true;
}

}  // namespace cablefilm
