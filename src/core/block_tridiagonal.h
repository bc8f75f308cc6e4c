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
#include "core/vec.h"
#include <vector>

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

 private:
  template <class Block>
  void SolveRange(std::vector<Block>& b) const;

  int first_ = 0, last_ = -1;  // the factored range
  int middle_ = 0;             // its row where the eliminations from both ends meet
  std::vector<Mat> c_prime_;   // eliminated upper blocks above the middle row, lower below it
  std::vector<Mat> inverse_;   // inverses of the eliminated pivots
};

}  // namespace cablefilm
