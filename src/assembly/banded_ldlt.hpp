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
  // The factors A = L D L^T: lower()(k, i) = L(i, i - k - 1) for k < bandwidth (column i holds
  // row i of L), and 1 / D(i).
  const Matrix& lower() const { return lower_; }
  const Vector& inverse_pivots() const { return inverse_pivot_; }

  // Half-bandwidth of a symmetric sparse matrix: max |i - j| over its entries.
  static Index bandwidth_of(const Eigen::SparseMatrix<double>& matrix);

 private:
  template <Index Band>
  void substitute(const double* rhs, double* x) const;
  template <Index Band>
  void substitute_in_registers(const double* rhs, double* x) const;

  Index size_;
  Index bandwidth_;
  // lower_(k, i) = L(i, i - k - 1) for k < b; stored by column, so that a row of L is contiguous.
  Matrix lower_;
  Vector inverse_pivot_;  // 1 / D(i)
};

}  // namespace pound::assembly
