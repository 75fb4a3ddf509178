// The flat tables of sums the monitors and element recorders read: each sum is model::value_of's
// (the first term's product, then fused multiply-adds in order; 0 with no terms), to the bit and
// with its sign of zero, whatever the mix of lengths and the order they were added in.
#include "results/term_sums.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "core/packets.hpp"

namespace pound::results {
namespace {

// value_of as the library compiles it (fused multiply-adds); this file is compiled at -Og,
// where the compiler would not fuse value_of's own loop.
double fused_value_of(const std::vector<model::DofTerm>& terms, const Vector& v) {
  if (terms.empty()) return 0.0;
  double value = terms[0].coefficient * v[terms[0].equation];
  for (std::size_t k = 1; k < terms.size(); ++k)
    value = multiply_add(terms[k].coefficient, v[terms[k].equation], value);
  return value;
}

TEST(TermSums, EachSumIsValueOfsToTheBitWhateverItsLength) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::uniform_int_distribution<int> length(0, 7);
  const Index n = 50;
  Vector v(n);
  for (Index i = 0; i < n; ++i) v[i] = i % 9 == 0 ? 0.0 : 1e3 * value(rng);  // zeros: -0 products
  std::uniform_int_distribution<Index> equation(0, n - 1);
  std::vector<std::vector<model::DofTerm>> sums(400);
  TermSums table;
  for (std::size_t s = 0; s < sums.size(); ++s) {
    for (int k = length(rng); k > 0; --k) sums[s].push_back({equation(rng), value(rng)});
    EXPECT_EQ(table.add(sums[s]), s);
  }
  ASSERT_EQ(table.size(), sums.size());
  std::vector<double> out(sums.size(), 123.0);
  table.evaluate(v, out.data());
  int unequal = 0, negative_zeros = 0;
  double worst = 0.0;
  for (std::size_t s = 0; s < sums.size(); ++s) {
    const double expected = fused_value_of(sums[s], v);
    unequal += out[s] != expected || std::signbit(out[s]) != std::signbit(expected);
    negative_zeros += out[s] == 0.0 && std::signbit(out[s]);
    double scale = 0.0;
    for (const model::DofTerm& term : sums[s])
      scale += std::abs(term.coefficient * v[term.equation]);
    if (scale > 0.0)
      worst = std::max(worst, std::abs(out[s] - model::value_of(sums[s], v)) / scale);
  }
  // Over v + w: each term c (v_e + w_e), as GroundAcceleration::absolute forms a + the frame's.
  Vector w(n);
  for (Index i = 0; i < n; ++i) w[i] = i % 7 == 0 ? -v[i] : value(rng);
  table.evaluate(v, w, out.data());
  const Vector sum = v + w;
  for (std::size_t s = 0; s < sums.size(); ++s) {
    const double expected = fused_value_of(sums[s], sum);
    unequal += out[s] != expected || std::signbit(out[s]) != std::signbit(expected);
  }
  std::cout << "  400 sums of 0 to 7 terms (" << negative_zeros
            << " of them -0), over v and over v + w: " << unequal
            << " unequal to value_of's fused form; within " << worst
            << " of value_of compiled here, relative to the sum of |terms|" << std::endl;
  EXPECT_EQ(unequal, 0);
  EXPECT_LT(worst, 1e-15);
}

}  // namespace
}  // namespace pound::results
