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

// Sums over the same equations (1 to 9 of them on each list: full batches of four and partly
// filled ones; two or fewer are read apart), among sums of their own, read four to a packet: still
// each one value_of's to the bit, over v and over v + w; and a sum added after an evaluate is read
// at the next.
TEST(TermSums, SumsOverTheSameEquationsAreValueOfsToTheBit) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  const Index n = 40;
  Vector v(n), w(n);
  for (Index i = 0; i < n; ++i) {
    v[i] = i % 7 == 0 ? 0.0 : 1e3 * value(rng);
    w[i] = i % 5 == 0 ? -v[i] : value(rng);
  }
  std::uniform_int_distribution<Index> equation(0, n - 1);
  std::vector<std::vector<model::DofTerm>> sums;
  TermSums table;
  for (int list = 0; list < 30; ++list) {
    std::vector<Index> equations(static_cast<std::size_t>(2 + list % 5));
    for (Index& e : equations) e = equation(rng);
    for (int sharing = 1 + list % 9; sharing > 0; --sharing) {
      std::vector<model::DofTerm>& sum = sums.emplace_back();
      for (const Index e : equations) sum.push_back({e, sharing % 3 == 0 ? 0.0 : value(rng)});
      EXPECT_EQ(table.add(sum), sums.size() - 1);
      if (list % 4 == 0) table.add(sums.emplace_back(1, model::DofTerm{equation(rng), 2.0}));
    }
  }
  std::vector<double> out;
  int unequal = 0, written_past = 0;
  const auto compare = [&](std::size_t count) {
    out.assign(count + 1, 123.0);
    table.evaluate(v, out.data());
    for (std::size_t s = 0; s < count; ++s) {
      const double expected = fused_value_of(sums[s], v);
      unequal += out[s] != expected || std::signbit(out[s]) != std::signbit(expected);
    }
    table.evaluate(v, w, out.data());
    for (std::size_t s = 0; s < count; ++s) {
      const double expected = fused_value_of(sums[s], v + w);
      unequal += out[s] != expected || std::signbit(out[s]) != std::signbit(expected);
    }
    written_past += out[count] != 123.0;
  };
  compare(sums.size());
  sums.push_back(sums.front());  // shares the first list
  EXPECT_EQ(table.add(sums.back()), sums.size() - 1);
  compare(sums.size());
  std::cout << "  " << sums.size()
            << " sums, most over lists of equations shared by 2 to 9: " << unequal
            << " unequal to value_of's fused form" << std::endl;
  EXPECT_EQ(unequal, 0);
  EXPECT_EQ(written_past, 0);  // the unused lanes are not stored
}

}  // namespace
}  // namespace pound::results
