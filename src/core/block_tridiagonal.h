#pragma once
// A linear system whose matrix is block tridiagonal with kDim x kDim blocks, one block row per station:
//   lower_i x_{i-1} + diag_i x_i + upper_i x_{i+1} = rhs_i.
// Solved by block Gaussian elimination without pivoting in O(n), from both ends towards the
// middle row (a twisted block Thomas algorithm: the two chains of dependent 3x3 inverses and
// products run side by side in the processor, where one chain from the top waits on each
// inverse in turn); fine for the systems here, which are block diagonally dominant or
// symmetric definite.
// A range of its rows (the interior of a line whose end stations are shared with other lines,
// coupled_step.h) may be factored once and then solved for several right-hand sides.
//
// Each eliminated pivot block is applied either as its inverse (by cofactors: the fastest) or
// through its LU factors with partial pivoting (`factored_pivots`). The inverse is exact only to
// cond(P) eps of P^-1, and applied to a vector that is a backward error of cond(P) eps |P|: a
// pivot of a line at rest, EA / l along its link and only T / l across it (a chain: EA / T =
// 5e4), turns that into an out-of-balance force that Newton's step leaves behind where the line
// curves. The factors are backward stable, eps |P|, for about the same work (the statics of
// long lines use them: line_equilibrium.cpp).
#include <array>
#include <cstdint>
#include <vector>

#include "core/vec.h"

namespace cablefilm {

class BlockTridiagonal {
 public:
  BlockTridiagonal() = default;
  explicit BlockTridiagonal(int n) { Resize(n); }
  void Resize(int n);
  int size() const { return static_cast<int>(diag.size()); }
  void SetZero();

  // Solves in place: on return rhs holds x. Returns false (rhs undefined) when a pivot block is
  // singular to working precision.
  bool Solve();

  // The rows first..last alone (the blocks coupling them to rows outside left out): factors
  // them; false when a pivot block is singular to working precision.
  bool Factor(int first, int last);
  // After Factor(first, last): solves that range for the right-hand sides b[first..last] in
  // place (Vec: one right-hand side; Mat: kDim of them, column by column).
  void SolveFactored(std::vector<Vec>& b) const { SolveRange(b); }
  void SolveFactored(std::vector<Mat>& b) const { SolveRange(b); }

  std::vector<Mat> lower, diag, upper;  // lower[0] and upper[n-1] are unused
  std::vector<Vec> rhs;
  // The pivots applied through their LU factors (backward stable) instead of their inverses
  // (above); read by Factor (and Solve), and kept for the solves of what it factored.
  bool factored_pivots = false;
  // The factors written over the matrix (factored pivots; the matrix is gone once factored):
  // no arrays of their own, 2 of the 6 blocks a row (set it before Resize, which then makes
  // none). The statics, which make the matrix anew for each solve, use it.
  bool in_place = false;

 private:
  template <class Block>
  void SolveRange(std::vector<Block>& b) const;
  template <bool kFactored, bool kInPlace>
  bool FactorRange(int first, int last);
  template <bool kFactored, bool kInPlace, class Block>
  void SolveRangeWith(std::vector<Block>& b) const;

  int first_ = 0, last_ = -1;  // the factored range
  int middle_ = 0;             // its row where the eliminations from both ends meet
  bool factored_ = false;      // factored_pivots (or in_place) when it was factored
  bool in_place_ = false;      // in_place when it was factored
  std::vector<Mat> c_prime_;   // eliminated upper blocks above the middle row, lower below it
  std::vector<Mat> inverse_;   // inverses of the eliminated pivots, or their LU factors
  std::vector<std::array<std::uint8_t, 3>> rows_;  // the factors' row order (factored_pivots)
};

}  // namespace cablefilm
