#pragma once
// LDL^T factorisation of a symmetric positive definite band matrix (half-bandwidth b), for the
// constant effective matrix of the linear part: factored once, solved every step in O(n b).
// A chain of rods numbered in node order has b = 1 per DOF direction.
#include <Eigen/SparseCore>

#include "core/types.hpp"

namespace pound::assembly {

class BandedLdlt {
 public:
  // Throws std::domain_error naming the equation whose pivot is not positive.
  explicit BandedLdlt(const Eigen::SparseMatrix<double>& matrix);

  Index size() const { return size_; }
  Index bandwidth() const { return bandwidth_; }
  void solve(const Vector& rhs, Vector& solution) const;

  // Half-bandwidth of a symmetric sparse matrix: max |i - j| over its entries.
  static Index bandwidth_of(const Eigen::SparseMatrix<double>& matrix);

 private:
  template <Index Band>
  void substitute(const double* rhs, double* x) const;

  Index size_;
  Index bandwidth_;
  // lower_(k, i) = L(i, i - k - 1) for k < b; stored column by row so a row is contiguous.
  Matrix lower_;
  Vector inverse_pivot_;  // 1 / D(i)
};

}  // namespace pound::assembly
