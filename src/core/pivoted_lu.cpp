#include "core/pivoted_lu.hpp"

#include <Eigen/LU>
#include <cmath>
#include <utility>

#include "core/packets.hpp"

namespace pound {

void PivotedLu::compute(const Matrix& a) {
  lu_ = a;
  const Index n = lu_.rows();
  transpositions_.resize(n);
  if (n <= kUnblockedRows) {
    factor_unblocked();
  } else {
    int swaps = 0;
    Eigen::internal::partial_lu_inplace(lu_, transpositions_, swaps);
  }
  permutation_ = transpositions_;
}

// Eigen's partial_lu_impl::unblocked_lu, step for step.
void PivotedLu::factor_unblocked() {
  const Index n = lu_.rows();
  double* const data = lu_.data();
  for (Index k = 0; k < n; ++k) {
    double* const column = data + k * n;
    // The first of the largest magnitudes (Eigen's maxCoeff: strictly larger replaces).
    Index pivot_row = k;
    double biggest = std::abs(column[k]);
    for (Index i = k + 1; i < n; ++i)
      if (const double score = std::abs(column[i]); score > biggest) {
        biggest = score;
        pivot_row = i;
      }
    transpositions_.indices()[k] = static_cast<int>(pivot_row);
    if (biggest != 0.0) {
      if (pivot_row != k)
        for (Index j = 0; j < n; ++j) std::swap(data[j * n + k], data[j * n + pivot_row]);
      const double pivot = column[k];
      for (Index i = k + 1; i < n; ++i) column[i] /= pivot;
    }
    // A zero pivot leaves its column as it is, as Eigen does (the solve then gives non-finite
    // values, which the caller handles).
    for (Index j = k + 1; j < n; ++j) {
      double* const target = data + j * n;
      const double upper = target[k];
      const Packet4 upper_packet = broadcast(upper);
      Index i = k + 1;
      for (; i + 4 <= n; i += 4)
        store_packet(multiply_add(-load_packet(column + i), upper_packet, load_packet(target + i)),
                     target + i);
      for (; i < n; ++i) target[i] = multiply_add(-column[i], upper, target[i]);
    }
  }
}

void PivotedLu::solve(const Vector& b, Vector& x) const {
  x = permutation_ * b;
  lu_.triangularView<Eigen::UnitLower>().solveInPlace(x);
  lu_.triangularView<Eigen::Upper>().solveInPlace(x);
}

}  // namespace pound
