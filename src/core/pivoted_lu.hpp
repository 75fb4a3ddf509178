#pragma once
// LU factors with partial pivoting of a small dense matrix (the link system's active rows, a
// dozen or two), P A = L U, and its solves, as Eigen::PartialPivLU computes them, to the bit.
// Up to 16 rows Eigen factors column by column (unblocked) and solves in panels of 8 rows (each
// row below a panel less the sum, from 0 in column order, of the panel's terms); each of those
// steps on a dynamic-size block costs more in set-up than in arithmetic at that size, so here
// the same operations run as plain loops: the first largest |a_ik| as pivot, exact divisions,
// every update and sum rounded once per term (fused multiply-adds, as GCC fuses Eigen's code in
// the release build on x86-64-v3; not at -O1) except where Eigen's own scalar loop rounds the
// product first (tested against Eigen's code on every size, Path::eigen). From 17 to 64 rows
// (the link systems of buildings with yielding storeys: 35 Takeda storeys and their contacts)
// Eigen blocks its factorisation and its solves, whose set-up cost the Takeda buildings 13 % of
// their run; the same unblocked loops factor them here (equal to Eigen's only within rounding:
// its blocks sum the panel products in another order) and the solves are plain column sweeps.
// Larger matrices take Eigen's own code. No 1-norm is kept (PartialPivLU's, for rcond(), is
// unused here). The loops keep each entry's chain of operations but not Eigen's loop order: the
// factorisation takes two pivots per pass over the columns right of them, and a panel's sums are
// taken four rows to a packet, each lane its own row's chain (docs/performance.md).
#include <Eigen/Core>

#include "core/types.hpp"

namespace pound {

class PivotedLu {
 public:
  static constexpr Index kUnblockedRows = 16;  // Eigen's own bound for its unblocked algorithm
  static constexpr Index kLoopRows = 64;       // the loops' bound (Eigen's code past it)
  // `eigen`: Eigen's code at every size, the general path the loops are compared with.
  enum class Path { loops, eigen };

  void compute(const Matrix& a, Path path = Path::loops);
  // x = A^-1 b (non-finite where A is singular, as Eigen's).
  void solve(const Vector& b, Vector& x, Path path = Path::loops) const;
  const Matrix& factors() const { return lu_; }  // L below the diagonal (unit), U on and above

 private:
  void factor_unblocked();
  void take_pivot(Index k);
  void subtract_pivot_rows(Index k);
  void solve_unit_lower(double* x) const;
  void solve_upper(double* x) const;
  void solve_by_columns(double* x) const;  // both sweeps, past kUnblockedRows
  double panel_sum(Index t, Index start, Index end, const double* x, bool scalar_row) const;
  void subtract_panel_sums(Index first, Index last, Index start, Index end, double* x) const;

  Matrix lu_;
  Eigen::Transpositions<Eigen::Dynamic, Eigen::Dynamic, int> transpositions_;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> permutation_;
};

}  // namespace pound
