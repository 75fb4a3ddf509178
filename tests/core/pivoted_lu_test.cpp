// The small LU: its loops give Eigen's factors and solutions to the bit (Path::eigen runs
// Eigen's own code, compiled in the library with the loops' flags), and the factors are those of
// the unblocked algorithm written out here (to 64 rows), its solves past 16 rows column sweeps
// written out here and within rounding of Eigen's blocked ones; they leave residuals at rounding
// at every size, Eigen's blocks past 64 included; a singular matrix gives non-finite values, as
// Eigen's does.
// No test file may instantiate Eigen's LU or its column-major triangular solves itself: the
// tests are compiled at -Og, without fused multiply-adds, and the linker keeps one copy of each
// template, which would then be the test's in the library code too (that is why
// twisted_tridiagonal_test.cpp's dense reference is a Cholesky factorisation).
#include "core/pivoted_lu.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "core/packets.hpp"
#include "support/matrices.hpp"

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

// Bits of a and b equal, NaNs equal, signs of zero included.
bool same_bits(double a, double b) {
  return (a == b && std::signbit(a) == std::signbit(b)) || (std::isnan(a) && std::isnan(b));
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

// The sizes the loops take: every one up to Eigen's unblocked bound, then a sample to theirs.
std::vector<Index> loop_sizes() {
  std::vector<Index> sizes;
  for (Index n = 1; n <= PivotedLu::kUnblockedRows; ++n) sizes.push_back(n);
  for (const Index n : {17, 20, 24, 33, 47, 63}) sizes.push_back(n);
  sizes.push_back(PivotedLu::kLoopRows);
  return sizes;
}

// The reference's solution: P b, then the unit lower and the upper sweeps column by column.
Vector reference_solve(const Reference& reference, Vector x) {
  const Matrix& lu = reference.lu;
  const Index n = lu.rows();
  for (Index k = 0; k < n; ++k) std::swap(x[k], x[reference.pivots[static_cast<std::size_t>(k)]]);
  for (Index j = 0; j < n; ++j)
    if (x[j] != 0.0)
      for (Index i = j + 1; i < n; ++i) x[i] = multiply_add(-x[j], lu(i, j), x[i]);
  for (Index j = n - 1; j >= 0; --j) {
    if (x[j] == 0.0) continue;
    x[j] /= lu(j, j);
    for (Index i = 0; i < j; ++i) x[i] = multiply_add(-x[j], lu(i, j), x[i]);
  }
  return x;
}

TEST(PivotedLu, FactorsAreTheUnblockedAlgorithmsToTheBit) {
  int unequal = 0, compared = 0;
  for (const Index n : loop_sizes())
    for (unsigned seed = 0; seed < 20; ++seed) {
      Matrix a = random_matrix(n, 100 * static_cast<unsigned>(n) + seed);
      if (seed % 5 == 0 && n > 2) a.row(1) = a.row(0);  // ties for the pivot, then a zero one
      PivotedLu lu;
      lu.compute(a);
      const Reference reference = reference_lu(a);
      for (Index j = 0; j < n; ++j)
        for (Index i = 0; i < n; ++i) {
          const double got = lu.factors()(i, j), want = reference.lu(i, j);
          unequal += !same_bits(got, want);
          ++compared;
        }
    }
  std::cout << "  " << compared << " factor entries (sizes 1 to 64, ties and zero pivots), "
            << unequal << " unequal to the reference's in value or sign" << std::endl;
  EXPECT_EQ(unequal, 0);
}

// Past 16 rows the solves are column sweeps: the reference's, to the bit, zeros (which both
// skip) and -0 among the right-hand sides.
TEST(PivotedLu, SolvesPastSixteenRowsAreTheColumnSweepsToTheBit) {
  int unequal = 0, compared = 0;
  for (const Index n : loop_sizes()) {
    if (n <= PivotedLu::kUnblockedRows) continue;
    for (unsigned seed = 0; seed < 10; ++seed) {
      const Matrix a = random_matrix(n, 900 * static_cast<unsigned>(n) + seed);
      std::mt19937 rng(500 * static_cast<unsigned>(n) + seed);
      Vector b = testing::random_vector(n, rng);
      if (seed % 3 == 0) b.head(n / 2).setZero();
      if (seed % 2 == 0) b[1] = -0.0;
      PivotedLu lu;
      lu.compute(a);
      Vector x;
      lu.solve(b, x);
      const Vector want = reference_solve(reference_lu(a), b);
      for (Index i = 0; i < n; ++i, ++compared) unequal += !same_bits(x[i], want[i]);
    }
  }
  std::cout << "  sizes 17 to 64: " << compared << " solution entries, " << unequal
            << " unequal to the reference's column sweeps" << std::endl;
  EXPECT_EQ(unequal, 0);
}

// |x_loops - x_eigen| / |x_eigen| of one random system of size n.
double loops_against_eigen(Index n, unsigned matrix_seed, unsigned rhs_seed) {
  const Matrix a = random_matrix(n, matrix_seed);
  std::mt19937 rng(rhs_seed);
  const Vector b = testing::random_vector(n, rng);
  PivotedLu loops, eigen;
  loops.compute(a);
  eigen.compute(a, PivotedLu::Path::eigen);
  Vector x, y;
  loops.solve(b, x);
  eigen.solve(b, y, PivotedLu::Path::eigen);
  return (x - y).norm() / y.norm();
}

// And within rounding of Eigen's blocked factors and solves (which sum in another order).
TEST(PivotedLu, PastSixteenRowsTheLoopsAreEigensWithinRounding) {
  double worst = 0.0;
  for (const Index n : loop_sizes())
    if (n > PivotedLu::kUnblockedRows)
      worst = std::max(worst, loops_against_eigen(n, 40 * static_cast<unsigned>(n),
                                                  60 * static_cast<unsigned>(n)));
  std::cout << "  sizes 17 to 64: largest |x_loops - x_eigen| / |x_eigen| " << worst << std::endl;
  EXPECT_LT(worst, 1e-13);
}

// Whether this build's Eigen code fuses its updates a - l u (the release build's -O3 does; the
// sanitizer build's -O1 does not, and there the loops' explicit fused multiply-adds round
// otherwise): a 2 x 2 factorisation whose one update rounds differently fused.
bool eigen_fuses() {
  // l u = 1 - 2^-54 exactly, which rounds to 1: d - l u is 0 unfused, 2^-54 fused.
  const double l = 1.0 - std::ldexp(1.0, -27), u = 1.0 + std::ldexp(1.0, -27), d = 1.0;
  Matrix a(2, 2);
  a << 1.0, u, l, d;
  PivotedLu eigen;
  eigen.compute(a, PivotedLu::Path::eigen);
  // The product is stored through a volatile: clang contracts d - l * u into a fused
  // multiply-add by itself (GCC's -O1 does not), which would leave no unfused value to compare.
  const volatile double product = l * u;
  const double fused = multiply_add(-l, u, d), separate = d - product;
#ifdef __FMA__
  EXPECT_NE(fused, separate) << "the probe must round differently fused";
#else
  // No fused multiply-add on this target (a portable build): multiply_add rounds twice, as
  // Eigen's code then does, and the loops are compared to the bit all the same.
  EXPECT_EQ(fused, separate);
#endif
  return eigen.factors()(1, 1) == fused;
}

TEST(PivotedLu, LoopsGiveEigensFactorsAndSolutionsToTheBit) {
  if (!eigen_fuses()) {
    // Compared within rounding instead: same pivots, factors and solutions to 1e-13.
    double worst = 0.0;
    for (Index n = 1; n <= PivotedLu::kUnblockedRows; ++n)
      worst = std::max(worst, loops_against_eigen(n, 300 * static_cast<unsigned>(n),
                                                  700 * static_cast<unsigned>(n)));
    std::cout << "  this build's Eigen code does not fuse multiply-adds (an -O1 build): the loops "
                 "compared within rounding, "
              << worst << std::endl;
    EXPECT_LT(worst, 1e-13);
    return;
  }
  int unequal_factors = 0, unequal_solutions = 0, factors = 0, solutions = 0;
  for (Index n = 1; n <= PivotedLu::kUnblockedRows; ++n)
    for (unsigned seed = 0; seed < 20; ++seed) {
      Matrix a = random_matrix(n, 300 * static_cast<unsigned>(n) + seed);
      if (seed % 5 == 0 && n > 2) a.row(1) = a.row(0);
      if (seed % 7 == 0) a.col(0) *= 1e-300;  // tiny pivots
      std::mt19937 rng(700 * static_cast<unsigned>(n) + seed);
      Vector b = testing::random_vector(n, rng);
      if (seed % 3 == 0) b.head(n / 2).setZero();  // zeros the solves skip, -0 among them
      if (seed % 6 == 0 && n > 1) b[1] = -0.0;
      PivotedLu loops, eigen;
      loops.compute(a);
      eigen.compute(a, PivotedLu::Path::eigen);
      for (Index j = 0; j < n; ++j)
        for (Index i = 0; i < n; ++i, ++factors)
          unequal_factors += !same_bits(loops.factors()(i, j), eigen.factors()(i, j));
      Vector x, y;
      loops.solve(b, x);
      eigen.solve(b, y, PivotedLu::Path::eigen);
      for (Index i = 0; i < n; ++i, ++solutions) unequal_solutions += !same_bits(x[i], y[i]);
    }
  std::cout << "  sizes 1 to 16: " << factors << " factor entries, " << unequal_factors
            << " unequal to Eigen's; " << solutions << " solution entries, " << unequal_solutions
            << " unequal" << std::endl;
  EXPECT_EQ(unequal_factors, 0);
  EXPECT_EQ(unequal_solutions, 0);
}

TEST(PivotedLu, SolvesLeaveResidualsAtRoundingAtEverySize) {
  double worst_residual = 0.0;
  for (const Index n : {1, 2, 3, 7, 13, 16, 17, 24, 40, 64, 65, 80}) {
    const Matrix a = random_matrix(n, 7 * static_cast<unsigned>(n));
    std::mt19937 rng(11 * static_cast<unsigned>(n));
    const Vector b = testing::random_vector(n, rng);
    PivotedLu lu;
    lu.compute(a);
    Vector x;
    lu.solve(b, x);
    worst_residual = std::max(worst_residual, (a * x - b).norm() / (a.norm() * x.norm()));
  }
  std::cout << "  sizes 1 to 80 (column sweeps past 16, Eigen's blocks past 64): largest residual "
               "|A x - b| / (|A| |x|) "
            << worst_residual << std::endl;
  EXPECT_LT(worst_residual, 1e-15);
}

TEST(PivotedLu, ASingularMatrixGivesNonFiniteValuesAsEigensDoes) {
  for (const Index n : {3, 20}) {
    Matrix a = random_matrix(n, 5);
    a.col(1).setZero();
    for (const PivotedLu::Path path : {PivotedLu::Path::loops, PivotedLu::Path::eigen}) {
      PivotedLu lu;
      lu.compute(a, path);
      Vector x;
      lu.solve(Vector::Ones(n), x, path);
      EXPECT_FALSE(x.allFinite()) << "n = " << n;
    }
  }
}

}  // namespace
}  // namespace pound
