#include "assembly/banded_ldlt.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <type_traits>

#include "assembly/not_positive_definite.hpp"
#include "core/packets.hpp"

namespace pound::assembly {
namespace {

// visit(std::integral_constant<Index, b>) for a bandwidth b of 2 to BandedLdlt::kUnrolledBand;
// visit(std::integral_constant<Index, 0>) for any other (the bandwidth at run time).
template <typename Visit>
void with_fixed_band(Index b, Visit visit) {
  static_assert(BandedLdlt::kUnrolledBand == 8, "one case for each unrolled bandwidth");
  switch (b) {
    case 2:
      return visit(std::integral_constant<Index, 2>{});
    case 3:
      return visit(std::integral_constant<Index, 3>{});
    case 4:
      return visit(std::integral_constant<Index, 4>{});
    case 5:
      return visit(std::integral_constant<Index, 5>{});
    case 6:
      return visit(std::integral_constant<Index, 6>{});
    case 7:
      return visit(std::integral_constant<Index, 7>{});
    case 8:
      return visit(std::integral_constant<Index, 8>{});
    default:
      return visit(std::integral_constant<Index, 0>{});
  }
}

}  // namespace

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
    if (!pivot_holds(diagonal, band(0, i))) throw NotPositiveDefinite(i, diagonal, band(0, i));
    pivot[i] = diagonal;
  }
  inverse_pivot_ = pivot.cwiseInverse();
}

BandedLdlt BandedLdlt::restricted(const std::vector<Index>& rows) const {
  BandedLdlt part = *this;
  const Index n = static_cast<Index>(rows.size()), b = bandwidth_;
  part.size_ = n;
  part.lower_ = Matrix::Zero(lower_.rows(), n);
  part.inverse_pivot_.resize(n);
  for (Index i = 0; i < n; ++i) {
    const Index row = rows[static_cast<std::size_t>(i)];
    part.inverse_pivot_[i] = inverse_pivot_[row];
    for (Index k = 0; k < b && i - k - 1 >= 0; ++k)
      if (const Index distance = row - rows[static_cast<std::size_t>(i - k - 1)]; distance <= b)
        part.lower_(k, i) = lower_(distance - 1, row);
  }
  return part;
}

void BandedLdlt::solve(const Vector& rhs, Vector& solution) const {
  solution.resize(size_);
  solve(rhs.data(), solution.data());
}

void BandedLdlt::solve(const double* r, double* x) const {
  const Index n = size_, b = bandwidth_;
  if (n == 0) return;
  const double* inv_d = inverse_pivot_.data();
  if (b == 1) {
    // Tridiagonal: the common case of rods numbered along their length.
    const double* l = lower_.data();  // l[i] = L(i, i-1)
    double previous = x[0] = r[0];
    for (Index i = 1; i < n; ++i) previous = x[i] = multiply_add(-l[i], previous, r[i]);
    double next = x[n - 1] *= inv_d[n - 1];
    for (Index i = n - 2; i >= 0; --i) next = x[i] = multiply_add(-l[i + 1], next, x[i] * inv_d[i]);
    return;
  }
  with_fixed_band(b, [&](auto band) { substitute<band()>(r, x); });
}

namespace {

// Row i of the forward pass from the x already in memory: its right-hand side less its `terms`
// nearest products L(i, i - k - 1) x[i - k - 1], farthest first, each fused (row i of L at lower +
// i b).
double forward_row(const double* lower, Index b, double rhs, const double* x, Index i,
                   Index terms) {
  double value = rhs;
  for (Index k = terms - 1; k >= 0; --k)
    value = multiply_add(-lower[i * b + k], x[i - k - 1], value);
  return value;
}

// Row i of the back pass: x[i] / D(i) less its `terms` products L(i + k + 1, i) x[i + k + 1].
double back_row(const double* lower, Index b, const double* inv_d, const double* x, Index i,
                Index terms) {
  double value = x[i] * inv_d[i];
  for (Index k = terms - 1; k >= 0; --k)
    value = multiply_add(-lower[(i + k + 1) * b + k], x[i + k + 1], value);
  return value;
}

// The newest value in front, the oldest dropped.
template <std::size_t Size>
void push(std::array<double, Size>& window, double value) {
  for (std::size_t k = Size - 1; k > 0; --k) window[k] = window[k - 1];
  window[0] = value;
}

}  // namespace

// Forward and back substitution. Each row's sum starts from its right-hand side and takes its
// products farthest first, each fused explicitly (multiply_add): left to itself GCC vectorised
// some of a row's products and subtracted them apart, so the bits depended on the band and on the
// compiler's choices. A Band > 0 fixes the bandwidth at compile time: the inner loops unroll and
// substitute_in_registers keeps the last Band values in registers.
template <Index Band>
void BandedLdlt::substitute(const double* rhs, double* x) const {
  const Index n = size_, b = Band > 0 ? Band : bandwidth_;
  if constexpr (Band > 0) {
    if (n > Band) return substitute_in_registers<Band>(rhs, x);
  }
  const double* inv_d = inverse_pivot_.data();
  const double* lower = lower_.data();
  for (Index i = 0; i < n; ++i) x[i] = forward_row(lower, b, rhs[i], x, i, std::min(i, b));
  for (Index i = n - 1; i >= 0; --i) x[i] = back_row(lower, b, inv_d, x, i, std::min(b, n - i - 1));
}

// substitute's loops for n > Band: the rows with all Band terms (past the first Band forward,
// before the last Band back) read the previous Band values from `window` (window[k]: x[i - k - 1]
// forward, x[i + k + 1] back), so a row waits for the one before it only for its last
// multiply-add, and through a register; a store and a load of x[i - 1] added the store-to-load
// forwarding to every row's wait (the bridge's substitution: 13 % -> 8 % of its cycles). The same
// operations in the same order as substitute's own loops; rhs and x may be the same array, as
// there.
namespace {
// With `places` (Placed), row i's right-hand side is rhs[places[i]] and its solution goes to
// out[places[i]], x being scratch: a renumbered matrix's equations gathered and scattered in the
// sweeps' own loads and stores, the same operations on the same values.
template <Index Band, bool Placed = false>
class RegisterSweep {
 public:
  RegisterSweep(const Matrix& lower, const Vector& inverse_pivots, const double* rhs, double* x,
                const Index* places = nullptr, double* out = nullptr)
      : lower_(lower.data()),
        inv_d_(inverse_pivots.data()),
        n_(inverse_pivots.size()),
        rhs_(rhs),
        x_(x),
        places_(places),
        out_(out) {}
  // The first Band rows of the forward pass, from memory; then rows Band, Band + 1, ... in turn.
  void begin_forward() {
    for (Index i = 0; i < Band; ++i)
      x_[i] = forward_row(lower_, Band, right_hand_side(i), x_, i, i);
    for (Index k = 0; k < Band; ++k) window_[k] = x_[Band - k - 1];
  }
  void forward(Index i) {
    const double* row = lower_ + i * Band;
    double value = right_hand_side(i);
    for (Index k = Band - 1; k >= 0; --k) value = multiply_add(-row[k], window_[k], value);
    x_[i] = value;
    push(window_, value);
  }
  // The last Band rows of the back pass; then rows n - Band - 1, n - Band - 2, ... in turn.
  void begin_back() {
    for (Index i = n_ - 1; i >= n_ - Band; --i) {
      x_[i] = back_row(lower_, Band, inv_d_, x_, i, n_ - i - 1);
      if constexpr (Placed) out_[places_[i]] = x_[i];
    }
    for (Index k = 0; k < Band; ++k) window_[k] = x_[n_ - Band + k];
  }
  void back(Index i) {
    double value = x_[i] * inv_d_[i];
    for (Index k = Band - 1; k >= 0; --k)
      value = multiply_add(-lower_[(i + k + 1) * Band + k], window_[k], value);
    if constexpr (Placed)
      out_[places_[i]] = value;  // x[i] is not read again: the window holds it
    else
      x_[i] = value;
    push(window_, value);
  }

 private:
  double right_hand_side(Index i) const {
    if constexpr (Placed) return rhs_[places_[i]];
    return rhs_[i];
  }
  const double* __restrict__ lower_;
  const double* __restrict__ inv_d_;
  Index n_;
  const double* rhs_;
  double* x_;
  const Index* __restrict__ places_;
  double* out_;
  std::array<double, Band> window_;
};
}  // namespace

template <Index Band>
void BandedLdlt::substitute_in_registers(const double* rhs, double* x) const {
  RegisterSweep<Band> sweep(lower_, inverse_pivot_, rhs, x);
  const Index n = size_;
  sweep.begin_forward();
  for (Index i = Band; i < n; ++i) sweep.forward(i);
  sweep.begin_back();
  for (Index i = n - Band - 1; i >= 0; --i) sweep.back(i);
}

// Two sweeps, each row of one beside the same row of the other (back: counted from each end),
// then the rest of the longer alone: each solution's operations are those of its own sweep.
template <Index Band, bool Placed>
void BandedLdlt::substitute_pair(const BandedLdlt& a, const double* rhs_a, double* x_a,
                                 const BandedLdlt& b, const double* rhs_b, double* x_b,
                                 const PairPlaces* places) {
  RegisterSweep<Band, Placed> first(a.lower_, a.inverse_pivot_, rhs_a, x_a,
                                    Placed ? places->a : nullptr, Placed ? places->out : nullptr);
  RegisterSweep<Band, Placed> second(b.lower_, b.inverse_pivot_, rhs_b, x_b,
                                     Placed ? places->b : nullptr, Placed ? places->out : nullptr);
  const Index n_a = a.size_, n_b = b.size_, common = std::min(n_a, n_b);
  first.begin_forward();
  second.begin_forward();
  for (Index i = Band; i < common; ++i) {
    first.forward(i);
    second.forward(i);
  }
  for (Index i = common; i < n_a; ++i) first.forward(i);
  for (Index i = common; i < n_b; ++i) second.forward(i);
  first.begin_back();
  second.begin_back();
  for (Index from_end = Band + 1; from_end <= common; ++from_end) {
    first.back(n_a - from_end);
    second.back(n_b - from_end);
  }
  for (Index i = n_a - common - 1; i >= 0; --i) first.back(i);
  for (Index i = n_b - common - 1; i >= 0; --i) second.back(i);
}

void BandedLdlt::solve_pair(const BandedLdlt& a, const Vector& rhs_a, Vector& x_a,
                            const BandedLdlt& b, const Vector& rhs_b, Vector& x_b) {
  x_a.resize(a.size_);
  x_b.resize(b.size_);
  solve_pair(a, rhs_a.data(), x_a.data(), b, rhs_b.data(), x_b.data());
}

void BandedLdlt::solve_pair(const BandedLdlt& a, const double* r_a, double* s_a,
                            const BandedLdlt& b, const double* r_b, double* s_b) {
  const Index band = a.bandwidth_;
  if (band != b.bandwidth_ || band < 2 || band > kUnrolledBand || a.size_ <= band ||
      b.size_ <= band) {
    a.solve(r_a, s_a);
    b.solve(r_b, s_b);
    return;
  }
  with_fixed_band(band, [&](auto fixed) {
    if constexpr (fixed() > 0) substitute_pair<fixed(), false>(a, r_a, s_a, b, r_b, s_b, nullptr);
  });
}

bool BandedLdlt::solve_pair_in_place(const BandedLdlt& a, const BandedLdlt& b,
                                     const PairPlaces& places, const double* rhs, double* scratch_a,
                                     double* scratch_b) {
  const Index band = a.bandwidth_;
  if (band != b.bandwidth_ || band < 2 || band > kUnrolledBand || a.size_ <= band ||
      b.size_ <= band)
    return false;
  with_fixed_band(band, [&](auto fixed) {
    if constexpr (fixed() > 0)
      substitute_pair<fixed(), true>(a, rhs, scratch_a, b, rhs, scratch_b, &places);
  });
  return true;
}

}  // namespace pound::assembly
