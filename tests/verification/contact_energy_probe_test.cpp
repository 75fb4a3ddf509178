// The probe of one impact's created energy: two masses (1 and 2, closing at 1.5) through an
// elastic gap spring (k = 1e4, contact pi sqrt(m_eff / k) = 0.02565) under Newmark.
#include "verification/contact_energy_probe.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "links/gap_spring.hpp"

namespace pound::verification {
namespace {

builder::AnalysisSpec newmark_at(double time_step) {
  builder::AnalysisSpec analysis;
  analysis.integrator = integrators::IntegratorChoice::preset("newmark_average_acceleration");
  analysis.time_step = time_step;
  return analysis;
}

const links::LinkContext kPair{.mass_i = 1.0, .mass_j = 2.0};

// The contact's duration is the bare pair's half period; a step of a fiftieth of it creates
// little, one of a fifth of it several percent at its worst phase.
TEST(ContactEnergyProbe, CreatesMoreAsTheStepCoarsensAndEstimatesTheContact) {
  const links::GapSpring law(1e4);
  const double duration = std::numbers::pi * std::sqrt((2.0 / 3.0) / 1e4);
  const auto fine = probe_contact_energy(law, kPair, newmark_at(duration / 50.0), 1.5);
  const auto coarse = probe_contact_energy(law, kPair, newmark_at(duration / 5.0), 1.5);
  ASSERT_TRUE(fine && coarse);
  std::printf("created: %.3e of the approach energy at T/50, %.3e at T/5\n", fine->created_fraction,
              coarse->created_fraction);
  EXPECT_NEAR(fine->contact_duration, duration, 1e-15);
  EXPECT_LT(fine->created_fraction, 1e-3);
  EXPECT_GT(coarse->created_fraction, 0.01);
}

// A rigid far end (an abutment): the free mass alone closes.
TEST(ContactEnergyProbe, ARigidEndLeavesOneMass) {
  const links::GapSpring law(1e4);
  const links::LinkContext against_wall{.mass_i = 1.0, .fixed_j = true};
  const auto probe = probe_contact_energy(law, against_wall, newmark_at(0.005), 1.0);
  ASSERT_TRUE(probe);
  EXPECT_NEAR(probe->contact_duration, std::numbers::pi * std::sqrt(1.0 / 1e4), 1e-15);
  EXPECT_GE(probe->created_fraction, 0.0);
}

TEST(ContactEnergyProbe, DoesNotApplyWithoutAVelocityAStepOrAMass) {
  const links::GapSpring law(1e4);
  EXPECT_FALSE(probe_contact_energy(law, kPair, newmark_at(0.001), 0.0));
  EXPECT_FALSE(probe_contact_energy(law, kPair, newmark_at(0.0), 1.0));
  EXPECT_FALSE(probe_contact_energy(law, {.mass_i = 0.0, .mass_j = 2.0}, newmark_at(0.001), 1.0));
  // Resolved by far more than 20,000 steps: nothing to find.
  EXPECT_FALSE(probe_contact_energy(law, kPair, newmark_at(1e-7), 1.0));
}

}  // namespace
}  // namespace pound::verification
