#include "core/block_tridiagonal.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {
namespace {

// inverse = P^-1 by cofactors, written out in scalars: Eigen's inverse built its result entry
// by entry in memory that the products after it read two entries at a time, which stalls the
// store forwarding (a tenth of a long line's run in this factoring). False when P is singular
// to working precision.
[[gnu::always_inline]] inline bool InvertPivot(const Mat& P, Mat& inverse) {
  static_assert(kDim == 3, "a 3x3 inverse");
  const double a = P(0, 0), b = P(0, 1), c = P(0, 2);
  const double d = P(1, 0), e = P(1, 1), f = P(1, 2);
  const double g = P(2, 0), h = P(2, 1), i = P(2, 2);
  const double A = e * i - f * h, B = f * g - d * i, C = d * h - e * g;  // row 0's cofactors
  const double det = a * A + b * B + c * C;
  const double scale = std::max({std::abs(a), std::abs(b), std::abs(c), std::abs(d), std::abs(e),
                                  std::abs(f), std::abs(g), std::abs(h), std::abs(i)});
  if (!(std::abs(det) > 1e-14 * scale * scale * scale)) return false;  // (det scales as P^3)
  const double r = 1.0 / det;
  inverse << A * r, (c * h - b * i) * r, (b * f - c * e) * r,
             B * r, (a * i - c * g) * r, (c * d - a * f) * r,
             C * r, (b * g - a * h) * r, (a * e - b * d) * r;
  return true;
}

// pivot = D - A B, entry by entry in scalars (as the inverse: no entry stored alone and then
// loaded in a pair).
[[gnu::always_inline]] inline void EliminatedPivot(const Mat& D, const Mat& A, const Mat& B,
                                                   Mat& pivot) {
  for (int c = 0; c < kDim; ++c)
    for (int r = 0; r < kDim; ++r)
      pivot(r, c) = D(r, c) - (A(r, 0) * B(0, c) + A(r, 1) * B(1, c) + A(r, 2) * B(2, c));
}

// C = A B, likewise.
[[gnu::always_inline]] inline void Product(const Mat& A, const Mat& B, Mat& C) {
  for (int c = 0; c < kDim; ++c)
    for (int r = 0; r < kDim; ++r)
      C(r, c) = A(r, 0) * B(0, c) + A(r, 1) * B(1, c) + A(r, 2) * B(2, c);
}

}  // namespace

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
  middle_ = first + (last - first) / 2;
  if (last < first) return true;  // no rows (a line whose stations are all prescribed)
  const int p = middle_;
  // Row s from the top (i) and row s from the bottom (k) in one pass: two chains that do not
  // wait for each other.
  Mat pivot;
  for (int s = 0;; ++s) {
    const int i = first + s, k = last - s;
    const bool top = i < p, bottom = k > p;
    if (!top && !bottom) break;
    if (top) {
      if (i > first) EliminatedPivot(diag[i], lower[i], c_prime_[i - 1], pivot);
      if (!InvertPivot(i > first ? pivot : diag[i], inverse_[i])) return false;
      Product(inverse_[i], upper[i], c_prime_[i]);
    }
    if (bottom) {
      if (k < last) EliminatedPivot(diag[k], upper[k], c_prime_[k + 1], pivot);
      if (!InvertPivot(k < last ? pivot : diag[k], inverse_[k])) return false;
      Product(inverse_[k], lower[k], c_prime_[k]);
    }
  }
  pivot = diag[p];
  if (p > first) pivot.noalias() -= lower[p] * c_prime_[p - 1];
  if (p < last) pivot.noalias() -= upper[p] * c_prime_[p + 1];
  return InvertPivot(pivot, inverse_[p]);
}

template <class Block>
void BlockTridiagonal::SolveRange(std::vector<Block>& b) const {
  const int first = first_, last = last_, p = middle_;
  if (last < first) return;
  for (int s = 0;; ++s) {  // eliminated towards the middle row from both ends
    const int i = first + s, k = last - s;
    const bool top = i < p, bottom = k > p;
    if (!top && !bottom) break;
    if (top) {
      if (i > first) b[i].noalias() -= lower[i] * b[i - 1];
      b[i] = (inverse_[i] * b[i]).eval();
    }
    if (bottom) {
      if (k < last) b[k].noalias() -= upper[k] * b[k + 1];
      b[k] = (inverse_[k] * b[k]).eval();
    }
  }
  if (p > first) b[p].noalias() -= lower[p] * b[p - 1];
  if (p < last) b[p].noalias() -= upper[p] * b[p + 1];
  b[p] = (inverse_[p] * b[p]).eval();
  for (int s = 1;; ++s) {  // and substituted back from it
    const int i = p - s, k = p + s;
    const bool top = i >= first, bottom = k <= last;
    if (!top && !bottom) break;
    if (top) b[i].noalias() -= c_prime_[i] * b[i + 1];
    if (bottom) b[k].noalias() -= c_prime_[k] * b[k - 1];
  }
}

template void BlockTridiagonal::SolveRange<Vec>(std::vector<Vec>&) const;
template void BlockTridiagonal::SolveRange<Mat>(std::vector<Mat>&) const;

bool BlockTridiagonal::Solve() {
  if (!Factor(0, size() - 1)) return false;
  SolveFactored(rhs);
  return true;
}

}  // namespace cablefilm
