// The stability map on a reduced grid: implicit methods never produce NaN/Inf, explicit central
// difference refuses steps above its limit instead of blowing up, and the cells the benchmarks
// call accurate are (the extended penalty at a resolved step, over eight decades of alpha0).
#include "verification/stability_map.hpp"

#include <gtest/gtest.h>

#include <iostream>

#include "support/studied_methods.hpp"

namespace pound::verification {
namespace {

TEST(StabilityMap, ClassificationsOnAReducedGrid) {
  StabilityOptions options;
  options.stiffness_ratios = {1.0, 1e4, 1e8};
  options.step_ratios = {1e-3, 0.1};
  options.methods = testing::studied_methods();
  const std::vector<StabilityCell> cells = stability_map(options);
  std::cout << format_stability_map(cells);
  ASSERT_EQ(cells.size(), options.methods.size() * 2u * 3u * 2u);
  for (const StabilityCell& c : cells) {
    const std::string where = c.integrator + ", " + c.law + ", k " +
                              std::to_string(c.stiffness_ratio) + ", dt " +
                              std::to_string(c.step_ratio);
    if (c.integrator == "central_difference") {
      // Either refused up front or a finite run: never a blow-up.
      EXPECT_NE(c.verdict, StabilityVerdict::unstable) << where << ": " << c.note;
      if (c.step_ratio == 0.1) {
        EXPECT_EQ(c.verdict, StabilityVerdict::refused) << where;
      }
    } else {
      EXPECT_NE(c.verdict, StabilityVerdict::refused) << where;
      EXPECT_NE(c.note, "not finite") << where;
      EXPECT_EQ(c.note.find("analysis failed"), std::string::npos) << where << ": " << c.note;
    }
    if (c.law == "extended_penalty" && c.step_ratio == 1e-3) {
      EXPECT_EQ(c.verdict, StabilityVerdict::accurate) << where;
    }
  }
}

}  // namespace
}  // namespace pound::verification
