// The structural spring laws (elastic_spring, bilinear_spring, backfill): consistent tangents
// against central finite differences in every regime, and the closed forms their headers
// promise (hysteretic energy of a bilinear cycle, the backfill hyperbola and its unloading).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>

#include "links/backfill.hpp"
#include "links/bilinear_spring.hpp"
#include "links/elastic_spring.hpp"

namespace pound::links {
namespace {

// Bearing-like numbers: k = 2e7 N/m, F_y = 1e5 N (delta_y = 5 mm), b = 0.05.
constexpr double kStiffness = 2e7, kYieldForce = 1e5, kHardening = 0.05;
constexpr double kYield = kYieldForce / kStiffness;
// Backfill per metre of a 1.7 m backwall: K = 2.87e7 N/m, F_ult = 4.06e5 N, delta_ult = 0.085 m.
constexpr double kBackfillStiffness = 2.87e7, kUltimateForce = 4.06e5, kUltimate = 0.085;

LinkKinematics at(double penetration, double rate = 0.0, double acceleration = 0.0) {
  return {penetration, rate, acceleration};
}

struct Case {
  std::string label;
  std::function<std::unique_ptr<LinkLaw>()> make;
  std::vector<double> history;  // deformations committed one after the other before the trial
  LinkKinematics trial;
};

// Relative error of each tangent component against central differences of the force (the
// force change over a unit relative change of the variable, over the force).
double tangent_error(const Case& c) {
  auto law = c.make();
  for (double penetration : c.history) {
    law->set_trial(at(penetration));
    law->commit();
  }
  const LawResponse response = law->set_trial(c.trial);
  const double analytic[3] = {response.stiffness, response.damping, response.mass};
  const double scale = std::max(std::abs(response.force), 1e-300);
  double worst = 0.0;
  for (int variable = 0; variable < 3; ++variable) {
    LinkKinematics plus = c.trial, minus = c.trial;
    double* const p[3] = {&plus.penetration, &plus.penetration_rate,
                          &plus.penetration_acceleration};
    double* const m[3] = {&minus.penetration, &minus.penetration_rate,
                          &minus.penetration_acceleration};
    const double reach = std::max(std::abs(*p[variable]), 1e-3);
    const double step = 1e-6 * reach;
    *p[variable] += step;
    *m[variable] -= step;
    const double numeric = (law->set_trial(plus).force - law->set_trial(minus).force) / (2 * step);
    worst = std::max(worst, std::abs(numeric - analytic[variable]) * reach / scale);
  }
  return worst;
}

std::unique_ptr<LinkLaw> bilinear() {
  return std::make_unique<BilinearSpring>(kStiffness, kYieldForce, kHardening);
}
std::unique_ptr<LinkLaw> backfill() {
  return std::make_unique<Backfill>(kBackfillStiffness, kUltimateForce, kUltimate);
}
// With the abutment's stem as stiff as the soil (what girder_bridge gives it).
std::unique_ptr<LinkLaw> backfill_with_stem() {
  return std::make_unique<Backfill>(kBackfillStiffness, kUltimateForce, kUltimate,
                                    kBackfillStiffness);
}

std::vector<Case> cases() {
  const auto elastic = [] { return std::make_unique<ElasticSpring>(kStiffness); };
  const double dy = kYield, du = kUltimate;
  return {
      {"elastic compression", elastic, {}, at(3e-3, 0.2)},
      {"elastic tension", elastic, {}, at(-3e-3, -0.2)},
      {"bilinear elastic compression", bilinear, {}, at(0.5 * dy, 0.1)},
      {"bilinear elastic tension", bilinear, {}, at(-0.5 * dy, -0.1)},
      {"bilinear yielding in compression", bilinear, {}, at(2.0 * dy, 0.1)},
      {"bilinear yielding in tension", bilinear, {}, at(-2.0 * dy, -0.1)},
      {"bilinear yielding, committed steps", bilinear, {1.5 * dy, 2.0 * dy}, at(2.5 * dy)},
      {"bilinear unloading after yield", bilinear, {3.0 * dy}, at(2.5 * dy)},
      {"bilinear elastic through zero after yield", bilinear, {3.0 * dy}, at(1.5 * dy)},
      // Reverse yield at delta = 3 dy - 2 dy = dy (the force has dropped by 2 F_y).
      {"bilinear reversed yielding", bilinear, {3.0 * dy}, at(-0.5 * dy)},
      {"bilinear reversed yielding in tension", bilinear, {3.0 * dy, 0.0}, at(-3.0 * dy)},
      {"bilinear reloading after reversal", bilinear, {3.0 * dy, -3.0 * dy}, at(-1.5 * dy)},
      {"bilinear re-yielding after reversal", bilinear, {3.0 * dy, -3.0 * dy}, at(2.0 * dy)},
      {"backfill virgin loading", backfill, {}, at(0.3 * du, 0.2)},
      {"backfill near the ultimate point", backfill, {}, at(0.99 * du)},
      {"backfill capped plastic", backfill, {}, at(1.5 * du)},
      {"backfill unloading", backfill, {0.6 * du}, at(0.55 * du)},
      {"backfill unloading from the plateau", backfill, {1.5 * du}, at(1.45 * du)},
      {"backfill reloading inside the gap line", backfill, {0.6 * du, 0.0}, at(0.59 * du)},
      {"backfill reloading past the largest deformation", backfill, {0.6 * du, 0.0}, at(0.7 * du)},
      {"backfill's stem holding the wall", backfill_with_stem, {}, at(-0.01, -0.3)},
      {"backfill's stem where the wall was pushed", backfill_with_stem, {0.6 * du}, at(0.1 * du)},
  };
}

TEST(SpringLaws, TangentsMatchFiniteDifferencesInEveryRegime) {
  for (const Case& c : cases()) {
    const double error = tangent_error(c);
    std::cout << c.label << ": tangent error " << error << "\n";
    EXPECT_LT(error, 1e-6) << c.label;
  }
}

// Where the force is 0 (an open backfill: before contact, inside the gap, no tension) the
// tangents must be exactly 0.
TEST(SpringLaws, BackfillOpenAndGapCarryNothing) {
  auto law = backfill();
  const LawResponse open = law->set_trial(at(-0.01, -0.3));
  EXPECT_EQ(open.force, 0.0);
  EXPECT_EQ(open.stiffness, 0.0);
  EXPECT_FALSE(law->in_contact());

  law->set_trial(at(0.6 * kUltimate));
  law->commit();
  EXPECT_TRUE(law->in_contact());
  const double permanent = static_cast<const Backfill&>(*law).permanent_deformation();
  ASSERT_GT(permanent, 0.0);
  for (double delta : {0.999 * permanent, 0.5 * permanent, 0.0, -0.05}) {
    const LawResponse gap = law->set_trial(at(delta, -0.2));
    EXPECT_EQ(gap.force, 0.0) << delta;
    EXPECT_EQ(gap.stiffness, 0.0) << delta;
  }
  law->commit();
  EXPECT_FALSE(law->in_contact());
  // Unloading into the gap does not change the permanent deformation.
  EXPECT_EQ(static_cast<const Backfill&>(*law).permanent_deformation(), permanent);
}

// The stem holds the wall where the girder last pushed it: at rest with the soil's stiffness both
// ways (a wall that hung free toward the span drifted across the joint's gap under shaking), and
// after the soil yielded at its permanent deformation p, F = k_s (delta - p) below it: no gap
// for the wall to rattle in.
TEST(SpringLaws, BackfillsStemHoldsTheWallWhereItWasPushed) {
  auto law = backfill_with_stem();
  const LawResponse toward_span = law->set_trial(at(-0.01));
  EXPECT_EQ(toward_span.force, -kBackfillStiffness * 0.01);
  EXPECT_EQ(toward_span.stiffness, kBackfillStiffness);
  EXPECT_EQ(law->set_trial(at(0.0)).stiffness, kBackfillStiffness);  // linear through rest
  law->set_trial(at(0.6 * kUltimate));
  law->commit();
  const double permanent = static_cast<const Backfill&>(*law).permanent_deformation();
  ASSERT_GT(permanent, 0.0);
  for (double delta : {0.999 * permanent, 0.5 * permanent, 0.0, -0.05}) {
    const LawResponse held = law->set_trial(at(delta, -0.2));
    EXPECT_DOUBLE_EQ(held.force, kBackfillStiffness * (delta - permanent)) << delta;
    EXPECT_EQ(held.stiffness, kBackfillStiffness) << delta;
  }
  law->commit();
  EXPECT_EQ(static_cast<const Backfill&>(*law).permanent_deformation(), permanent);
  EXPECT_FALSE(law->in_contact());  // not pushing the soil
}

TEST(SpringLaws, ElasticSpringIsLinearBothWays) {
  ElasticSpring spring(kStiffness);
  EXPECT_DOUBLE_EQ(spring.set_trial(at(0.01)).force, kStiffness * 0.01);
  EXPECT_DOUBLE_EQ(spring.set_trial(at(-0.01)).force, -kStiffness * 0.01);
  spring.commit();
  EXPECT_TRUE(spring.in_contact());
}

// A symmetric cycle: load to +delta_m, then to -delta_m and back to +delta_m in committed steps.
// The closed loop from +delta_m back to +delta_m dissipates the parallelogram between the yield
// lines F = b k delta +- (1 - b) F_y: 4 (1 - b) F_y (delta_m - delta_y).
double cycle_energy(double hardening, double peak) {
  BilinearSpring spring(kStiffness, kYieldForce, hardening);
  // Steps of delta_y / 1000 (peak a multiple of delta_y): every kink of the path, at +-delta_y
  // and +-(peak - 2 delta_y), is a step end, so the trapezoidal rule is exact on the loop.
  const int per_yield = 1000;
  const int peak_steps = static_cast<int>(std::lround(peak / kYield)) * per_yield;
  const auto deformation = [&](int index) { return kYield * index / per_yield; };
  const auto step_to = [&spring, &deformation](int index) {
    const double force = spring.set_trial(at(deformation(index))).force;
    spring.commit();
    return force;
  };
  for (int i = 0; i <= peak_steps; ++i) step_to(i);
  double energy = 0.0, previous_force = step_to(peak_steps);
  int previous = peak_steps;
  const auto advance = [&](int index) {
    const double force = step_to(index);
    energy += 0.5 * (force + previous_force) * (deformation(index) - deformation(previous));
    previous_force = force;
    previous = index;
  };
  for (int i = peak_steps - 1; i >= -peak_steps; --i) advance(i);
  for (int i = -peak_steps + 1; i <= peak_steps; ++i) advance(i);
  return energy;
}

TEST(SpringLaws, BilinearCycleDissipatesTheParallelogram) {
  for (double hardening : {0.0, kHardening, 0.3}) {
    for (double ductility : {3.0, 5.0}) {
      const double peak = ductility * kYield;
      const double exact = 4.0 * (1.0 - hardening) * kYieldForce * (peak - kYield);
      const double energy = cycle_energy(hardening, peak);
      const double error = std::abs(energy - exact) / exact;
      std::cout << "b = " << hardening << ", delta_m = " << ductility << " delta_y: energy "
                << energy << ", exact " << exact << ", relative error " << error << "\n";
      EXPECT_LT(error, 1e-9);
    }
  }
}

TEST(SpringLaws, BilinearKinematicHardeningMovesTheYieldSurface) {
  BilinearSpring spring(kStiffness, kYieldForce, kHardening);
  // First yield at F_y in either direction.
  EXPECT_DOUBLE_EQ(spring.set_trial(at(kYield)).force, kYieldForce);
  EXPECT_DOUBLE_EQ(spring.set_trial(at(-kYield)).force, -kYieldForce);
  // On the upper yield line b k delta + (1 - b) F_y.
  const double peak = 3.0 * kYield;
  const double peak_force = kHardening * kStiffness * peak + (1.0 - kHardening) * kYieldForce;
  EXPECT_NEAR(spring.set_trial(at(peak)).force, peak_force, 1e-9 * kYieldForce);
  spring.commit();
  EXPECT_NEAR(spring.back_force(), peak_force - kYieldForce, 1e-9 * kYieldForce);
  // Unloading is elastic until the force has dropped by 2 F_y (Bauschinger effect).
  const double reverse = peak - 2.0 * kYield;
  EXPECT_EQ(spring.set_trial(at(reverse + 1e-9)).stiffness, kStiffness);
  EXPECT_NEAR(spring.set_trial(at(reverse)).force, peak_force - 2.0 * kYieldForce,
              1e-9 * kYieldForce);
  EXPECT_DOUBLE_EQ(spring.set_trial(at(reverse - 1e-9)).stiffness, kHardening * kStiffness);
  // and then follows the lower yield line b k delta - (1 - b) F_y.
  EXPECT_NEAR(spring.set_trial(at(-peak)).force,
              -kHardening * kStiffness * peak - (1.0 - kHardening) * kYieldForce,
              1e-9 * kYieldForce);
  // A revert forgets the trial.
  spring.revert();
  EXPECT_NEAR(spring.set_trial(at(peak)).force, peak_force, 1e-9 * kYieldForce);
}

TEST(SpringLaws, BackfillHyperbolaPassesThroughTheUltimatePoint) {
  const Backfill law(kBackfillStiffness, kUltimateForce, kUltimate);
  const LawResponse ultimate = law.envelope(kUltimate);
  EXPECT_NEAR(ultimate.force, kUltimateForce, 1e-12 * kUltimateForce);
  const LawResponse origin = law.envelope(1e-12 * kUltimate);
  EXPECT_NEAR(origin.stiffness, kBackfillStiffness, 1e-9 * kBackfillStiffness);
  EXPECT_EQ(law.envelope(2.0 * kUltimate).force, kUltimateForce);
  EXPECT_EQ(law.envelope(2.0 * kUltimate).stiffness, 0.0);
  // Slope K (F_ult / (K delta_ult))^2 at delta_ult, from 1 + D delta_ult = K delta_ult / F_ult.
  const double ratio = kUltimateForce / (kBackfillStiffness * kUltimate);
  EXPECT_NEAR(ultimate.stiffness, kBackfillStiffness * ratio * ratio, 1e-9 * kBackfillStiffness);
}

TEST(SpringLaws, BackfillReloadsFromItsPermanentDeformation) {
  Backfill law(kBackfillStiffness, kUltimateForce, kUltimate);
  const double largest = 0.6 * kUltimate;
  const double largest_force = law.set_trial(at(largest)).force;
  law.commit();
  const double permanent = largest - largest_force / kBackfillStiffness;
  EXPECT_NEAR(law.permanent_deformation(), permanent, 1e-15);
  law.set_trial(at(-0.01));  // pulled back past the wall's original place: a gap opens
  law.commit();
  EXPECT_FALSE(law.in_contact());
  // Contact again at delta = p, slope K up to the largest deformation, then the backbone.
  EXPECT_EQ(law.set_trial(at(permanent - 1e-9)).force, 0.0);
  const double between = 0.5 * (permanent + largest);
  EXPECT_NEAR(law.set_trial(at(between)).force, kBackfillStiffness * (between - permanent),
              1e-9 * largest_force);
  EXPECT_NEAR(law.set_trial(at(largest)).force, largest_force, 1e-9 * largest_force);
  EXPECT_DOUBLE_EQ(law.set_trial(at(0.8 * kUltimate)).force, law.envelope(0.8 * kUltimate).force);
  // Beyond the ultimate point the permanent deformation grows with F_ult.
  law.set_trial(at(1.5 * kUltimate));
  law.commit();
  EXPECT_NEAR(law.permanent_deformation(), 1.5 * kUltimate - kUltimateForce / kBackfillStiffness,
              1e-15);
}

// Random walks of committed steps: the backfill never pulls nor exceeds its backbone and its
// permanent deformation never shrinks; the bilinear spring stays between its yield lines.
TEST(SpringLaws, ForcesStayInsideTheirBounds) {
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> step(-1.0, 1.0);
  Backfill soil(kBackfillStiffness, kUltimateForce, kUltimate);
  BilinearSpring bearing(kStiffness, kYieldForce, kHardening);
  double soil_delta = 0.0, bearing_delta = 0.0, soil_permanent = 0.0;
  double least_soil_force = 0.0, worst_above_backbone = 0.0, worst_permanent_drop = 0.0;
  double worst_outside_yield_lines = 0.0;
  for (int i = 0; i < 20000; ++i) {
    soil_delta =
        std::clamp(soil_delta + 0.05 * kUltimate * step(random), -kUltimate, 2.0 * kUltimate);
    const double force = soil.set_trial(at(soil_delta)).force;
    soil.commit();
    least_soil_force = std::min(least_soil_force, force);
    worst_above_backbone = std::max(worst_above_backbone, force - soil.envelope(soil_delta).force);
    worst_permanent_drop =
        std::max(worst_permanent_drop, soil_permanent - soil.permanent_deformation());
    soil_permanent = soil.permanent_deformation();

    bearing_delta =
        std::clamp(bearing_delta + 0.5 * kYield * step(random), -6.0 * kYield, 6.0 * kYield);
    const double bearing_force = bearing.set_trial(at(bearing_delta)).force;
    bearing.commit();
    const double line = kHardening * kStiffness * bearing_delta;
    worst_outside_yield_lines =
        std::max(worst_outside_yield_lines,
                 std::abs(bearing_force - line) - (1.0 - kHardening) * kYieldForce);
  }
  EXPECT_GE(least_soil_force, 0.0);
  EXPECT_LE(worst_above_backbone, 1e-12 * kUltimateForce);
  EXPECT_LE(worst_permanent_drop, 0.0);
  EXPECT_LE(worst_outside_yield_lines, 1e-12 * kYieldForce);
  EXPECT_GT(soil_permanent, kUltimate);  // the walk did reach the plateau
}

TEST(SpringLaws, BackfillRefusesAHyperbolaWithoutSoftening) {
  // F_ult / K = 0.1 >= delta_ult: D = K / F_ult - 1 / delta_ult <= 0.
  EXPECT_THROW(Backfill(1e6, 1e5, 0.1), std::invalid_argument);
  EXPECT_THROW(Backfill(1e6, 1e5, 0.05), std::invalid_argument);
  EXPECT_NO_THROW(Backfill(1e6, 1e5, 0.2));
}

TEST(SpringLaws, ClonesStartFromTheCommittedState) {
  auto law = bilinear();
  law->set_trial(at(3.0 * kYield));
  law->commit();
  law->set_trial(at(-3.0 * kYield));  // not committed
  auto copy = law->clone();
  EXPECT_DOUBLE_EQ(copy->set_trial(at(3.0 * kYield)).force, law->set_trial(at(3.0 * kYield)).force);
  EXPECT_EQ(copy->name(), "bilinear_spring");
}

}  // namespace
}  // namespace pound::links
