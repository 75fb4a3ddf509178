#include "assembly/banded_ldlt.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "assembly/not_positive_definite.hpp"

namespace pound::assembly {

Index BandedLdlt::bandwidth_of(const Eigen::SparseMatrix<double>& matrix) {
  Index band = 0;
  for (Index col = 0; col < matrix.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, col); it; ++it)
      if (it.value() != 0.0) band = std::max(band, std::abs(it.row() - col));
  return band;
}

BandedLdlt::BandedLdlt(const Eigen::SparseMatrix<double>& matrix)
    : size_(matrix.rows()), bandwidth_(bandwidth_of(matrix)) {
  const Index n = size_, b = bandwidth_;
  // Dense band of the lower triangle: band(k, i) = A(i, i - k), k = 0..b.
  Matrix band = Matrix::Zero(b + 1, n);
  for (Index col = 0; col < matrix.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, col); it; ++it)
      if (it.row() >= col) band(it.row() - col, it.row()) += it.value();

  lower_ = Matrix::Zero(std::max<Index>(b, 1), n);
  Vector pivot(n);
  for (Index i = 0; i < n; ++i) {
    const Index first = std::max<Index>(0, i - b);
    for (Index j = first; j < i; ++j) {
      double value = band(i - j, i);
      for (Index k = std::max(first, j - b); k < j; ++k)
        value -= lower_(i - k - 1, i) * pivot[k] * lower_(j - k - 1, j);
      lower_(i - j - 1, i) = value / pivot[j];
    }
    double diagonal = band(0, i);
    for (Index k = first; k < i; ++k)
      diagonal -= lower_(i - k - 1, i) * lower_(i - k - 1, i) * pivot[k];
    if (!(diagonal > 0.0)) throw NotPositiveDefinite(i, diagonal);
    pivot[i] = diagonal;
  }
  inverse_pivot_ = pivot.cwiseInverse();
}

void BandedLdlt::solve(const Vector& rhs, Vector& solution) const {
  const Index n = size_, b = bandwidth_;
  solution.resize(n);
  if (n == 0) return;
  double* x = solution.data();
  const double* r = rhs.data();
  const double* inv_d = inverse_pivot_.data();
  if (b == 1) {
    // Tridiagonal: the common case of rods numbered along their length.
    const double* l = lower_.data();  // l[i] = L(i, i-1)
    double previous = x[0] = r[0];
    for (Index i = 1; i < n; ++i) previous = x[i] = r[i] - l[i] * previous;
    double next = x[n - 1] *= inv_d[n - 1];
    for (Index i = n - 2; i >= 0; --i) next = x[i] = x[i] * inv_d[i] - l[i + 1] * next;
    return;
  }
  switch (b) {
    case 2:
      return substitute<2>(r, x);
    case 3:
      return substitute<3>(r, x);
    case 4:
      return substitute<4>(r, x);
    case 5:
      return substitute<5>(r, x);
    case 6:
      return substitute<6>(r, x);
    case 7:
      return substitute<7>(r, x);
    case 8:
      return substitute<8>(r, x);
    default:
      return substitute<0>(r, x);
  }
}

// Forward and back substitution; a Band > 0 fixes the bandwidth at compile time, so the inner
// loops of the rows away from the ends unroll (the bridge's b = 5: a quarter of the time).
template <Index Band>
void BandedLdlt::substitute(const double* rhs, double* x) const {
  const Index n = size_, b = Band > 0 ? Band : bandwidth_;
  const double* inv_d = inverse_pivot_.data();
  const double* lower = lower_.data();  // row i of L at lower + i * b
  for (Index i = 0; i < n; ++i) {
    double value = rhs[i];
    const double* row = lower + i * b;
    // In column order, as the factorisation's own products.
    if (i >= b) {
      for (Index k = b - 1; k >= 0; --k) value -= row[k] * x[i - k - 1];
    } else {
      for (Index k = i - 1; k >= 0; --k) value -= row[k] * x[i - k - 1];
    }
    x[i] = value;
  }
  // The farthest terms first, as in the forward pass: each row waits for the one before it only
  // for its last product, so the rows' chains overlap.
  for (Index i = n - 1; i >= 0; --i) {
    double value = x[i] * inv_d[i];
    if (i + b < n) {
      for (Index k = b - 1; k >= 0; --k) value -= lower[(i + k + 1) * b + k] * x[i + k + 1];
    } else {
      for (Index k = n - i - 2; k >= 0; --k) value -= lower[(i + k + 1) * b + k] * x[i + k + 1];
    }
    x[i] = value;
  }
}

}  // namespace pound::assembly
