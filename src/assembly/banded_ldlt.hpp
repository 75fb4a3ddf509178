#pragma once
// LDL^T factorisation of a symmetric positive definite band matrix (half-bandwidth b), for the
// constant effective matrix of the linear part: factored once, solved every step in O(n b).
// A chain of rods numbered in node order has b = 1 per DOF direction.
#include <Eigen/SparseCore>
#include <vector>

#include "core/types.hpp"

namespace pound::assembly {

class BandedLdlt {
 public:
  // Bandwidths 2 to this have their substitution unrolled, the last b values kept in registers.
  static constexpr Index kUnrolledBand = 8;

  // Throws std::domain_error naming the equation whose pivot is not positive.
  explicit BandedLdlt(const Eigen::SparseMatrix<double>& matrix);
  // The factors of the equations `rows` (increasing) alone, in this band, when no entry of L
  // joins them to the others (one or more connected components of the matrix): L's entries
  // between them as they are, zeros where their distance grew past the band. A row's sum then
  // takes the same products in the same order but for zeros, so solutions keep their bits.
  // (Factoring those equations' matrix anew can round otherwise: GCC vectorises the factor's
  // product loops differently for another bandwidth.)
  BandedLdlt restricted(const std::vector<Index>& rows) const;

  Index size() const { return size_; }
  Index bandwidth() const { return bandwidth_; }
  void solve(const Vector& rhs, Vector& solution) const;
  // a x_a = rhs_a and b x_b = rhs_b, each solution to the bit as solve() gives it. With the same
  // bandwidth (2 to 8) and both larger than it, the two substitutions go row by row side by side,
  // so that each one's chain of rows (a row waits for the one before it) fills the other's waits:
  // two structures that only links join (buildings that pound) in the time of the larger.
  static void solve_pair(const BandedLdlt& a, const Vector& rhs_a, Vector& x_a, const BandedLdlt& b,
                         const Vector& rhs_b, Vector& x_b);
  // The same on arrays of size() entries (each solution and its right-hand side may be one).
  void solve(const double* rhs, double* solution) const;
  static void solve_pair(const BandedLdlt& a, const double* rhs_a, double* x_a, const BandedLdlt& b,
                         const double* rhs_b, double* x_b);
  // The same for two groups of one system's equations: a's row i is equation places.a[i], b's
  // places.b[i]; right-hand sides read from rhs and solutions written to places.out at those
  // places, in the sweeps' own loads and stores (scratch_a, scratch_b: a.size() and b.size()
  // entries), to the same bits as gathered, solve_pair and scattered. False (nothing done)
  // outside solve_pair's paired case.
  struct PairPlaces {
    const Index* a;
    const Index* b;
    double* out;
  };
  static bool solve_pair_in_place(const BandedLdlt& a, const BandedLdlt& b,
                                  const PairPlaces& places, const double* rhs, double* scratch_a,
                                  double* scratch_b);
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
  template <Index Band, bool Placed>
  static void substitute_pair(const BandedLdlt& a, const double* rhs_a, double* x_a,
                              const BandedLdlt& b, const double* rhs_b, double* x_b,
                              const PairPlaces* places);

  Index size_;
  Index bandwidth_;
  // lower_(k, i) = L(i, i - k - 1) for k < b; stored by column, so that a row of L is contiguous.
  Matrix lower_;
  Vector inverse_pivot_;  // 1 / D(i)
};

}  // namespace pound::assembly
