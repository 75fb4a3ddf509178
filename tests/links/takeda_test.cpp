// The modified Takeda law (links/takeda.hpp): its consistent tangent against finite differences
// on every branch, a displacement history through every rule against branch points computed by
// hand from the rules, trial -> commit / revert, the energy of a symmetric cycle, and the input
// errors of a model whose link has this law.
#include "links/takeda.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <random>
#include <vector>

#include "builder/build.hpp"
#include "core/errors.hpp"
#include "io/model_reader.hpp"
#include "links/law_registry.hpp"
#include "support/law_models.hpp"

namespace pound::links {
namespace {

// Round numbers: k0 = 100, cracking at (0.01, 1), yield at (0.05, 3): k_y = 60, the cracked
// slope k1 = 2 / 0.04 = 50, post-yield slope r k_y = 6; alpha = 0.5.
constexpr double kK0 = 100.0, kFc = 1.0, kFy = 3.0, kDy = 0.05, kR = 0.1, kAlpha = 0.5;
constexpr double kDc = kFc / kK0, kKy = kFy / kDy, kK1 = (kFy - kFc) / (kDy - kDc);
constexpr double kPost = kR * kKy;

Takeda::Parameters trilinear(double beta = 0.0) {
  return {.stiffness = kK0,
          .cracking_force = kFc,
          .yield_force = kFy,
          .yield_deformation = kDy,
          .hardening_ratio = kR,
          .unloading_exponent = kAlpha,
          .reloading_factor = beta};
}

LinkKinematics at(double delta) { return {delta, 0.0, 0.0}; }

double commit_at(LinkLaw& law, double delta) {
  const double force = law.set_trial(at(delta)).force;
  law.commit();
  return force;
}

// Relative error of dF/d(delta) against central differences (as in spring_laws_test.cpp).
double tangent_error(const Takeda::Parameters& parameters, const std::vector<double>& history,
                     double trial) {
  Takeda law(parameters);
  for (double delta : history) commit_at(law, delta);
  const LawResponse response = law.set_trial(at(trial));
  const double reach = std::max(std::abs(trial), 1e-3), step = 1e-6 * reach;
  const double numeric =
      (law.set_trial(at(trial + step)).force - law.set_trial(at(trial - step)).force) / (2 * step);
  return std::abs(numeric - response.stiffness) * reach /
         std::max(std::abs(response.force), 1e-300);
}

struct TangentCase {
  std::string branch;
  Takeda::Parameters parameters;
  std::vector<double> history;
  double trial;
};

TEST(Takeda, TangentsMatchFiniteDifferencesOnEveryBranch) {
  const Takeda::Parameters p = trilinear(), shifted = trilinear(0.5);
  Takeda::Parameters bilinear = p;
  bilinear.cracking_force = 0.0;
  const std::vector<TangentCase> cases{
      {"elastic", p, {}, 0.005},
      {"elastic, tension", p, {}, -0.005},
      {"cracked skeleton", p, {}, 0.03},
      {"post-yield skeleton", p, {}, 0.07},
      {"post-yield skeleton, tension", p, {}, -0.07},
      {"unloading from a cracked peak", p, {0.02}, 0.015},
      {"past zero force toward the opposite cracking point", p, {0.02}, -0.005},
      {"cracked skeleton beyond the opposite cracking point", p, {0.02}, -0.02},
      {"reloading toward the opposite cracked peak", p, {0.02, -0.03}, 0.005},
      {"unloading after yield", p, {0.08}, 0.07},
      {"inner loop back toward its departure point", p, {0.08, 0.07}, 0.075},
      {"inner loop through its departure point onto the skeleton", p, {0.08, 0.07}, 0.085},
      {"reloading toward the yield point of the unyielded side", p, {0.08}, -0.02},
      {"skeleton beyond the yield-point target", p, {0.08}, -0.06},
      {"reloading toward the previous peak", p, {0.08, -0.06}, 0.03},
      {"unloading from a reloading line", p, {0.09, -0.06, 0.0}, -0.002},
      {"inner loop back onto the reloading line", p, {0.09, -0.06, 0.0, -0.002}, 0.05},
      {"reloading after crossing zero from an inner loop", p, {0.09, -0.06, 0.0}, -0.03},
      {"reloading toward a beta-shifted target", shifted, {0.08, -0.08}, 0.03},
      {"skeleton after a beta-shifted target", shifted, {0.08, -0.08}, 0.07},
      {"bilinear skeleton, elastic", bilinear, {}, 0.02},
      {"bilinear skeleton, post-yield", bilinear, {}, 0.07},
      {"bilinear skeleton, unloading", bilinear, {0.1}, 0.09},
      {"bilinear skeleton, reloading", bilinear, {0.1, -0.1}, 0.0},
  };
  for (const TangentCase& c : cases) {
    const double error = tangent_error(c.parameters, c.history, c.trial);
    std::cout << c.branch << ": tangent error " << error << "\n";
    EXPECT_LT(error, 1e-6) << c.branch;
  }
}

// The force at each turning point of a history that visits every rule, computed from the rules
// by hand (branch slopes and zero-force points written out), each after one committed step.
TEST(Takeda, HistoryThroughEveryRuleMatchesHandComputedBranchPoints) {
  Takeda law(trilinear());
  const auto expect_force = [&law](double delta, double expected, const char* what) {
    const double force = commit_at(law, delta);
    const double error = std::abs(force - expected) / std::abs(expected);
    std::cout << what << ": F(" << delta << ") = " << force << ", expected " << expected
              << ", relative error " << error << "\n";
    EXPECT_LT(error, 1e-9) << what;
  };
  expect_force(0.005, kK0 * 0.005, "elastic");
  expect_force(0.02, kFc + kK1 * (0.02 - kDc), "cracked skeleton");
  // Before yield the unloading line from the peak aims at the opposite cracking point and runs
  // through zero force to it (the negative side is uncracked).
  const double cracked_unloading = (kFc + kK1 * (0.02 - kDc) + kFc) / (0.02 + kDc);
  expect_force(0.0, kFc + kK1 * (0.02 - kDc) - cracked_unloading * 0.02, "cracked unloading");
  expect_force(-kDc, -kFc, "at the opposite cracking point");
  const double negative_peak_force = -(kFc + kK1 * (0.03 - kDc));
  expect_force(-0.03, negative_peak_force, "negative cracked skeleton");
  {  // One trial from -0.03 to 0: zero force, then toward the positive cracked peak (0.02).
    const double slope = (-negative_peak_force + kFc) / (0.03 + kDc);
    const double zero = -0.03 - negative_peak_force / slope;
    const double peak_force = kFc + kK1 * (0.02 - kDc);
    const double expected = peak_force * (0.0 - zero) / (0.02 - zero);
    EXPECT_NEAR(law.set_trial(at(0.0)).force, expected, 1e-9 * expected);
  }
  expect_force(0.08, kFy + kPost * (0.08 - kDy), "post-yield skeleton");
  const double unloading_08 = kKy * std::pow(kDy / 0.08, kAlpha);
  expect_force(0.07, kFy + kPost * 0.03 - unloading_08 * 0.01, "unloading after yield");
  expect_force(0.075, kFy + kPost * 0.03 - unloading_08 * 0.005, "inner loop");
  expect_force(0.09, kFy + kPost * (0.09 - kDy), "through the departure point onto the skeleton");
  const double peak_09 = kFy + kPost * (0.09 - kDy);
  const double unloading_09 = kKy * std::pow(kDy / 0.09, kAlpha);
  {  // The negative side has not yielded: reloading aims at its yield point (-d_y, -F_y).
    const double zero = 0.09 - peak_09 / unloading_09;
    const double expected = -kFy * (zero + 0.02) / (zero + kDy);
    EXPECT_NEAR(law.set_trial(at(-0.02)).force, expected, 1e-9 * std::abs(expected));
  }
  const double peak_06 = -(kFy + kPost * (0.06 - kDy));
  expect_force(-0.06, peak_06, "negative post-yield skeleton");
  const double unloading_06 = kKy * std::pow(kDy / 0.06, kAlpha);
  const double zero_06 = -0.06 - peak_06 / unloading_06;
  const double reloading = peak_09 / (0.09 - zero_06);  // toward the previous peak (0.09)
  const double on_line = reloading * (0.0 - zero_06);
  expect_force(0.0, on_line, "reloading toward the previous peak");
  // Reversed on the reloading line (d_T = 0, so no secant): the stiffer of k_u and the line.
  expect_force(-0.002, on_line - std::max(unloading_09, reloading) * 0.002,
               "unloading from the reloading line");
  expect_force(0.095, kFy + kPost * (0.095 - kDy), "back along it, the line, the skeleton");
  EXPECT_DOUBLE_EQ(law.peak(1), 0.095);
  EXPECT_DOUBLE_EQ(law.peak(-1), 0.06);
}

// With beta the reloading aims at the skeleton point beta (d_p - d_y) short of the peak; after an
// inner excursion that crossed zero force beyond that point, at the peak itself.
TEST(Takeda, ReloadingFactorShiftsTheTargetAndFallsBackToThePeak) {
  {
    Takeda law(trilinear(0.5));
    commit_at(law, 0.08);
    commit_at(law, -0.08);
    const double peak_force = kFy + kPost * (0.08 - kDy);
    const double zero = -0.08 + peak_force / (kKy * std::pow(kDy / 0.08, kAlpha));
    const double target = 0.08 - 0.5 * (0.08 - kDy), target_force = kFy + kPost * (target - kDy);
    const double expected = target_force * (0.03 - zero) / (target - zero);
    const double force = law.set_trial(at(0.03)).force;
    std::cout << "beta 0.5: F(0.03) = " << force << ", expected " << expected << "\n";
    EXPECT_NEAR(force, expected, 1e-9 * expected);
    EXPECT_NEAR(law.set_trial(at(0.07)).force, kFy + kPost * (0.07 - kDy), 1e-12);
  }
  Takeda law(trilinear(1.0));  // beta = 1: the yield point
  const double peak_force = kFy + kPost * (0.5 - kDy);
  const double unloading = kKy * std::pow(kDy / 0.5, kAlpha);
  commit_at(law, 0.5);
  commit_at(law, -0.5);
  const double zero = -0.5 + peak_force / unloading;
  const double line = kFy / (kDy - zero);  // toward (d_y, F_y)
  const double turn = line * (-0.15 - zero);
  EXPECT_NEAR(commit_at(law, -0.15), turn, 1e-9 * turn);
  // Unloading from (-0.15, turn) reaches zero force at |d| > d_y: back to the peak (-0.5).
  const double inner_zero = -0.15 - turn / std::max(unloading, line);
  ASSERT_GT(-inner_zero, kDy);
  const double expected = -peak_force * (inner_zero + 0.3) / (inner_zero + 0.5);
  const double force = law.set_trial(at(-0.3)).force;
  std::cout << "beta 1 inside an inner excursion: F(-0.3) = " << force << ", expected " << expected
            << "\n";
  EXPECT_NEAR(force, expected, 1e-9 * std::abs(expected));
}

// A path taken in one trial or in a thousand committed steps ends at the same force: a trial
// follows every branch point it crosses.
TEST(Takeda, OneTrialAcrossManyBranchPointsEqualsSmallSteps) {
  const std::vector<double> turns{0.09, -0.06, 0.0, -0.002, 0.095, -0.1, 0.04};
  Takeda coarse(trilinear(0.3)), fine(trilinear(0.3));
  double from = 0.0, worst = 0.0;
  for (double to : turns) {
    const double coarse_force = commit_at(coarse, to);
    double fine_force = 0.0;
    for (int k = 1; k <= 1000; ++k) fine_force = commit_at(fine, from + (to - from) * k / 1000);
    worst = std::max(worst, std::abs(coarse_force - fine_force) / kFy);
    from = to;
  }
  std::cout << "one trial against 1000 steps: largest difference " << worst << " F_y\n";
  EXPECT_LT(worst, 1e-12);
}

TEST(Takeda, TrialsLeaveTheCommittedStateAndRevertRestoresIt) {
  Takeda law(trilinear(0.4));
  for (double delta : {0.08, -0.06, 0.01}) commit_at(law, delta);
  const std::unique_ptr<LinkLaw> snapshot = law.clone();
  const std::vector<double> probes{0.01, 0.0, -0.03, 0.09, -0.2, 0.3};
  for (double far : {0.5, -0.5, 0.0, 0.2, -0.07}) law.set_trial(at(far));
  for (double probe : probes)
    EXPECT_EQ(law.set_trial(at(probe)).force, snapshot->clone()->set_trial(at(probe)).force)
        << probe;
  EXPECT_EQ(law.peak(1), 0.08);
  EXPECT_EQ(law.peak(-1), 0.06);
  law.set_trial(at(0.4));
  law.revert();
  law.commit();  // a commit after revert keeps the old state
  EXPECT_EQ(law.peak(1), 0.08);
  for (double probe : probes)
    EXPECT_EQ(law.set_trial(at(probe)).force, snapshot->clone()->set_trial(at(probe)).force)
        << probe;
  EXPECT_TRUE(law.in_contact());
  EXPECT_EQ(law.yield_deformation(), kDy);
}

// Work done on the law along `path` (committed steps, uniform between its points). The law is
// piecewise linear; with every kink a point of the path the trapezoidal rule is exact.
double work_along(LinkLaw& law, double from, const std::vector<double>& path) {
  double work = 0.0, force = law.set_trial(at(from)).force;
  for (double to : path) {
    for (int k = 1; k <= 100; ++k) {
      const double a = from + (to - from) * (k - 1) / 100, b = from + (to - from) * k / 100;
      const double next = commit_at(law, b);
      work += 0.5 * (force + next) * (b - a);
      force = next;
    }
    from = to;
  }
  return work;
}

// Both peaks at +-d_m: the cycle is the parallelogram (d_m, F_m), (d_0, 0), (-d_m, -F_m),
// (-d_0, 0) with d_0 = d_m - F_m / k_u: area 2 F_m d_0.
TEST(Takeda, SymmetricCycleDissipatesItsParallelogram) {
  for (double peak : {0.08, 0.2}) {
    Takeda law(trilinear());
    for (double delta : {peak, -peak, peak}) commit_at(law, delta);
    const double force = kFy + kPost * (peak - kDy);
    const double zero = peak - force / (kKy * std::pow(kDy / peak, kAlpha));
    const double energy = work_along(law, peak, {zero, -peak, -zero, peak});
    const double exact = 2.0 * force * zero;
    std::cout << "d_m = " << peak << ": cycle energy " << energy << ", exact " << exact
              << ", relative error " << std::abs(energy / exact - 1.0) << "\n";
    EXPECT_GT(energy, 0.0);
    EXPECT_NEAR(energy / exact, 1.0, 1e-9);
  }
}

// Random walks with extreme numbers (alpha near 1, beta = 1, the steepest allowed hardening):
// the force stays finite and inside the skeleton of the largest excursion, the tangent positive.
TEST(Takeda, RandomWalksStayInsideTheSkeleton) {
  Takeda::Parameters extreme = trilinear(1.0);
  extreme.unloading_exponent = 0.99;
  extreme.hardening_ratio = 0.99 * kK1 / kKy;
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> step(-1.0, 1.0);
  for (const Takeda::Parameters& p : {trilinear(), trilinear(0.6), extreme}) {
    Takeda law(p);
    double delta = 0.0, worst = 0.0, least_slope = 1e300;
    for (int i = 0; i < 20000; ++i) {
      delta = std::clamp(delta + 0.3 * kDy * step(random), -12 * kDy, 12 * kDy);
      const LawResponse response = law.set_trial(at(delta));
      law.commit();
      ASSERT_TRUE(std::isfinite(response.force) && std::isfinite(response.stiffness));
      const double bound = law.skeleton_force(std::max(law.peak(1), law.peak(-1)));
      worst = std::max(worst, std::abs(response.force) - bound);
      least_slope = std::min(least_slope, response.stiffness);
    }
    EXPECT_LE(worst, 1e-12 * kFy);
    EXPECT_GT(least_slope, 0.0);
  }
}

TEST(Takeda, BadNumbersAreInputErrorsNamingTheirPath) {
  struct Bad {
    std::string law, where, phrase;
  };
  const std::string base = R"("type": "takeda", "stiffness": 100, "yield_force": 3)";
  const std::vector<Bad> cases{
      {base + R"(, "cracking_force": 3, "yield_deformation": 0.05)", "/links/0/law/cracking_force",
       "the cracking force must be below the yield force 3, got 3"},
      {base + R"(, "cracking_force": 1, "yield_deformation": 0.03)",
       "/links/0/law/yield_deformation", "must exceed yield_force / stiffness = 0.03"},
      {base + R"(, "cracking_force": 1, "yield_deformation": 0.05, "hardening_ratio": 0.9)",
       "/links/0/law/hardening_ratio", "must not exceed the cracked slope"},
      {base + R"(, "reloading_factor": 1.5)", "/links/0/law/reloading_factor",
       "the reloading factor must be in [0, 1], got 1.5"},
      {base + R"(, "unloading_exponent": 1)", "/links/0/law/unloading_exponent", "must be < 1"},
      {base + R"(, "cracking_force": 1)", "/links/0/law",
       "'cracking_force' needs 'yield_deformation'"},
      {base + R"(, "yield_deformation": 0.05)", "/links/0/law",
       "'yield_deformation' needs 'cracking_force'"},
  };
  for (const Bad& bad : cases) {
    const std::optional<InputError> error = testing::law_model_error("{" + bad.law + "}");
    ASSERT_TRUE(error) << "accepted: " << bad.law;
    std::cout << error->what() << "\n";
    EXPECT_EQ(error->file(), "m.json");
    EXPECT_EQ(error->where(), bad.where) << error->what();
    EXPECT_NE(error->reason().find(bad.phrase), std::string::npos) << error->what();
  }
  EXPECT_FALSE(testing::law_model_error("{" + base +
                                        R"(, "cracking_force": 1, "yield_deformation": 0.05})"));
  EXPECT_THROW(Takeda({.stiffness = 100, .cracking_force = 3, .yield_force = 3}),
               std::invalid_argument);
}

}  // namespace
}  // namespace pound::links
