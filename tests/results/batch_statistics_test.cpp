#include "results/batch_statistics.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

namespace pound::results {
namespace {

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

TEST(Quantile, InterpolatesBetweenOrderStatisticsLikeNumpy) {
  // numpy.quantile([3, 1, 4, 1, 5], [0.5, 0.84, 1.0]) = [3, 4.36, 5]
  const std::vector<double> values{3, 1, 4, 1, 5};
  EXPECT_DOUBLE_EQ(quantile(values, 0.5), 3.0);
  EXPECT_NEAR(quantile(values, 0.84), 4.36, 1e-12);
  EXPECT_DOUBLE_EQ(quantile(values, 1.0), 5.0);
  EXPECT_DOUBLE_EQ(quantile({7.0}, 0.84), 7.0);
  EXPECT_THROW(quantile({}, 0.5), std::invalid_argument);
}

// Stripes whose exceeding counts follow a lognormal fragility exactly (to the rounding of the
// counts): the maximum-likelihood fit must give back its median and dispersion.
TEST(Fragility, RecoversTheLognormalThatGeneratedTheStripes) {
  const double median = 0.45, dispersion = 0.35;
  const int per_stripe = 4000;
  std::vector<FragilityObservation> data;
  for (double im = 0.15; im <= 1.2; im += 0.15) {
    const int exceeding =
        static_cast<int>(std::lround(per_stripe * normal_cdf(std::log(im / median) / dispersion)));
    for (int k = 0; k < per_stripe; ++k) data.push_back({im, k < exceeding});
  }
  const FragilityFit fit = fit_lognormal_fragility(data);
  ASSERT_TRUE(fit.fitted) << fit.reason;
  const double median_error = fit.median / median - 1.0;
  const double dispersion_error = fit.dispersion / dispersion - 1.0;
  std::cout << fmt::format("fragility fit: median error {:.2e}, dispersion error {:.2e}\n",
                           median_error, dispersion_error);
  // Counts rounded to 1/4000 move the estimates by well under 0.5 %.
  EXPECT_LT(std::abs(median_error), 5e-3);
  EXPECT_LT(std::abs(dispersion_error), 5e-3);
}

// At the maximum the log-likelihood's gradient vanishes: check it by central differences in
// (ln median, dispersion) on a small, ragged data set like a real IDA.
TEST(Fragility, IsAMaximumOfTheLikelihood) {
  const std::vector<FragilityObservation> data = {
      {0.1, false}, {0.1, false}, {0.2, false}, {0.2, true}, {0.3, false}, {0.3, true},
      {0.3, true},  {0.4, false}, {0.4, true},  {0.5, true}, {0.2, false}, {0.1, true}};
  const FragilityFit fit = fit_lognormal_fragility(data);
  ASSERT_TRUE(fit.fitted) << fit.reason;
  auto log_likelihood = [&](double median, double dispersion) {
    double sum = 0.0;
    for (const FragilityObservation& o : data) {
      const double p = normal_cdf(std::log(o.intensity / median) / dispersion);
      sum += std::log(o.exceeded ? p : 1.0 - p);
    }
    return sum;
  };
  EXPECT_NEAR(log_likelihood(fit.median, fit.dispersion), fit.log_likelihood, 1e-10);
  const double h = 1e-5;
  const double d_median = (log_likelihood(fit.median * std::exp(h), fit.dispersion) -
                           log_likelihood(fit.median * std::exp(-h), fit.dispersion)) /
                          (2 * h);
  const double d_dispersion = (log_likelihood(fit.median, fit.dispersion + h) -
                               log_likelihood(fit.median, fit.dispersion - h)) /
                              (2 * h);
  std::cout << fmt::format("gradient at the fit: {:.1e}, {:.1e}\n", d_median, d_dispersion);
  EXPECT_LT(std::abs(d_median), 1e-6);
  EXPECT_LT(std::abs(d_dispersion), 1e-6);
  // And any step away lowers it.
  for (const auto& [m, b] : {std::pair{1.05, 1.0}, {0.95, 1.0}, {1.0, 1.05}, {1.0, 0.95}})
    EXPECT_LT(log_likelihood(fit.median * m, fit.dispersion * b), fit.log_likelihood);
}

TEST(Fragility, SaysWhyThereIsNoFit) {
  EXPECT_EQ(fit_lognormal_fragility({{0.1, false}, {0.2, false}}).reason,
            "no case exceeds the limit");
  EXPECT_EQ(fit_lognormal_fragility({{0.1, true}, {0.2, true}}).reason,
            "every case exceeds the limit");
  const FragilityFit one_stripe = fit_lognormal_fragility({{0.3, true}, {0.3, false}});
  EXPECT_FALSE(one_stripe.fitted);
  EXPECT_NE(one_stripe.reason.find("same intensity"), std::string::npos);
  // Records scaled to one target differ in their last digits: still one intensity (it read "the
  // fitted probability does not grow with intensity": audit 71).
  const FragilityFit ulps_apart = fit_lognormal_fragility(
      {{0.27, true}, {0.2700000000000001, false}, {0.27, false}, {0.2700000000000001, true}});
  EXPECT_NE(ulps_apart.reason.find("same intensity"), std::string::npos) << ulps_apart.reason;
  const FragilityFit separated =
      fit_lognormal_fragility({{0.1, false}, {0.2, false}, {0.3, true}, {0.4, true}});
  EXPECT_FALSE(separated.fitted);
  EXPECT_NE(separated.reason.find("separate completely between intensities 0.2 and 0.3"),
            std::string::npos)
      << separated.reason;
  // Both outcomes at 0.3 and none other on the wrong side: not complete (the median is 0.3),
  // and not said to be.
  const FragilityFit at_one =
      fit_lognormal_fragility({{0.1, false}, {0.3, false}, {0.3, true}, {0.4, true}});
  EXPECT_FALSE(at_one.fitted);
  EXPECT_NE(at_one.reason.find("separate at intensity 0.3 (none exceeds below it, all do above "
                               "it, some at it: the median is there)"),
            std::string::npos)
      << at_one.reason;
}

results::CaseSummary row(const std::string& record, double scale, double ductility,
                         CaseStatus status = CaseStatus::completed) {
  results::CaseSummary c;
  c.model = "bridge";
  c.record = record;
  c.scale = scale;
  c.status = status;
  c.intensity = 0.2 * scale;
  c.max_ductility = ductility;
  return c;
}

// The responses' statistics are over completed cases only. A failed case whose running peak had
// passed a limit before it stopped exceeded it (its whole run's peak is at least that): it counts
// among the exceedances and the fragility's observations; one below the limit says nothing and
// stays out, as does a residual drift (a value at the end, not a peak).
TEST(BatchStatistics, GroupsByModelAndScaleOverCompletedCasesOnly) {
  builder::SetSpec set;
  set.models = {{"bridge", "bridge.json"}};
  set.scales = {1.0, 2.0};
  set.limits = {{"max_ductility", 1.0}, {"max_residual_drift_ratio", 0.01}};
  std::vector<results::CaseSummary> cases = {row("a", 1, 0.5),
                                             row("b", 1, 0.9),
                                             row("c", 1, 1.3),
                                             row("d", 1, 99.0, CaseStatus::failed),
                                             row("e", 1, 0.2, CaseStatus::failed),
                                             row("a", 2, 1.1),
                                             row("b", 2, 0.8),
                                             row("c", 2, 2.0),
                                             row("d", 2, 0.0, CaseStatus::input_error)};
  for (results::CaseSummary& c : cases) c.max_residual_drift_ratio = c.max_ductility.value() / 50;
  const BatchStatistics stats = batch_statistics(set, cases);
  EXPECT_EQ(stats.cases, 9u);
  EXPECT_EQ(stats.completed, 6u);
  EXPECT_EQ(stats.failed, 2u);
  EXPECT_EQ(stats.input_errors, 1u);
  ASSERT_EQ(stats.groups.size(), 2u);
  const ScaleGroup& first = stats.groups[0];
  EXPECT_EQ(first.cases, 5u);
  EXPECT_EQ(first.completed, 3u);
  ASSERT_EQ(first.responses.size(), 2u);  // ductility and residual drift are present
  EXPECT_EQ(first.responses[0].count, 3u);
  EXPECT_DOUBLE_EQ(first.responses[0].median, 0.9);
  EXPECT_NEAR(first.responses[0].p84, 0.9 + 0.68 * 0.4, 1e-12);  // position 0.84 * 2 = 1.68
  EXPECT_DOUBLE_EQ(first.responses[0].max, 1.3);                 // not the failed 99
  ASSERT_EQ(first.exceedances.size(), 2u);
  EXPECT_EQ(first.exceedances[0].count, 4u);  // the three completed, and d past the limit
  EXPECT_EQ(first.exceedances[0].exceeded, 2u);
  EXPECT_NEAR(first.exceedances[0].fraction, 0.5, 1e-15);
  EXPECT_EQ(first.exceedances[1].count, 3u);     // a residual is not a peak: d stays out
  EXPECT_EQ(first.exceedances[1].exceeded, 2u);  // b 0.018 and c 0.026
  EXPECT_NEAR(stats.groups[1].exceedances[0].fraction, 2.0 / 3.0, 1e-15);
  ASSERT_EQ(stats.fragilities.size(), 2u);
  EXPECT_EQ(stats.fragilities[0].observations, 7u);
  EXPECT_EQ(stats.fragilities[0].exceeded, 4u);
  EXPECT_EQ(stats.fragilities[0].left_out, 2u);  // e failed below the limit, d refused
  EXPECT_TRUE(stats.fragilities[0].fitted) << stats.fragilities[0].reason;
  EXPECT_EQ(stats.fragilities[1].observations, 6u);
  EXPECT_EQ(stats.fragilities[1].left_out, 3u);  // and d's residual, not a peak
}

}  // namespace
}  // namespace pound::results
