#pragma once
// Random well-conditioned banded systems for the linear solvers' tests, and the checks that a
// solver refuses a matrix it cannot factor, naming the equation, and one whose pivot round-off
// has cancelled.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <algorithm>
#include <iostream>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "assembly/not_positive_definite.hpp"
#include "core/types.hpp"

namespace pound::testing {

// A random symmetric positive definite matrix of half-bandwidth `band` made of independent blocks
// of the given sizes (entries within a block and the band are non-zero, between blocks zero).
// Diagonally dominant, so well conditioned.
inline Eigen::SparseMatrix<double> random_banded(const std::vector<Index>& blocks, Index band,
                                                 std::mt19937& rng) {
  std::uniform_real_distribution<double> magnitude(0.1, 1.0), margin(0.05, 2.0);
  std::bernoulli_distribution negative(0.5);
  const Index n = std::accumulate(blocks.begin(), blocks.end(), Index{0});
  Matrix dense = Matrix::Zero(n, n);
  Index first = 0;
  for (Index size : blocks) {
    for (Index i = first; i < first + size; ++i)
      for (Index j = std::max(first, i - band); j < i; ++j)
        dense(i, j) = dense(j, i) = negative(rng) ? -magnitude(rng) : magnitude(rng);
    first += size;
  }
  for (Index i = 0; i < n; ++i) dense(i, i) = dense.row(i).cwiseAbs().sum() + margin(rng);
  return dense.sparseView();
}

inline Vector random_vector(Index n, std::mt19937& rng) {
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Vector v(n);
  for (Index i = 0; i < n; ++i) v[i] = value(rng);
  return v;
}

// Factoring `matrix` with Solver must throw std::domain_error whose message names `equation`
// ("equation 4"), so that a user can find the part of the model at fault.
template <class Solver>
void expect_factoring_fails_at(const Eigen::SparseMatrix<double>& matrix,
                               const std::string& equation) {
  try {
    const Solver solver(matrix);
    ADD_FAILURE() << "no exception";
  } catch (const std::domain_error& error) {
    std::cout << error.what() << "\n";
    EXPECT_NE(std::string(error.what()).find(equation), std::string::npos) << error.what();
  }
}

// A soft bearing (`soft`) from the ground to DOF 0, a strut (`stiff`) from DOF 0 to DOF 1, and
// `mass` on the diagonal of both: [[soft + stiff + mass, -stiff], [-stiff, stiff + mass]]. Once
// DOF 0 is eliminated, DOF 1's pivot is exactly (stiff (soft + 2 mass) + mass (soft + mass)) /
// (soft + stiff + mass), about soft + 2 mass, formed as the difference of two numbers of the
// strut's size: its round-off is about eps stiff.
inline Eigen::SparseMatrix<double> strut_on_bearing(double stiff, double soft, double mass) {
  Eigen::SparseMatrix<double> matrix(2, 2);
  matrix.insert(0, 0) = soft + stiff + mass;
  matrix.insert(1, 0) = -stiff;
  matrix.insert(0, 1) = -stiff;
  matrix.insert(1, 1) = stiff + mass;
  return matrix;
}

// A strut 1e20 times the bearing's stiffness leaves DOF 1's pivot to round-off: the factorisation
// refuses it as cancelled (assembly::kLostPivot) at equation 1, whatever sign the round-off took.
// At 1e10 times it factors, and solves to eps x 1e10 of the exact solution.
template <typename Solver>
void expect_cancelled_pivot_refused() {
  try {
    const Solver solver(strut_on_bearing(1e20, 1.0, 1.0));
    ADD_FAILURE() << "no exception";
  } catch (const assembly::NotPositiveDefinite& error) {
    std::cout << error.what() << "\n";
    EXPECT_EQ(error.equation(), 1);
    EXPECT_TRUE(error.cancelled()) << error.what();
    EXPECT_DOUBLE_EQ(error.diagonal(), 1e20 + 1.0);
  }
  const double stiff = 1e10, soft = 1.0, mass = 1.0;
  const Solver solver(strut_on_bearing(stiff, soft, mass));
  Vector x;
  solver.solve(Vector::Unit(2, 1), x);
  // The exact solution of A x = e_1 by Cramer's rule, its determinant formed without cancelling.
  const double determinant = stiff * (soft + 2.0 * mass) + mass * (soft + mass);
  const Vector exact{{stiff / determinant, (soft + stiff + mass) / determinant}};
  const double error = (x - exact).norm() / exact.norm();
  std::cout << "strut 1e10 x the bearing: relative error " << error << " (bound 1e10 x 1e-15)\n";
  EXPECT_LT(error, 1e10 * 1e-15);
}

}  // namespace pound::testing
