#pragma once
// A linear system whose matrix is block tridiagonal with kDim x kDim blocks, one block row per station:
//   lower_i x_{i-1} + diag_i x_i + upper_i x_{i+1} = rhs_i.
// Solved by block Gaussian elimination without pivoting (the block Thomas algorithm) in O(n);
// fine for the systems here, which are block diagonally dominant or symmetric definite.
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

  std::vector<Mat> lower, diag, upper;  // lower[0] and upper[n-1] are unused
  std::vector<Vec> rhs;

 private:
  std::vector<Mat> c_prime_;  // eliminated upper blocks
};

}  // namespace cablefilm
