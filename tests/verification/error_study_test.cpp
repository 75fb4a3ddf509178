// The error-against-run-time study on a small grid: every implicit run of a penalty law completes,
// explicit steps above their stable limit and hard contacts under implicit methods are refused
// before running, and the marked front is exactly the set
// of runs no other run beats on both force error and run time.
#include "verification/error_study.hpp"

#include <gtest/gtest.h>

#include <iostream>

#include "support/studied_methods.hpp"

namespace pound::verification {
namespace {

TEST(ErrorStudy, FrontIsTheNonDominatedRunsAndExplicitStepsAboveTheLimitAreRefused) {
  ErrorStudyOptions options;
  options.elements = {50};
  options.courants = {1.0, 0.5};
  options.repeats = 1;
  options.benchmarks = {"kawashima", "area-ratio-3"};
  options.methods = testing::studied_methods();
  const std::vector<StudyResult> results = error_study(options);
  std::cout << format_error_study(results);
  ASSERT_EQ(results.size(), 2u * options.methods.size() * 3u * 2u);
  int front = 0;
  for (const StudyResult& r : results) {
    if (r.input.law == "hard_contact") {
      // A constraint: every integrator, and it leaves the rods' own stable step (Courant 1).
      EXPECT_FALSE(r.refused) << r.input.integrator << " " << r.refusal;
    } else if (r.input.integrator == "central_difference") {
      // Courant 1 is above the contact-active limit for both penalty laws; 0.5 is below.
      EXPECT_EQ(r.refused, r.input.courant == 1.0) << r.input.law << " " << r.input.courant;
    } else {
      EXPECT_FALSE(r.refused) << r.input.integrator;
    }
    if (r.refused) continue;
    EXPECT_GE(r.metrics.min_force, 0.0);
    EXPECT_GT(r.metrics.run_time_s, 0.0);
    bool dominated = false;
    for (const StudyResult& other : results)
      if (!other.refused && other.input.benchmark == r.input.benchmark && &other != &r &&
          other.metrics.force_l2_error <= r.metrics.force_l2_error &&
          other.metrics.run_time_s <= r.metrics.run_time_s &&
          (other.metrics.force_l2_error < r.metrics.force_l2_error ||
           other.metrics.run_time_s < r.metrics.run_time_s))
        dominated = true;
    EXPECT_EQ(r.pareto, !dominated);
    front += r.pareto;
  }
  EXPECT_GE(front, 2);  // at least one per case
}

}  // namespace
}  // namespace pound::verification
