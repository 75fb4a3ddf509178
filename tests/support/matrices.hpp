#pragma once
// Random well-conditioned banded systems for the linear solvers' tests, and the check that a
// solver refuses a matrix it cannot factor, naming the equation.
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

}  // namespace pound::testing
