#include "assembly/banded_ldlt.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/packets.hpp"
#include "support/matrices.hpp"

namespace pound::assembly {
namespace {

using Sparse = Eigen::SparseMatrix<double>;

using testing::random_banded;
using testing::random_vector;

// || x - x_eigen || / || x_eigen || against Eigen's dense Cholesky (LL^T) of the same system.
double relative_error(const BandedLdlt& solver, const Sparse& matrix, const Vector& rhs) {
  Vector x = Vector::Constant(rhs.size(), 123.0);  // whatever was in it must not matter
  solver.solve(rhs, x);
  const Vector reference = Matrix(matrix).llt().solve(rhs);
  return (x - reference).norm() / reference.norm();
}

TEST(BandedLdlt, MatchesDenseCholeskyForOneBlock) {
  std::mt19937 rng(11);
  for (Index band : {0, 1, 2, 5}) {
    for (Index n : {1, 2, 3, 7, 1000}) {
      const Sparse matrix = random_banded({n}, band, rng);
      const BandedLdlt solver(matrix);
      EXPECT_EQ(solver.size(), n);
      EXPECT_EQ(solver.bandwidth(), std::min(band, n - 1));
      const double error = relative_error(solver, matrix, random_vector(n, rng));
      std::cout << "bandwidth " << band << ", n = " << n << ": relative error " << error << "\n";
      EXPECT_LE(error, 1e-12) << "bandwidth " << band << ", n = " << n;
    }
  }
}

TEST(BandedLdlt, MatchesDenseCholeskyForIndependentBlocks) {
  std::mt19937 rng(13);
  const std::vector<std::vector<Index>> layouts = {
      {1, 2}, {2, 1, 3}, {5, 1, 13, 2, 8, 3, 1, 40, 2, 7}, {500, 2, 1, 497}};
  for (Index band : {2, 5}) {
    for (const auto& blocks : layouts) {
      const Sparse matrix = random_banded(blocks, band, rng);
      const BandedLdlt solver(matrix);
      const double error = relative_error(solver, matrix, random_vector(matrix.rows(), rng));
      std::cout << "bandwidth " << band << ", " << blocks.size() << " blocks, n = " << matrix.rows()
                << ": relative error " << error << "\n";
      EXPECT_LE(error, 1e-12) << "bandwidth " << band << ", n = " << matrix.rows();
    }
  }
}

// The substitution's contract, whatever path runs it (tridiagonal, a bandwidth fixed at compile
// time with its values in registers, or the general loop): each row's sum starts from its
// right-hand side and takes its products farthest first, each fused (multiply_add), forward
// through L and back through D^-1 and L^T. Written out here from the factors, to the bit.
TEST(BandedLdlt, SubstitutionFusesEachRowsProductsFarthestFirst) {
  std::mt19937 rng(17);
  long entries = 0, unequal = 0;
  for (Index band : {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 12}) {
    for (Index n : {Index{1}, Index{2}, band, band + 1, 3 * band + 2, Index{200}}) {
      if (n < 1) continue;
      const Sparse matrix = random_banded({n}, band, rng);
      const BandedLdlt solver(matrix);
      const Index b = solver.bandwidth();
      const Matrix& lower = solver.lower();
      const Vector& inverse_pivots = solver.inverse_pivots();
      Vector rhs = random_vector(n, rng);
      for (Index i = 0; i < n; i += 3) rhs[i] = i % 2 ? -0.0 : 0.0;  // signed zeros kept
      Vector x(n), reference(n);
      solver.solve(rhs, x);
      Vector in_place = rhs;  // the right-hand side overwritten by the solution: the same bits
      solver.solve(in_place, in_place);
      EXPECT_TRUE(in_place.cwiseEqual(x).all()) << "bandwidth " << b << ", n = " << n;
      for (Index i = 0; i < n; ++i) {
        double value = rhs[i];
        for (Index k = std::min(i, b) - 1; k >= 0; --k)
          value = multiply_add(-lower(k, i), reference[i - k - 1], value);
        reference[i] = value;
      }
      for (Index i = n - 1; i >= 0; --i) {
        double value = reference[i] * inverse_pivots[i];
        for (Index k = std::min(b, n - i - 1) - 1; k >= 0; --k)
          value = multiply_add(-lower(k, i + k + 1), reference[i + k + 1], value);
        reference[i] = value;
      }
      for (Index i = 0; i < n; ++i) {
        ++entries;
        const bool same = x[i] == reference[i] && std::signbit(x[i]) == std::signbit(reference[i]);
        unequal += !same;
        EXPECT_TRUE(same) << "bandwidth " << b << ", n = " << n << ", x[" << i << "] = " << x[i]
                          << ", written out " << reference[i];
      }
    }
  }
  std::cout << entries << " solution entries, " << unequal << " unequal to the written-out sums\n";
}

// Two systems solved side by side give each the bits of its own solve, whatever their sizes
// (equal, one longer by less or more than the band, one just past the band); pairs the
// side-by-side path does not take (bandwidths that differ, a system within its band) are solved
// one after the other.
TEST(BandedLdlt, APairSolvedSideBySideGivesEachItsOwnSolution) {
  std::mt19937 rng(23);
  int pairs = 0;
  for (Index band : {2, 3, 4, 6, 8}) {
    for (const auto& [n_a, n_b] : std::vector<std::pair<Index, Index>>{
             {band + 1, band + 1}, {40, 40}, {34, 55}, {55, 34}, {band + 2, 200}, {97, band + 1}}) {
      const BandedLdlt a(random_banded({n_a}, band, rng)), b(random_banded({n_b}, band, rng));
      const Vector rhs_a = random_vector(n_a, rng), rhs_b = random_vector(n_b, rng);
      Vector alone_a, alone_b, x_a = Vector::Constant(3, 9.0), x_b;
      a.solve(rhs_a, alone_a);
      b.solve(rhs_b, alone_b);
      BandedLdlt::solve_pair(a, rhs_a, x_a, b, rhs_b, x_b);
      ASSERT_EQ(x_a.size(), n_a);
      ASSERT_EQ(x_b.size(), n_b);
      for (Index i = 0; i < n_a; ++i) ASSERT_EQ(x_a[i], alone_a[i]) << "b " << band << " row " << i;
      for (Index i = 0; i < n_b; ++i) ASSERT_EQ(x_b[i], alone_b[i]) << "b " << band << " row " << i;
      ++pairs;
    }
  }
  // The factors of a block-diagonal band restricted to each block's rows (one block, or the
  // first and third together): each solution the band's own, to the bit, alone or side by side
  // with the other group; a band of 3 beside one of 5, or a system of 4 beside a band of 6, one
  // at a time.
  const Sparse blocks = random_banded({30, 25, 20}, 5, rng);
  const BandedLdlt whole(blocks);
  std::vector<Index> first_third, second;
  for (Index i = 0; i < 75; ++i) (i >= 30 && i < 55 ? second : first_third).push_back(i);
  const BandedLdlt outer = whole.restricted(first_third), middle = whole.restricted(second);
  EXPECT_EQ(outer.bandwidth(), 5);
  EXPECT_EQ(outer.size(), 50);
  const Vector rhs = random_vector(75, rng);
  Vector x_whole, x_outer, x_middle, rhs_outer(50), rhs_middle(25);
  whole.solve(rhs, x_whole);
  for (std::size_t k = 0; k < first_third.size(); ++k) rhs_outer[Index(k)] = rhs[first_third[k]];
  for (std::size_t k = 0; k < second.size(); ++k) rhs_middle[Index(k)] = rhs[second[k]];
  BandedLdlt::solve_pair(outer, rhs_outer, x_outer, middle, rhs_middle, x_middle);
  for (std::size_t k = 0; k < first_third.size(); ++k)
    EXPECT_EQ(x_outer[Index(k)], x_whole[first_third[k]]) << "row " << first_third[k];
  for (std::size_t k = 0; k < second.size(); ++k)
    EXPECT_EQ(x_middle[Index(k)], x_whole[second[k]]) << "row " << second[k];
  const BandedLdlt three(random_banded({60}, 3, rng)), five(random_banded({30}, 5, rng));
  const BandedLdlt small(random_banded({4}, 6, rng)), wide(random_banded({70}, 6, rng));
  Vector x_three, x_five, alone_three, alone_five, x_small, x_wide, alone_small, alone_wide;
  BandedLdlt::solve_pair(three, rhs.head(60), x_three, five, rhs.head(30), x_five);
  three.solve(rhs.head(60), alone_three);
  five.solve(rhs.head(30), alone_five);
  EXPECT_EQ(x_three, alone_three);
  EXPECT_EQ(x_five, alone_five);
  BandedLdlt::solve_pair(small, rhs.head(4), x_small, wide, rhs.head(70), x_wide);
  small.solve(rhs.head(4), alone_small);
  wide.solve(rhs.head(70), alone_wide);
  EXPECT_EQ(x_small, alone_small);
  EXPECT_EQ(x_wide, alone_wide);
  std::cout << pairs << " pairs solved side by side, each to the bit of its own solve\n";
}

// Two groups of one system's equations, interleaved (each group's places shuffled), solved in
// place: the right-hand sides read and the solutions written at their places in the sweeps'
// loads and stores give the bits of gathering, solving side by side and scattering; outside the
// side-by-side case (bandwidths that differ) nothing is done.
TEST(BandedLdlt, APairSolvedInPlaceGivesTheGatheredPairsBits) {
  std::mt19937 rng(29);
  int pairs = 0;
  for (Index band : {2, 4, 5, 8}) {
    for (const auto& [n_a, n_b] : std::vector<std::pair<Index, Index>>{
             {band + 1, band + 1}, {34, 55}, {55, 34}, {97, band + 1}}) {
      const BandedLdlt a(random_banded({n_a}, band, rng)), b(random_banded({n_b}, band, rng));
      std::vector<Index> places(static_cast<std::size_t>(n_a + n_b));
      std::iota(places.begin(), places.end(), Index{0});
      std::shuffle(places.begin(), places.end(), rng);
      const std::vector<Index> places_a(places.begin(), places.begin() + n_a);
      const std::vector<Index> places_b(places.begin() + n_a, places.end());
      const Vector rhs = random_vector(n_a + n_b, rng);
      Vector rhs_a(n_a), rhs_b(n_b), x_a, x_b;
      for (Index i = 0; i < n_a; ++i) rhs_a[i] = rhs[places_a[static_cast<std::size_t>(i)]];
      for (Index i = 0; i < n_b; ++i) rhs_b[i] = rhs[places_b[static_cast<std::size_t>(i)]];
      BandedLdlt::solve_pair(a, rhs_a, x_a, b, rhs_b, x_b);
      Vector solution = Vector::Constant(n_a + n_b, 9.0), scratch_a(n_a), scratch_b(n_b);
      ASSERT_TRUE(
          BandedLdlt::solve_pair_in_place(a, b, {places_a.data(), places_b.data(), solution.data()},
                                          rhs.data(), scratch_a.data(), scratch_b.data()));
      for (Index i = 0; i < n_a; ++i)
        ASSERT_EQ(solution[places_a[static_cast<std::size_t>(i)]], x_a[i])
            << "b " << band << " row " << i;
      for (Index i = 0; i < n_b; ++i)
        ASSERT_EQ(solution[places_b[static_cast<std::size_t>(i)]], x_b[i])
            << "b " << band << " row " << i;
      ++pairs;
    }
  }
  const BandedLdlt three(random_banded({20}, 3, rng)), five(random_banded({20}, 5, rng));
  std::vector<Index> places(40);
  std::iota(places.begin(), places.end(), Index{0});
  const Vector rhs = random_vector(40, rng);
  Vector solution = Vector::Zero(40), scratch(20);
  EXPECT_FALSE(BandedLdlt::solve_pair_in_place(three, five,
                                               {places.data(), places.data() + 20, solution.data()},
                                               rhs.data(), scratch.data(), scratch.data()));
  EXPECT_EQ(solution, Vector::Zero(40));
  std::cout << pairs
            << " interleaved pairs solved in place, each to the bits of the gathered pair\n";
}

TEST(BandedLdlt, BandwidthOfIsTheFarthestNonZeroFromTheDiagonal) {
  Sparse matrix = Sparse(Matrix::Identity(6, 6).sparseView());
  EXPECT_EQ(BandedLdlt::bandwidth_of(matrix), 0);
  matrix.coeffRef(4, 1) = 0.5;
  matrix.coeffRef(1, 4) = 0.5;
  EXPECT_EQ(BandedLdlt::bandwidth_of(matrix), 3);
  matrix.coeffRef(5, 0) = 0.0;  // a stored zero does not widen the band
  EXPECT_EQ(BandedLdlt::bandwidth_of(matrix), 3);
}

TEST(BandedLdlt, IndefiniteMatrixThrowsNamingItsEquation) {
  std::mt19937 rng(19);
  Sparse matrix = random_banded({10}, 2, rng);
  matrix.coeffRef(4, 4) = -100.0;
  testing::expect_factoring_fails_at<BandedLdlt>(matrix, "equation 4");
}

TEST(BandedLdlt, SingularMatrixThrows) {
  Sparse matrix(2, 2);
  matrix.insert(0, 0) = 1.0;
  matrix.insert(1, 0) = 1.0;
  matrix.insert(0, 1) = 1.0;
  matrix.insert(1, 1) = 1.0;
  EXPECT_THROW(BandedLdlt{matrix}, std::domain_error);
}

TEST(BandedLdlt, PivotCancelledToRoundOffIsRefused) {
  testing::expect_cancelled_pivot_refused<BandedLdlt>();
}

}  // namespace
}  // namespace pound::assembly
