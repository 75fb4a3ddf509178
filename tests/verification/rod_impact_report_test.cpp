// The named rod-impact cases and the metrics document: what each case sets up, what a wrong name
// says, and every metric under its key.
#include "verification/rod_impact_report.hpp"

#include <gtest/gtest.h>

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
