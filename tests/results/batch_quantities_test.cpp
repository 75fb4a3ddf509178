// The table of batch quantities: complete, each name once, each pointing at its own member of
// CaseSummary, described with units.
#include "results/batch_quantities.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace pound::results {
namespace {

TEST(BatchQuantities, AreTheResponseColumnsInTheirOrder) {
  std::vector<std::string> names;
  for (const BatchQuantity& q : batch_quantities()) names.emplace_back(q.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{
                "impacts", "max_pounding_force", "max_restrainer_force", "max_joint_opening",
                "max_seat_movement", "max_drift_ratio", "max_ductility", "max_residual_drift_ratio",
                "energy_balance_error", "max_top_acceleration", "max_deck_acceleration"}));
}

TEST(BatchQuantities, EachReadsItsOwnMemberAndSaysWhatItIsWithUnits) {
  for (const BatchQuantity& q : batch_quantities()) {
    EXPECT_EQ(q.meaning.back(), ']') << q.name << ": " << q.meaning;
    EXPECT_EQ(q.axis_label.back(), ']') << q.name << ": " << q.axis_label;
    EXPECT_NE(q.axis_label.find(" ["), std::string_view::npos) << q.name;
    EXPECT_EQ(q.response, q.name != "energy_balance_error") << q.name;
  }
  // Each its own member: set one, and only that one is there.
  for (const BatchQuantity& q : batch_quantities()) {
    CaseSummary summary;
    summary.*q.value = 42.0;
    for (const BatchQuantity& other : batch_quantities())
      EXPECT_EQ((summary.*other.value).has_value(), &other == &q) << q.name << " " << other.name;
  }
}

TEST(BatchQuantities, AreFoundByName) {
  const BatchQuantity* opening = find_batch_quantity("max_joint_opening");
  ASSERT_NE(opening, nullptr);
  EXPECT_EQ(opening->value, &CaseSummary::max_joint_opening);
  EXPECT_EQ(find_batch_quantity("max_joint_openin"), nullptr);
  EXPECT_EQ(find_batch_quantity("min_unseating_margin"), nullptr);  // a column, not a quantity
}

}  // namespace
}  // namespace pound::results
