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
  for (Index i = 0; i < n; ++i) {
    double value = r[i];
    for (Index j = std::max<Index>(0, i - b); j < i; ++j) value -= lower_(i - j - 1, i) * x[j];
    x[i] = value;
  }
  for (Index i = n - 1; i >= 0; --i) {
    double value = x[i] * inv_d[i];
    for (Index j = i + 1; j <= std::min(n - 1, i + b); ++j) value -= lower_(j - i - 1, j) * x[j];
    x[i] = value;
  }
}

}  // namespace pound::assembly
