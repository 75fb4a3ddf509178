// Kawashima's gap spring: force, sign convention, tangent (finite differences), trial/commit.
#include "links/gap_spring.hpp"

#include <gtest/gtest.h>

#include <iostream>

namespace pound::links {
namespace {

TEST(GapSpring, CompressionOnlyAlongPenetration) {
  GapSpring law(250.0);
  EXPECT_EQ(law.set_trial({.penetration = -0.1}).force, 0.0);
  EXPECT_EQ(law.set_trial({.penetration = 0.0}).force, 0.0);  // touching: still open (r >= 0)
  EXPECT_DOUBLE_EQ(law.set_trial({.penetration = 0.02}).force, 5.0);
  EXPECT_GT(law.set_trial({.penetration = 1e-12}).force, 0.0);
}

// dF/d(delta) against central differences on both sides of the kink; rate and acceleration
// do not enter this law.
TEST(GapSpring, TangentMatchesFiniteDifferences) {
  GapSpring law(1.0e5);
  double worst = 0.0;
  for (double penetration : {-1.0, -1e-3, -1e-6, 1e-6, 1e-3, 0.5, 2.0}) {
    const double step = 1e-7 * std::max(1e-6, std::abs(penetration));
    const LawResponse at = law.set_trial({penetration, 3.0, 7.0});
    const double plus = law.set_trial({penetration + step, 3.0, 7.0}).force;
    const double minus = law.set_trial({penetration - step, 3.0, 7.0}).force;
    const double numeric = (plus - minus) / (2.0 * step);
    const double error = std::abs(numeric - at.stiffness) / 1.0e5;
    worst = std::max(worst, error);
    EXPECT_LT(error, 1e-8) << "at delta = " << penetration;
    EXPECT_EQ(at.damping, 0.0);
    EXPECT_EQ(at.mass, 0.0);
  }
  std::cout << "worst relative tangent error " << worst << "\n";
}

TEST(GapSpring, TrialCommitRevert) {
  GapSpring law(10.0);
  law.set_trial({.penetration = 0.1});
  EXPECT_FALSE(law.in_contact());  // not committed yet
  law.commit();
  EXPECT_TRUE(law.in_contact());
  law.set_trial({.penetration = -0.1});
  law.revert();
  EXPECT_TRUE(law.in_contact());
  auto copy = law.clone();
  EXPECT_TRUE(copy->in_contact());
  EXPECT_EQ(copy->name(), "gap_spring");
}

}  // namespace
}  // namespace pound::links
