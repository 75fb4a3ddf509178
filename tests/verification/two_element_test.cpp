// Suzuki & Toi's two-element model: the assembled model's generalised eigenvalues against the
// closed forms (eq. 4, eqs. 23-24), and the paper's observations about them.
#include "verification/two_element.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace pound::verification {
namespace {

TEST(TwoElement, EigenvaluesMatchTheClosedFormsOverTheSweep) {
  double worst = 0.0;
  const auto results = two_element_sweep();
  for (const TwoElementResult& r : results) worst = std::max(worst, r.relative_error);
  std::cout << results.size() << " cases, largest relative error " << worst << "\n";
  EXPECT_EQ(results.size(), 180u);
  EXPECT_LE(worst, 1e-10);
}

// Fig. 2: a penalty spring 1000 times k1 leaves the merged mode right but adds a spurious mode
// at 40-60 times the exact frequency (m1 = m2, k1 = k2).
TEST(TwoElement, StiffPenaltyAloneCreatesASpuriousHighMode) {
  const TwoElementResult r = solve_two_element({100.0, 100.0, 2.0, 2.0, 1e5, 0.0});
  const double first = std::sqrt(r.omega1_squared / r.exact_omega_squared);
  const double second = std::sqrt(r.omega2_squared / r.exact_omega_squared);
  std::cout << "w1/w_exact " << first << ", w2/w_exact " << second << "\n";
  EXPECT_NEAR(first, 1.0, 1e-3);
  EXPECT_GT(second, 40.0);
  EXPECT_LT(second, 60.0);
}

// Fig. 5 with eq. 29: adding the penalty mass brings both modes to the exact frequency.
TEST(TwoElement, PenaltyMassFromEquation29PullsBothModesToTheExactOne) {
  const double alpha0 = 1e5, alpha2 = alpha0 * 4.0 / 200.0;
  const TwoElementResult r = solve_two_element({100.0, 100.0, 2.0, 2.0, alpha0, alpha2});
  const double first = std::sqrt(r.omega1_squared / r.exact_omega_squared);
  const double second = std::sqrt(r.omega2_squared / r.exact_omega_squared);
  std::cout << "w1/w_exact " << first << ", w2/w_exact " << second << "\n";
  EXPECT_NEAR(first, 1.0, 0.05);
  EXPECT_NEAR(second, 1.0, 0.05);
}

}  // namespace
}  // namespace pound::verification
