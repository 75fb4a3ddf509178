#include "assembly/twisted_tridiagonal.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <iostream>
#include <random>
#include <stdexcept>
#include <vector>

#include "support/matrices.hpp"

namespace pound::assembly {
namespace {

using Sparse = Eigen::SparseMatrix<double>;

using testing::random_vector;

// A random symmetric positive definite tridiagonal matrix made of independent blocks of the given
// sizes (the off-diagonal entry between two blocks is zero, every other one is not).
Sparse random_tridiagonal(const std::vector<Index>& blocks, std::mt19937& rng) {
  return testing::random_banded(blocks, 1, rng);
}

// || x - x_eigen || / || x_eigen || against Eigen's dense Cholesky solve of the same system (not
// its LDL^T: see core/pivoted_lu_test.cpp on Eigen's triangular solves in test files).
double relative_error(const Sparse& matrix, const Vector& rhs) {
  const TwistedTridiagonal solver(matrix);
  Vector x = Vector::Constant(rhs.size(), 123.0);  // whatever was in it must not matter
  solver.solve(rhs, x);
  const Vector reference = Matrix(matrix).llt().solve(rhs);
  return (x - reference).norm() / reference.norm();
}

TEST(TwistedTridiagonal, MatchesDenseCholeskyForOneBlock) {
  std::mt19937 rng(17);
  for (Index n : {1, 2, 3, 7, 1000}) {
    const Sparse matrix = random_tridiagonal({n}, rng);
    const double error = relative_error(matrix, random_vector(n, rng));
    std::cout << "n = " << n << ": relative error " << error << "\n";
    EXPECT_LE(error, 1e-12) << "n = " << n;
  }
}

TEST(TwistedTridiagonal, MatchesDenseCholeskyForIndependentBlocks) {
  std::mt19937 rng(29);
  // Unequal blocks, including 1 and 2, enough of them to run chains in groups of 4, 2 and 1.
  const std::vector<std::vector<Index>> layouts = {
      {1, 2},       {2, 1, 3},        {5, 1, 13, 2, 8, 3, 1, 40, 2, 7},
      {1, 1, 1, 1}, {500, 2, 1, 497}, {3, 4, 5, 6, 7, 8, 9, 10, 11}};
  for (const auto& blocks : layouts) {
    const Sparse matrix = random_tridiagonal(blocks, rng);
    const double error = relative_error(matrix, random_vector(matrix.rows(), rng));
    std::cout << blocks.size() << " blocks, n = " << matrix.rows() << ": relative error " << error
              << "\n";
    EXPECT_LE(error, 1e-12) << "n = " << matrix.rows();
  }
}

TEST(TwistedTridiagonal, SplitsBlocksIntoTopAndBottomChains) {
  std::mt19937 rng(3);
  // A block of 1 row is its twist alone; of 2 rows, one chain; of 3 or more, two chains.
  EXPECT_EQ(TwistedTridiagonal(random_tridiagonal({1, 2, 3, 10}, rng)).chains(), 0u + 1u + 2u + 2u);
  EXPECT_EQ(TwistedTridiagonal(random_tridiagonal({1, 1, 1}, rng)).chains(), 0u);
}

TEST(TwistedTridiagonal, SolvesRepeatedly) {
  std::mt19937 rng(5);
  const Sparse matrix = random_tridiagonal({6, 9}, rng);
  const TwistedTridiagonal solver(matrix);
  const Eigen::LLT<Matrix> reference(matrix);
  Vector x;
  for (int k = 0; k < 3; ++k) {
    const Vector rhs = random_vector(matrix.rows(), rng);
    solver.solve(rhs, x);
    const Vector expected = reference.solve(rhs);
    EXPECT_LE((x - expected).norm() / expected.norm(), 1e-12);
  }
}

TEST(TwistedTridiagonal, IndefiniteMatrixThrows) {
  Sparse matrix(2, 2);
  matrix.insert(0, 0) = 1.0;
  matrix.insert(1, 0) = 2.0;
  matrix.insert(0, 1) = 2.0;
  matrix.insert(1, 1) = 1.0;
  EXPECT_THROW(TwistedTridiagonal{matrix}, std::domain_error);
}

TEST(TwistedTridiagonal, NegativePivotInALaterBlockThrowsNamingItsEquation) {
  std::mt19937 rng(7);
  Sparse matrix = random_tridiagonal({3, 1, 3}, rng);
  matrix.coeffRef(3, 3) = -1.0;
  testing::expect_factoring_fails_at<TwistedTridiagonal>(matrix, "equation 3");
}

TEST(TwistedTridiagonal, SingularMatrixThrows) {
  Sparse matrix(3, 3);
  matrix.insert(0, 0) = 1.0;
  matrix.insert(1, 1) = 0.0;
  matrix.insert(2, 2) = 1.0;
  EXPECT_THROW(TwistedTridiagonal{matrix}, std::domain_error);
}

TEST(TwistedTridiagonal, WiderBandThrows) {
  Sparse matrix = Sparse(Matrix::Identity(4, 4).sparseView());
  matrix.coeffRef(2, 0) = 0.1;
  matrix.coeffRef(0, 2) = 0.1;
  EXPECT_THROW(TwistedTridiagonal{matrix}, std::domain_error);
}

TEST(TwistedTridiagonal, PivotCancelledToRoundOffIsRefused) {
  testing::expect_cancelled_pivot_refused<TwistedTridiagonal>();
}

}  // namespace
}  // namespace pound::assembly
