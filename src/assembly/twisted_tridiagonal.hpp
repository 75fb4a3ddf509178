#pragma once
// Solver for a symmetric positive definite tridiagonal matrix that is factored once and solved
// every step. Each substitution sweep is a chain of dependent multiply-adds, so its speed is set
// by latency, not arithmetic. To run several chains at once the matrix is split into its
// independent blocks (the rods of a rod pair are uncoupled until the link acts) and each block
// gets a twisted factorisation: L D L^T from the top and U D U^T from the bottom meeting in the
// middle (Meurant 1992, "A review on the inverse of symmetric tridiagonal and block tridiagonal
// matrices"). All chains then advance in lockstep, which the CPU overlaps.
#include <Eigen/SparseCore>
#include <vector>

#include "core/types.hpp"

namespace pound::assembly {

class TwistedTridiagonal {
 public:
  // The matrix must be tridiagonal; throws std::domain_error on a non-positive pivot.
  explicit TwistedTridiagonal(const Eigen::SparseMatrix<double>& matrix);
  void solve(const Vector& rhs, Vector& solution) const;
  Index size() const { return static_cast<Index>(inverse_pivot_.size()); }
  std::size_t chains() const { return chains_.size(); }

 private:
  struct Block {
    Index first;        // a
    Index twist;        // k, a <= k < b
    Index end;          // b
    double from_above;  // l_k (0 when k == a)
    double from_below;  // u_k (0 when k == b - 1)
  };
  // A run of rows from a block end to (not including) its twist: rows start, start + step, ...
  struct Chain {
    Index start;
    Index step;  // +1 for the top part, -1 for the bottom part
    Index length;
  };
  void factor_block(Index a, Index b, const std::vector<double>& diagonal,
                    const std::vector<double>& off);
  double factor_top(Index a, Index k, const std::vector<double>& diagonal,
                    const std::vector<double>& off);
  double factor_bottom(Index k, Index b, const std::vector<double>& diagonal,
                       const std::vector<double>& off);

  std::vector<Block> blocks_;
  std::vector<Chain> chains_;
  Index common_length_ = 0;  // shortest chain: the lockstep part
  // multiplier_[i]: l_i (row i on row i-1) in top parts, u_i (row i on row i+1) in bottom parts.
  std::vector<double> multiplier_;
  std::vector<double> inverse_pivot_;
};

}  // namespace pound::assembly
