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

// P's LU factors with partial pivoting (P's rows in the order `rows`: row k of L U is row
// rows[k] of P), in `lu`: L's multipliers below the diagonal (its unit diagonal implied), U above
// it and the reciprocals of U's diagonal on it. False when P is singular to working precision
// (InvertPivot's test, on det P = +-u00 u11 u22).
[[gnu::always_inline]] inline bool FactorPivot(const Mat& P, Mat& lu,
                                               std::array<std::uint8_t, 3>& rows) {
  static_assert(kDim == 3, "a 3x3 factoring");
  lu = P;
  rows = {0, 1, 2};
  const double scale = P.cwiseAbs().maxCoeff();
  double det = 1;
  for (int k = 0; k < kDim; ++k) {
    int p = k;
    for (int r = k + 1; r < kDim; ++r)
      if (std::abs(lu(r, k)) > std::abs(lu(p, k))) p = r;
    if (p != k) {
      lu.row(p).swap(lu.row(k));
      std::swap(rows[p], rows[k]);
    }
    const double pivot = lu(k, k);
    det *= pivot;
    if (!(pivot != 0)) return false;
    const double inverse = 1.0 / pivot;
    lu(k, k) = inverse;
    for (int r = k + 1; r < kDim; ++r) {
      const double f = lu(r, k) * inverse;
      lu(r, k) = f;
      for (int c = k + 1; c < kDim; ++c) lu(r, c) -= f * lu(k, c);
    }
  }
  return std::abs(det) > 1e-14 * scale * scale * scale;
}

// x = P^-1 b from FactorPivot's factors, in place (b: one column or kDim of them).
[[gnu::always_inline]] inline void SolvePivot(const Mat& lu, const std::array<std::uint8_t, 3>& rows,
                                              Vec& b) {
  const double y0 = b[rows[0]];
  const double y1 = b[rows[1]] - lu(1, 0) * y0;
  const double y2 = b[rows[2]] - lu(2, 0) * y0 - lu(2, 1) * y1;
  const double x2 = y2 * lu(2, 2);
  const double x1 = (y1 - lu(1, 2) * x2) * lu(1, 1);
  b[0] = (y0 - lu(0, 1) * x1 - lu(0, 2) * x2) * lu(0, 0);
  b[1] = x1;
  b[2] = x2;
}
[[gnu::always_inline]] inline void SolvePivot(const Mat& lu, const std::array<std::uint8_t, 3>& rows,
                                              Mat& b) {
  for (int c = 0; c < kDim; ++c) {
    Vec column = b.col(c);
    SolvePivot(lu, rows, column);
    b.col(c) = column;
  }
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
  // The factors' own arrays (none in place; a Factor in another mode makes them then).
  if (!in_place) {
    c_prime_.resize(n);
    inverse_.resize(n);
  }
  if (factored_pivots || in_place) rows_.resize(n);
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
  factored_ = factored_pivots || in_place;
  in_place_ = in_place;
  const std::size_t n = diag.size();
  if (!in_place_) {  // no-ops once made
    c_prime_.resize(n);
    inverse_.resize(n);
  }
  if (factored_) rows_.resize(n);
  if (in_place_) return FactorRange<true, true>(first, last);
  return factored_ ? FactorRange<true, false>(first, last) : FactorRange<false, false>(first, last);
}

template <bool kFactored, bool kInPlace>
bool BlockTridiagonal::FactorRange(int first, int last) {
  first_ = first;
  last_ = last;
  middle_ = first + (last - first) / 2;
  if (last < first) return true;  // no rows (a line whose stations are all prescribed)
  const int p = middle_;
  // Row i's eliminated block: c_prime_, or in place the upper block above the middle row and
  // the lower one below it (each read for the last time where it is eliminated); its pivot's
  // inverse or factors: inverse_, or in place the diagonal block.
  auto c = [&](int i) -> Mat& {
    if constexpr (kInPlace) return i < p ? upper[i] : lower[i];
    else return c_prime_[i];
  };
  auto pivot_of = [&](int i) -> Mat& {
    if constexpr (kInPlace) return diag[i];
    else return inverse_[i];
  };
  // Pivot i's inverse, or its factors; and c = P^-1 b for b its upper or lower block.
  auto take = [&](const Mat& pivot, int i, const Mat& b) {
    if constexpr (kFactored) {
      const Mat copy = pivot;  // (in place, the pivot may be the diagonal block it replaces)
      if (!FactorPivot(copy, pivot_of(i), rows_[i])) return false;
      if (&c(i) != &b) c(i) = b;
      SolvePivot(pivot_of(i), rows_[i], c(i));
    } else {
      if (!InvertPivot(pivot, inverse_[i])) return false;
      Product(inverse_[i], b, c_prime_[i]);
    }
    return true;
  };
  // Row s from the top (i) and row s from the bottom (k) in one pass: two chains that do not
  // wait for each other.
  Mat pivot;
  for (int s = 0;; ++s) {
    const int i = first + s, k = last - s;
    const bool top = i < p, bottom = k > p;
    if (!top && !bottom) break;
    if (top) {
      if (i > first) EliminatedPivot(diag[i], lower[i], c(i - 1), pivot);
      if (!take(i > first ? pivot : diag[i], i, upper[i])) return false;
    }
    if (bottom) {
      if (k < last) EliminatedPivot(diag[k], upper[k], c(k + 1), pivot);
      if (!take(k < last ? pivot : diag[k], k, lower[k])) return false;
    }
  }
  pivot = diag[p];
  if (p > first) pivot.noalias() -= lower[p] * c(p - 1);
  if (p < last) pivot.noalias() -= upper[p] * c(p + 1);
  if constexpr (kFactored) return FactorPivot(pivot, pivot_of(p), rows_[p]);
  return InvertPivot(pivot, inverse_[p]);
}

template <class Block>
void BlockTridiagonal::SolveRange(std::vector<Block>& b) const {
  if (in_place_) SolveRangeWith<true, true>(b);
  else if (factored_) SolveRangeWith<true, false>(b);
  else SolveRangeWith<false, false>(b);
}

template <bool kFactored, bool kInPlace, class Block>
void BlockTridiagonal::SolveRangeWith(std::vector<Block>& b) const {
  const int first = first_, last = last_, p = middle_;
  if (last < first) return;
  auto c = [&](int i) -> const Mat& {  // as in FactorRange
    if constexpr (kInPlace) return i < p ? upper[i] : lower[i];
    else return c_prime_[i];
  };
  auto apply = [&](int i) {  // b_i = P_i^-1 b_i
    if constexpr (kInPlace) SolvePivot(diag[i], rows_[i], b[i]);
    else if constexpr (kFactored) SolvePivot(inverse_[i], rows_[i], b[i]);
    else b[i] = (inverse_[i] * b[i]).eval();
  };
  for (int s = 0;; ++s) {  // eliminated towards the middle row from both ends
    const int i = first + s, k = last - s;
    const bool top = i < p, bottom = k > p;
    if (!top && !bottom) break;
    if (top) {
      if (i > first) b[i].noalias() -= lower[i] * b[i - 1];
      apply(i);
    }
    if (bottom) {
      if (k < last) b[k].noalias() -= upper[k] * b[k + 1];
      apply(k);
    }
  }
  if (p > first) b[p].noalias() -= lower[p] * b[p - 1];
  if (p < last) b[p].noalias() -= upper[p] * b[p + 1];
  apply(p);
  for (int s = 1;; ++s) {  // and substituted back from it
    const int i = p - s, k = p + s;
    const bool top = i >= first, bottom = k <= last;
    if (!top && !bottom) break;
    if (top) b[i].noalias() -= c(i) * b[i + 1];
    if (bottom) b[k].noalias() -= c(k) * b[k - 1];
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
