#include "assembly/twisted_tridiagonal.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "assembly/not_positive_definite.hpp"

namespace pound::assembly {

namespace {

// The diagonal d_i and the subdiagonal e_i = A(i, i-1) (e_0 = 0) of a tridiagonal matrix.
struct Tridiagonal {
  std::vector<double> diagonal;
  std::vector<double> off;
};

Tridiagonal tridiagonal_parts(const Eigen::SparseMatrix<double>& matrix) {
  const Index n = matrix.rows();
  Tridiagonal parts{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  for (Index col = 0; col < matrix.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, col); it; ++it) {
      if (it.row() == col)
        parts.diagonal[col] += it.value();
      else if (it.row() == col + 1)
        parts.off[col + 1] += it.value();
      else if (it.row() != col - 1 && it.value() != 0.0)
        throw std::domain_error("TwistedTridiagonal needs a tridiagonal matrix");
    }
  return parts;
}

// 1 / p_i of row i, whose diagonal is d_i (refused as assembly::pivot_holds says).
double inverse(double pivot, const std::vector<double>& diagonal, Index row) {
  const double own = diagonal[static_cast<std::size_t>(row)];
  if (!pivot_holds(pivot, own)) throw NotPositiveDefinite(row, pivot, own);
  return 1.0 / pivot;
}

}  // namespace

TwistedTridiagonal::TwistedTridiagonal(const Eigen::SparseMatrix<double>& matrix) {
  const auto [diagonal, off] = tridiagonal_parts(matrix);
  const Index n = matrix.rows();
  multiplier_.assign(n, 0.0);
  inverse_pivot_.assign(n, 0.0);
  // A zero off-diagonal ends a block: rows a..b-1 do not couple to the rest.
  for (Index a = 0; a < n;) {
    Index b = a + 1;
    while (b < n && off[b] != 0.0) ++b;
    factor_block(a, b, diagonal, off);
    a = b;
  }
  common_length_ = chains_.empty() ? 0 : chains_.front().length;
  for (const Chain& chain : chains_) common_length_ = std::min(common_length_, chain.length);
}

// Twisted at the middle row k: the top part from row a down, the bottom part from row b-1 up.
void TwistedTridiagonal::factor_block(Index a, Index b, const std::vector<double>& diagonal,
                                      const std::vector<double>& off) {
  const Index k = a + (b - a) / 2;
  Block block{a, k, b, 0.0, 0.0};
  if (k > a) {
    block.from_above = factor_top(a, k, diagonal, off);
    chains_.push_back({a, 1, k - a});
  }
  if (k < b - 1) {
    block.from_below = factor_bottom(k, b, diagonal, off);
    chains_.push_back({b - 1, -1, b - 1 - k});
  }
  const double twist =
      diagonal[k] - block.from_above * off[k] - (k + 1 < b ? block.from_below * off[k + 1] : 0.0);
  inverse_pivot_[k] = inverse(twist, diagonal, k);
  blocks_.push_back(block);
}

// Top rows a..k-1: p_i = d_i - l_i e_i, l_i = e_i / p_{i-1}. Returns the twist's l_k.
double TwistedTridiagonal::factor_top(Index a, Index k, const std::vector<double>& diagonal,
                                      const std::vector<double>& off) {
  double pivot = diagonal[a];
  for (Index i = a + 1; i < k; ++i) {
    inverse_pivot_[i - 1] = inverse(pivot, diagonal, i - 1);
    multiplier_[i] = off[i] / pivot;
    pivot = diagonal[i] - multiplier_[i] * off[i];
  }
  inverse_pivot_[k - 1] = inverse(pivot, diagonal, k - 1);
  return off[k] / pivot;
}

// Bottom rows b-1..k+1: q_i = d_i - u_i e_{i+1}, u_i = e_{i+1} / q_{i+1}. Returns the twist's u_k.
double TwistedTridiagonal::factor_bottom(Index k, Index b, const std::vector<double>& diagonal,
                                         const std::vector<double>& off) {
  double pivot = diagonal[b - 1];
  for (Index i = b - 2; i > k; --i) {
    inverse_pivot_[i + 1] = inverse(pivot, diagonal, i + 1);
    multiplier_[i] = off[i + 1] / pivot;
    pivot = diagonal[i] - multiplier_[i] * off[i + 1];
  }
  inverse_pivot_[k + 1] = inverse(pivot, diagonal, k + 1);
  return off[k + 1] / pivot;
}

namespace {

// Runs up to kWidth chains side by side, each chain's running value held in a register (a value
// reloaded from memory would add store-forwarding latency to every link of the chain).
// Elimination visits rows start, start + step, ...: x_i = r_i - m_i x_(i - step).
// Substitution visits them in reverse from the row next to the twist (already final):
// x_i = x_i / p_i - m_(i + step) x_(i + step).
constexpr int kWidth = 4;

// Runs Width chains: all of them in lockstep over the shortest one's length, then each one's
// rest alone. `start` sets a chain's first row and returns its value there; `link` moves a
// position one row along its step and returns the new value.
template <int Width, typename Chain, typename Start, typename Link>
void in_lockstep(const Chain* chains, Start start, Link link) {
  Index position[Width], step[Width], length[Width];
  double carry[Width];
  Index common = chains[0].length;
  for (int c = 0; c < Width; ++c) {
    step[c] = chains[c].step;
    length[c] = chains[c].length;
    carry[c] = start(chains[c], position[c]);
    common = std::min(common, length[c]);
  }
  for (Index s = 1; s < common; ++s)
    for (int c = 0; c < Width; ++c) carry[c] = link(position[c], step[c], carry[c]);
  for (int c = 0; c < Width; ++c)
    for (Index s = common; s < length[c]; ++s) carry[c] = link(position[c], step[c], carry[c]);
}

template <int Width, typename Chain>
void eliminate(const Chain* chains, const double* r, const double* m, double* x) {
  in_lockstep<Width>(
      chains,
      [&](const Chain& chain, Index& position) {
        position = chain.start;
        return x[position] = r[position];
      },
      [&](Index& position, Index step, double carry) {
        position += step;
        return x[position] = r[position] - m[position] * carry;
      });
}

template <int Width, typename Chain>
void substitute(const Chain* chains, const double* inv, const double* m, double* x) {
  in_lockstep<Width>(
      chains,
      [&](const Chain& chain, Index& position) {
        position = chain.start + (chain.length - 1) * chain.step;  // next to the twist
        return x[position];
      },
      [&](Index& position, Index step, double carry) {
        const double multiplier = m[position];
        position -= step;
        return x[position] = x[position] * inv[position] - multiplier * carry;
      });
}

template <typename Chain, typename Kernel4, typename Kernel2, typename Kernel1>
void in_groups(const std::vector<Chain>& chains, Kernel4 four, Kernel2 two, Kernel1 one) {
  std::size_t c = 0;
  for (; c + kWidth <= chains.size(); c += kWidth) four(&chains[c]);
  for (; c + 2 <= chains.size(); c += 2) two(&chains[c]);
  for (; c < chains.size(); ++c) one(&chains[c]);
}

}  // namespace

void TwistedTridiagonal::solve(const Vector& rhs, Vector& solution) const {
  solution.resize(rhs.size());
  double* x = solution.data();
  const double* r = rhs.data();
  const double* m = multiplier_.data();
  const double* inv = inverse_pivot_.data();
  in_groups(
      chains_, [&](const Chain* c) { eliminate<kWidth>(c, r, m, x); },
      [&](const Chain* c) { eliminate<2>(c, r, m, x); },
      [&](const Chain* c) { eliminate<1>(c, r, m, x); });
  for (const Block& block : blocks_) {
    const Index k = block.twist;
    double value = r[k];
    if (k > block.first) value -= block.from_above * x[k - 1];
    if (k + 1 < block.end) value -= block.from_below * x[k + 1];
    x[k] = value * inv[k];
    // The rows next to the twist use the block's own l_k and u_k.
    if (k > block.first) x[k - 1] = x[k - 1] * inv[k - 1] - block.from_above * x[k];
    if (k + 1 < block.end) x[k + 1] = x[k + 1] * inv[k + 1] - block.from_below * x[k];
  }
  in_groups(
      chains_, [&](const Chain* c) { substitute<kWidth>(c, inv, m, x); },
      [&](const Chain* c) { substitute<2>(c, inv, m, x); },
      [&](const Chain* c) { substitute<1>(c, inv, m, x); });
}

}  // namespace pound::assembly
