// The impact velocity is taken where the penetration crosses zero inside the step, so laws that
// use it do not depend on which step first penetrates.
#include "links/impact_onset.hpp"

#include <gtest/gtest.h>

#include <iostream>

#include "verification/restitution.hpp"

namespace pound::links {
namespace {

TEST(ImpactOnset, InterpolatesTheRateWherePenetrationCrossesZero) {
  ImpactOnset onset;
  onset.commit({-1e-3, 1.0, 0.0}, false);
  // Crossing a quarter of the way: v0 = 1.0 + 0.25 (0.6 - 1.0).
  const OnsetVelocity v0 = onset.at({3e-3, 0.6, 0.0});
  EXPECT_DOUBLE_EQ(v0.velocity, 0.9);
  onset.commit({3e-3, 0.6, 0.0}, true);
  EXPECT_DOUBLE_EQ(onset.impact_velocity(), 0.9);
  EXPECT_DOUBLE_EQ(onset.at({4e-3, 0.2, 0.0}).velocity, 0.9);  // kept during the contact
}

// Shifting the gap moves first contact to a different place within a step; with the impact
// velocity interpolated the achieved restitution of Hertz-damp barely moves.
TEST(ImpactOnset, HertzDampRestitutionDoesNotDependOnWhereTheStepFalls) {
  verification::ImpactSetup setup;
  setup.steps_per_contact = 100;  // coarse on purpose
  const builder::LawSpec law{
      .type = "hertz_damp",
      .parameters = {{"stiffness", setup.hertz_stiffness}, {"restitution", 0.5}}};
  double low = 1.0, high = 0.0;
  for (double fraction : {0.05, 0.3, 0.55, 0.8}) {
    // Contact estimate 0.0157 s / 100 steps: a gap of (k + fraction) steps at 1 m/s.
    setup.gap = (20.0 + fraction) * 1.57e-4;
    const double e = verification::simulate_impact(setup, law, 0.0157).achieved;
    low = std::min(low, e);
    high = std::max(high, e);
  }
  std::cout << "achieved e between " << low << " and " << high << "\n";
  EXPECT_LT(high - low, 2e-3);
}

}  // namespace
}  // namespace pound::links
