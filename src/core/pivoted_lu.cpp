#include "core/pivoted_lu.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <utility>

#include "core/packets.hpp"

namespace pound {

void PivotedLu::compute(const Matrix& a, Path path) {
  lu_ = a;
  const Index n = lu_.rows();
  transpositions_.resize(n);
  if (n <= kLoopRows && path == Path::loops) {
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

// Eigen's triangular_solve_vector (panels of EIGEN_TUNE_TRIANGULAR_PANEL_WIDTH rows) and its
// column-major matrix-vector product for the rows past a panel, step for step.
constexpr Index kPanelRows = 8;

namespace {
// c + a b with the product rounded first, as Eigen's scalar loops compute it: the empty asm
// keeps the compiler from fusing the two.
double multiply_then_add(double a, double b, double c) {
  double product = a * b;
#if defined(__x86_64__)
  asm("" : "+x"(product));
#else
  volatile double kept = product;
  product = kept;
#endif
  return c + product;
}
}  // namespace

// Row t of the panel's columns [start, end) times x, summed from 0 in column order as Eigen's
// matrix-vector product sums it: rows in packets of four or two with fused multiply-adds, and
// its last row, when it takes an odd number of rows, in its scalar loop (product, then sum).
double PivotedLu::panel_sum(Index t, Index start, Index end, const double* x,
                            bool scalar_row) const {
  const Index n = lu_.rows();
  const double* const a = lu_.data();
  double sum = 0.0;
  for (Index j = start; j < end; ++j)
    sum = scalar_row ? multiply_then_add(a[j * n + t], x[j], sum)
                     : multiply_add(a[j * n + t], x[j], sum);
  return sum;
}

void PivotedLu::solve_unit_lower(double* x) const {
  const Index n = lu_.rows();
  const double* const a = lu_.data();
  for (Index start = 0; start < n; start += kPanelRows) {
    const Index end = std::min(n, start + kPanelRows);
    for (Index i = start; i < end; ++i) {
      const double known = x[i];
      if (known == 0.0) continue;  // Eigen skips a zero (not a NaN)
      for (Index t = i + 1; t < end; ++t) x[t] = multiply_add(-known, a[i * n + t], x[t]);
    }
    for (Index t = end; t < n; ++t)
      x[t] -= panel_sum(t, start, end, x, (n - end) % 2 == 1 && t == n - 1);
  }
}

void PivotedLu::solve_upper(double* x) const {
  const Index n = lu_.rows();
  const double* const a = lu_.data();
  for (Index end = n; end > 0; end -= kPanelRows) {
    const Index start = std::max<Index>(0, end - kPanelRows);
    for (Index i = end - 1; i >= start; --i) {
      if (x[i] == 0.0) continue;
      x[i] /= a[i * n + i];
      const double known = x[i];
      for (Index t = start; t < i; ++t) x[t] = multiply_add(-known, a[i * n + t], x[t]);
    }
    for (Index t = 0; t < start; ++t)
      x[t] -= panel_sum(t, start, end, x, start % 2 == 1 && t == start - 1);
  }
}

namespace {
// x[start, end) -= known * column[start, end), four rows at a time, each rounded once.
void subtract_multiple(double known, const double* column, double* x, Index start, Index end) {
  const Packet4 factor = broadcast(-known);
  Index i = start;
  for (; i + 4 <= end; i += 4)
    store_packet(multiply_add(factor, load_packet(column + i), load_packet(x + i)), x + i);
  for (; i < end; ++i) x[i] = multiply_add(-known, column[i], x[i]);
}
}  // namespace

// Past Eigen's unblocked bound its solves are blocked and matched by nothing here: plain column
// sweeps (each known value taken off the rows below, then above), skipping a zero as Eigen does.
void PivotedLu::solve_by_columns(double* x) const {
  const Index n = lu_.rows();
  const double* const a = lu_.data();
  for (Index j = 0; j < n; ++j)
    if (const double known = x[j]; known != 0.0) subtract_multiple(known, a + j * n, x, j + 1, n);
  for (Index j = n - 1; j >= 0; --j) {
    if (x[j] == 0.0) continue;
    x[j] /= a[j * n + j];
    subtract_multiple(x[j], a + j * n, x, 0, j);
  }
}

void PivotedLu::solve(const Vector& b, Vector& x, Path path) const {
  x = permutation_ * b;
  if (lu_.rows() <= kUnblockedRows && path == Path::loops) {
    solve_unit_lower(x.data());
    solve_upper(x.data());
    return;
  }
  if (lu_.rows() <= kLoopRows && path == Path::loops) {
    solve_by_columns(x.data());
    return;
  }
  lu_.triangularView<Eigen::UnitLower>().solveInPlace(x);
  lu_.triangularView<Eigen::Upper>().solveInPlace(x);
}

}  // namespace pound
