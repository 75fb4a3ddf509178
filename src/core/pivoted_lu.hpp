#pragma once
// LU factors with partial pivoting of a small dense matrix (the link system's active rows, a
// dozen or two), P A = L U, as Eigen::PartialPivLU computes them, to the bit. Up to 16 rows
// Eigen factors column by column (unblocked), and each column's update of a dynamic-size
// block costs more in set-up than in arithmetic at that size; here the same operations run as
// plain loops: the first largest |a_ik| as pivot, an exact division, each update a_ij - l_i u_j
// rounded once. Larger matrices take Eigen's blocked algorithm itself (its panel products sum
// in another order). The solves are Eigen's triangular solves, as PartialPivLU::solve does
// them; no 1-norm is kept (PartialPivLU keeps it for rcond(), unused here).
#include <Eigen/Core>
#include <vector>

#include "core/types.hpp"

namespace pound {

class PivotedLu {
 public:
  static constexpr Index kUnblockedRows = 16;  // Eigen's own bound for its unblocked algorithm

  void compute(const Matrix& a);
  // x = A^-1 b (non-finite where A is singular, as Eigen's).
  void solve(const Vector& b, Vector& x) const;
  const Matrix& factors() const { return lu_; }  // L below the diagonal (unit), U on and above

 private:
  void factor_unblocked();

  Matrix lu_;
  Eigen::Transpositions<Eigen::Dynamic, Eigen::Dynamic, int> transpositions_;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation_;
};

}  // namespace pound
