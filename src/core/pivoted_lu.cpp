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

// Eigen's partial_lu_impl::unblocked_lu, every entry's updates the same in the same order, two
// pivots at a time: the columns right of a pair take both of its updates in one pass (one load
// and one store of each entry for two multiply-adds). Taking pivot k + 1's row swap before pivot
// k's update of those columns changes nothing: the swap moves whole rows, the multipliers of
// column k with them, and row k, which the update reads, is not among them.
void PivotedLu::factor_unblocked() {
  const Index n = lu_.rows();
  Index k = 0;
  for (; k + 2 <= n; k += 2) {
    take_pivot(k);
    double* const column = lu_.data() + k * n;
    double* const next = column + n;  // column k + 1 takes pivot k's update before its pivot
    subtract_multiple(next[k], column, next, k + 1, n);
    take_pivot(k + 1);
    subtract_pivot_rows(k);
  }
  if (k < n) take_pivot(k);
}

// Column k's pivot: the first of its largest magnitudes (Eigen's maxCoeff: strictly larger
// replaces) swapped into row k across the whole matrix, and the multipliers below it. A zero
// pivot leaves its column as it is, as Eigen does (the solve then gives non-finite values, which
// the caller handles).
void PivotedLu::take_pivot(Index k) {
  const Index n = lu_.rows();
  double* const data = lu_.data();
  double* const column = data + k * n;
  Index pivot_row = k;
  double biggest = std::abs(column[k]);
  for (Index i = k + 1; i < n; ++i)
    if (const double score = std::abs(column[i]); score > biggest) {
      biggest = score;
      pivot_row = i;
    }
  transpositions_.indices()[k] = static_cast<int>(pivot_row);
  if (biggest == 0.0) return;
  if (pivot_row != k)
    for (Index j = 0; j < n; ++j) std::swap(data[j * n + k], data[j * n + pivot_row]);
  const double pivot = column[k];
  for (Index i = k + 1; i < n; ++i) column[i] /= pivot;
}

// The columns right of the pair k, k + 1 less both pivots' updates: in each, row k + 1 first,
// which gives the second pivot's row entry, then each row below takes the first update and the
// second.
void PivotedLu::subtract_pivot_rows(Index k) {
  const Index n = lu_.rows();
  const double* const first = lu_.data() + k * n;
  const double* const second = first + n;
  const double below = -first[k + 1];
  for (Index j = k + 2; j < n; ++j) {
    double* const target = lu_.data() + j * n;
    const double upper = target[k];
    const double next_upper = target[k + 1] = multiply_add(below, upper, target[k + 1]);
    const Packet4 upper_packet = broadcast(upper), next_upper_packet = broadcast(next_upper);
    Index i = k + 2;
    for (; i + 4 <= n; i += 4) {
      const Packet4 once =
          multiply_add(-load_packet(first + i), upper_packet, load_packet(target + i));
      store_packet(multiply_add(-load_packet(second + i), next_upper_packet, once), target + i);
    }
    for (; i < n; ++i)
      target[i] = multiply_add(-second[i], next_upper, multiply_add(-first[i], upper, target[i]));
  }
}

// Eigen's triangular_solve_vector (panels of EIGEN_TUNE_TRIANGULAR_PANEL_WIDTH rows) and its
// column-major matrix-vector product for the rows past a panel, each entry's operations in
// Eigen's order (the rows past a panel four at a time, each lane its own row's sum).
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

// Rows [first, last) less their panel sums, four rows to a packet (each lane the same chain of
// multiply-adds from 0 as panel_sum's), then the rest one by one. Of an odd number of rows Eigen
// takes the last in its scalar loop; the packets, four rows each from the first, never reach it.
void PivotedLu::subtract_panel_sums(Index first, Index last, Index start, Index end,
                                    double* x) const {
  const Index n = lu_.rows();
  const double* const a = lu_.data();
  const bool odd = (last - first) % 2 == 1;
  Index t = first;
  for (; t + 4 <= last; t += 4) {
    Packet4 sums{};
    for (Index j = start; j < end; ++j)
      sums = multiply_add(load_packet(a + j * n + t), broadcast(x[j]), sums);
    store_packet(load_packet(x + t) - sums, x + t);
  }
  for (; t < last; ++t) x[t] -= panel_sum(t, start, end, x, odd && t == last - 1);
}

void PivotedLu::solve_unit_lower(double* x) const {
  const Index n = lu_.rows();
  const double* const a = lu_.data();
  for (Index start = 0; start < n; start += kPanelRows) {
    const Index end = std::min(n, start + kPanelRows);
    for (Index i = start; i < end; ++i) {
      const double known = x[i];
      if (known == 0.0) continue;  // Eigen skips a zero (not a NaN)
      subtract_multiple(known, a + i * n, x, i + 1, end);
    }
    if (end < n) subtract_panel_sums(end, n, start, end, x);
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
      subtract_multiple(x[i], a + i * n, x, start, i);
    }
    if (start > 0) subtract_panel_sums(0, start, start, end, x);
  }
}

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
