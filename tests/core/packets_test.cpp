// The packet loops: each row summed from 0 in column order, to the bit, as the band product and
// the beams' end forces promise; and within a rounding of Eigen's own products.
#include "core/packets.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>

#include "core/types.hpp"

namespace pound {
namespace {

struct Comparison {
  int unequal_bits = 0;         // against the row sums in column order
  double eigen_difference = 0;  // largest, against Eigen's product, relative to the row's scale
};

template <int Size>
Comparison compare(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Matrix a(Size, Size);
  Vector x(Size);
  for (Index j = 0; j < Size; ++j) {
    x[j] = 1e3 * value(rng);
    for (Index i = 0; i < Size; ++i) a(i, j) = 1e6 * value(rng);
  }
  std::array<double, Size> y{};
  multiply_by_columns<Size, Size>(a.data(), x.data(), y.data());
  const Vector eigen = a * x;
  Comparison result;
  for (int i = 0; i < Size; ++i) {
    double sum = 0.0;
    for (int j = 0; j < Size; ++j) sum = multiply_add(a(i, j), x[j], sum);
    const double computed = y[static_cast<std::size_t>(i)];
    result.unequal_bits += computed != sum;
    const double scale = a.row(i).cwiseAbs().dot(x.cwiseAbs());
    result.eigen_difference =
        std::max(result.eigen_difference, std::abs(computed - eigen[i]) / scale);
  }
  return result;
}

TEST(Packets, MultiplyByColumnsSumsEachRowInColumnOrder) {
  int unequal = 0, products = 0;
  double difference = 0.0;
  for (unsigned seed = 1; seed <= 50; ++seed) {
    for (const Comparison& c :
         {compare<12>(seed), compare<6>(seed), compare<4>(seed), compare<3>(seed)}) {
      unequal += c.unequal_bits;
      difference = std::max(difference, c.eigen_difference);
      ++products;
    }
  }
  std::cout << products << " products (12, 6, 4, 3 rows): " << unequal
            << " entries unequal to the row sums; against Eigen's product within " << difference
            << " of each row's scale\n";
  EXPECT_EQ(unequal, 0);
  EXPECT_LE(difference, 12 * std::numeric_limits<double>::epsilon());
}

TEST(Packets, MultiplyAddRoundsOnceWhereTheMachineFuses) {
  // (1 + 2^-30)^2 - (1 + 2^-29) = 2^-60 exactly, which a rounded product loses.
  const double a = 1.0 + std::ldexp(1.0, -30), c = -(1.0 + std::ldexp(1.0, -29));
#ifdef __FMA__
  EXPECT_EQ(multiply_add(a, a, c), std::ldexp(1.0, -60));
#else
  EXPECT_EQ(multiply_add(a, a, c), 0.0);
#endif
}

}  // namespace
}  // namespace pound
