// The small LU: Eigen's unblocked algorithm step for step (first largest pivot, exact
// divisions, each update rounded once), so its factors are those of a plain loop written from
// that description to the bit; its solves agree with Eigen's PartialPivLU (which in this file
// is compiled without fused multiply-adds, hence "within rounding") at every size, blocked
// ones included; a singular matrix gives non-finite values, as Eigen's does.
#include "core/pivoted_lu.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "core/packets.hpp"

namespace pound {
namespace {

Matrix random_matrix(Index n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Matrix a(n, n);
  for (Index j = 0; j < n; ++j)
    for (Index i = 0; i < n; ++i) a(i, j) = value(rng);
  a.diagonal().array() += 0.5;  // I + T G: the link system's Jacobians lean on their diagonal
  return a;
}

// The reference: the unblocked algorithm written out on a copy.
struct Reference {
  Matrix lu;
  std::vector<Index> pivots;
};

Reference reference_lu(Matrix lu) {
  const Index n = lu.rows();
  Reference result;
  for (Index k = 0; k < n; ++k) {
    Index pivot = k;
    for (Index i = k + 1; i < n; ++i)
      if (std::abs(lu(i, k)) > std::abs(lu(pivot, k))) pivot = i;
    result.pivots.push_back(pivot);
    if (lu(pivot, k) != 0.0) {
      lu.row(k).swap(lu.row(pivot));
      for (Index i = k + 1; i < n; ++i) lu(i, k) = lu(i, k) / lu(k, k);
    }
    for (Index j = k + 1; j < n; ++j)
      for (Index i = k + 1; i < n; ++i) lu(i, j) = multiply_add(-lu(i, k), lu(k, j), lu(i, j));
  }
  result.lu = std::move(lu);
  return result;
}

TEST(PivotedLu, FactorsAreTheUnblockedAlgorithmsToTheBit) {
  int unequal = 0, compared = 0;
  for (Index n = 1; n <= PivotedLu::kUnblockedRows; ++n)
    for (unsigned seed = 0; seed < 20; ++seed) {
      Matrix a = random_matrix(n, 100 * static_cast<unsigned>(n) + seed);
      if (seed % 5 == 0 && n > 2) a.row(1) = a.row(0);  // ties for the pivot, then a zero one
      PivotedLu lu;
      lu.compute(a);
      const Reference reference = reference_lu(a);
      for (Index j = 0; j < n; ++j)
        for (Index i = 0; i < n; ++i) {
          const double got = lu.factors()(i, j), want = reference.lu(i, j);
          unequal += !(got == want || (std::isnan(got) && std::isnan(want))) ||
                     std::signbit(got) != std::signbit(want);
          ++compared;
        }
    }
  std::cout << "  " << compared << " factor entries (sizes 1 to 16, ties and zero pivots), "
            << unequal << " unequal to the reference's in value or sign" << std::endl;
  EXPECT_EQ(unequal, 0);
}

TEST(PivotedLu, SolvesAgreeWithEigensPartialPivLuAtEverySize) {
  double worst_difference = 0.0, worst_residual = 0.0;
  for (const Index n : {1, 2, 3, 7, 13, 16, 17, 24, 40, 64}) {
    const Matrix a = random_matrix(n, 7 * static_cast<unsigned>(n));
    const Vector b = Matrix(random_matrix(n, 11 * static_cast<unsigned>(n))).col(0);
    PivotedLu lu;
    lu.compute(a);
    Vector x;
    lu.solve(b, x);
    const Vector eigen = Eigen::PartialPivLU<Matrix>(a).solve(b);
    worst_difference = std::max(worst_difference, (x - eigen).norm() / eigen.norm());
    worst_residual = std::max(worst_residual, (a * x - b).norm() / (a.norm() * x.norm()));
  }
  std::cout << "  sizes 1 to 64 (blocked past 16): solutions within " << worst_difference
            << " of Eigen's (relative), residual " << worst_residual << std::endl;
  EXPECT_LT(worst_difference, 1e-11);
  EXPECT_LT(worst_residual, 1e-15);
}

TEST(PivotedLu, ASingularMatrixGivesNonFiniteValuesAsEigensDoes) {
  for (const Index n : {3, 20}) {
    Matrix a = random_matrix(n, 5);
    a.col(1).setZero();
    PivotedLu lu;
    lu.compute(a);
    Vector x;
    lu.solve(Vector::Ones(n), x);
    EXPECT_FALSE(x.allFinite()) << "n = " << n;
    EXPECT_FALSE(Eigen::PartialPivLU<Matrix>(a).solve(Vector::Ones(n)).allFinite());
  }
}

}  // namespace
}  // namespace pound
