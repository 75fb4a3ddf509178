// The named rod-impact cases and the metrics document: what each case sets up, what a wrong name
// says, and every metric under its key.
#include "verification/rod_impact_report.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace pound::verification {
namespace {

TEST(RodImpactCases, KawashimaIsTwoFreeRodsMovingTowardsEachOther) {
  const builder::RodPairSpec pair = rod_impact_case("kawashima", 10, 1.0);
  for (const builder::RodSpec& rod : {pair.left, pair.right}) {
    EXPECT_EQ(rod.youngs_modulus, 100.0);
    EXPECT_EQ(rod.density, 0.1);
    EXPECT_EQ(rod.area, 1.0);
    EXPECT_EQ(rod.length, 10.0);
    EXPECT_EQ(rod.elements, 10);
    EXPECT_FALSE(rod.far_end_fixed);
  }
  EXPECT_EQ(pair.left.initial_velocity, 0.1);
  EXPECT_EQ(pair.right.initial_velocity, -0.1);
  EXPECT_EQ(pair.law.type, "gap_spring");
}

TEST(RodImpactCases, FixedEndAndAreaRatioStrikeARodAtRestWithItsFarEndFixed) {
  const builder::RodPairSpec fixed = rod_impact_case("fixed-end", 50, 1.0);
  EXPECT_EQ(fixed.left.initial_velocity, 0.1);
  EXPECT_EQ(fixed.right.initial_velocity, 0.0);
  EXPECT_TRUE(fixed.right.far_end_fixed);
  EXPECT_EQ(fixed.left.area, fixed.right.area);
  const builder::RodPairSpec ratio =
      rod_impact_case("area-ratio-3", 50, 1.0, "extended_penalty", 2.0);
  EXPECT_EQ(ratio.left.area, 3.0 * ratio.right.area);
  EXPECT_TRUE(ratio.right.far_end_fixed);
  EXPECT_EQ(ratio.law.type, "extended_penalty");
  EXPECT_EQ(ratio.law.number("eta"), 2.0);
}

TEST(RodImpactCases, AnUnknownNameListsTheKnownOnes) {
  try {
    rod_impact_case("kawasima", 10, 1.0);
    FAIL() << "accepted an unknown case";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("kawashima, fixed-end, area-ratio-3"),
              std::string::npos)
        << error.what();
  }
  EXPECT_THROW(rod_impact_case("kawashima", 10, 1.0, "hertz"), std::invalid_argument);
}

TEST(RodImpactMetrics, DocumentHasEveryMetricUnderItsName) {
  RodImpactMetrics m;
  m.force_l2_error = 0.25;
  m.duration_error = -0.5;
  m.separation_velocity_error = 0.125;
  m.peak_force_ratio = 1.5;
  m.steps = 600;
  m.newton_iterations = 1234;
  m.contact_episodes = 3;
  const nlohmann::json doc = nlohmann::json::parse(to_document(m).dump());
  EXPECT_EQ(doc["force_l2_error"], 0.25);
  EXPECT_EQ(doc["duration_error"], -0.5);
  EXPECT_EQ(doc["separation_velocity_error"], 0.125);
  EXPECT_EQ(doc["peak_force_ratio"], 1.5);
  EXPECT_EQ(doc["steps"], 600);
  EXPECT_EQ(doc["newton_iterations"], 1234);
  EXPECT_EQ(doc["contact_episodes"], 3);
  for (const char* key : {"max_penetration", "min_force", "run_time_s", "contact_duration",
                          "exact_contact_duration", "exact_peak_force", "exact_contact_episodes",
                          "separation_velocity", "exact_separation_velocity", "energy_ratio"})
    EXPECT_TRUE(doc.contains(key)) << key;
}

}  // namespace
}  // namespace pound::verification

namespace pound::verification {
namespace {

// A report's text with its wrapped lines joined.
std::string joined(std::string text) {
  for (std::size_t at; (at = text.find("\n    ")) != std::string::npos;) text.replace(at, 5, " ");
  return text;
}

// The note under an energy ratio above 1 gives the run's own reason: an implicit run's penalty
// contact (no explicit stable step to blame), an explicit run's step against its stable step with
// the contact closed, and the chatter from 0.9 of it (1,000 elements a rod at Courant 0.75, 0.954
// of that step: 626 contact episodes and 8.9 times the energy). It once blamed central
// difference's step at Courant 1 whatever the run.
TEST(RodImpactMetrics, EnergyMadeNoteGivesThisRunsReason) {
  RodImpactOptions implicit_run;
  implicit_run.pair = rod_impact_case("kawashima", 10, 1.0);
  implicit_run.dt_ratio = 0.3;
  const RodImpactMetrics implicit_metrics = run_rod_impact(implicit_run).metrics;
  const std::string implicit_text = joined(format_metrics(implicit_metrics));
  std::cout << format_metrics(implicit_metrics);
  EXPECT_GT(implicit_metrics.energy_ratio, 1.1);
  EXPECT_FALSE(implicit_metrics.stable_time_step);
  EXPECT_NE(implicit_text.find("a penalty contact that closes or opens inside a step"),
            std::string::npos);
  EXPECT_EQ(implicit_text.find("central difference"), std::string::npos);

  RodImpactOptions explicit_run;
  explicit_run.pair = rod_impact_case("kawashima", 1000, 1.0);
  explicit_run.integrator = integrators::IntegratorChoice::preset("central_difference");
  explicit_run.courant = 0.75;
  const RodImpactMetrics m = run_rod_impact(explicit_run).metrics;
  const std::string text = joined(format_metrics(m));
  std::cout << format_metrics(m);
  ASSERT_TRUE(m.stable_time_step);
  const double fraction = m.time_step / *m.stable_time_step;
  EXPECT_GT(fraction, 0.9);
  EXPECT_LT(fraction, 1.0);
  EXPECT_GT(m.energy_ratio, 2.0);
  EXPECT_GT(m.contact_episodes, 100);
  EXPECT_NE(
      text.find(fmt::format("the step is {:.3g} of central difference's stable step", fraction)),
      std::string::npos);
  EXPECT_NE(text.find("the contact chatters"), std::string::npos);
  EXPECT_EQ(text.find("Courant 1"), std::string::npos);
  const nlohmann::json doc = nlohmann::json::parse(to_document(m).dump());
  EXPECT_EQ(doc["stable_time_step"].get<double>(), *m.stable_time_step);
  EXPECT_EQ(doc["time_step"].get<double>(), m.time_step);
}

}  // namespace
}  // namespace pound::verification
