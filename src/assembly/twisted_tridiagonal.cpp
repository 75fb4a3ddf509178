#include "assembly/twisted_tridiagonal.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "assembly/not_positive_definite.hpp"

namespace pound::assembly {

TwistedTridiagonal::TwistedTridiagonal(const Eigen::SparseMatrix<double>& matrix) {
  const Index n = matrix.rows();
  std::vector<double> diagonal(n, 0.0), off(n, 0.0);  // off[i] = A(i, i-1)
  for (Index col = 0; col < matrix.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, col); it; ++it) {
      if (it.row() == col)
        diagonal[col] += it.value();
      else if (it.row() == col + 1)
        off[col + 1] += it.value();
      else if (it.row() != col - 1 && it.value() != 0.0)
        throw std::domain_error("TwistedTridiagonal needs a tridiagonal matrix");
    }
  multiplier_.assign(n, 0.0);
  inverse_pivot_.assign(n, 0.0);
  auto inverse = [](double pivot, Index row) {
    if (!(pivot > 0.0)) throw NotPositiveDefinite(row, pivot);
    return 1.0 / pivot;
  };
  for (Index a = 0; a < n;) {
    Index b = a + 1;
    while (b < n && off[b] != 0.0) ++b;
    const Index k = a + (b - a) / 2;
    Block block{a, k, b, 0.0, 0.0};
    if (k > a) {  // top rows a..k-1: p_i = d_i - l_i e_i, l_i = e_i / p_{i-1}
      double pivot = diagonal[a];
      for (Index i = a + 1; i < k; ++i) {
        inverse_pivot_[i - 1] = inverse(pivot, i - 1);
        multiplier_[i] = off[i] / pivot;
        pivot = diagonal[i] - multiplier_[i] * off[i];
      }
      inverse_pivot_[k - 1] = inverse(pivot, k - 1);
      block.from_above = off[k] / pivot;
      chains_.push_back({a, 1, k - a});
    }
    if (k < b - 1) {  // bottom rows b-1..k+1: q_i = d_i - u_i e_{i+1}, u_i = e_{i+1} / q_{i+1}
      double pivot = diagonal[b - 1];
      for (Index i = b - 2; i > k; --i) {
        inverse_pivot_[i + 1] = inverse(pivot, i + 1);
        multiplier_[i] = off[i + 1] / pivot;
        pivot = diagonal[i] - multiplier_[i] * off[i + 1];
      }
      inverse_pivot_[k + 1] = inverse(pivot, k + 1);
      block.from_below = off[k + 1] / pivot;
      chains_.push_back({b - 1, -1, b - 1 - k});
    }
    const double twist =
        diagonal[k] - block.from_above * off[k] - (k + 1 < b ? block.from_below * off[k + 1] : 0.0);
    inverse_pivot_[k] = inverse(twist, k);
    blocks_.push_back(block);
    a = b;
  }
  common_length_ = chains_.empty() ? 0 : chains_.front().length;
  for (const Chain& chain : chains_) common_length_ = std::min(common_length_, chain.length);
}

namespace {

// Runs up to kWidth chains side by side, each chain's running value held in a register (a value
// reloaded from memory would add store-forwarding latency to every link of the chain).
// Elimination visits rows start, start + step, ...: x_i = r_i - m_i x_(i - step).
// Substitution visits them in reverse from the row next to the twist (already final):
// x_i = x_i / p_i - m_(i + step) x_(i + step).
constexpr int kWidth = 4;

template <int Width, typename Chain>
void eliminate(const Chain* chains, const double* r, const double* m, double* x) {
  Index position[Width], step[Width], length[Width];
  double carry[Width];
  Index common = chains[0].length;
  for (int c = 0; c < Width; ++c) {
    position[c] = chains[c].start;
    step[c] = chains[c].step;
    length[c] = chains[c].length;
    carry[c] = x[position[c]] = r[position[c]];
    common = std::min(common, length[c]);
  }
  for (Index s = 1; s < common; ++s)
    for (int c = 0; c < Width; ++c) {
      position[c] += step[c];
      carry[c] = x[position[c]] = r[position[c]] - m[position[c]] * carry[c];
    }
  for (int c = 0; c < Width; ++c)
    for (Index s = common; s < length[c]; ++s) {
      position[c] += step[c];
      carry[c] = x[position[c]] = r[position[c]] - m[position[c]] * carry[c];
    }
}

template <int Width, typename Chain>
void substitute(const Chain* chains, const double* inv, const double* m, double* x) {
  Index position[Width], step[Width], length[Width];
  double carry[Width];
  Index common = chains[0].length;
  for (int c = 0; c < Width; ++c) {
    step[c] = chains[c].step;
    length[c] = chains[c].length;
    position[c] = chains[c].start + (length[c] - 1) * step[c];  // next to the twist
    carry[c] = x[position[c]];
    common = std::min(common, length[c]);
  }
  for (Index t = 1; t < common; ++t)
    for (int c = 0; c < Width; ++c) {
      const double multiplier = m[position[c]];
      position[c] -= step[c];
      carry[c] = x[position[c]] = x[position[c]] * inv[position[c]] - multiplier * carry[c];
    }
  for (int c = 0; c < Width; ++c)
    for (Index t = common; t < length[c]; ++t) {
      const double multiplier = m[position[c]];
      position[c] -= step[c];
      carry[c] = x[position[c]] = x[position[c]] * inv[position[c]] - multiplier * carry[c];
    }
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
