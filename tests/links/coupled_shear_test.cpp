// A bearing's coupled shear (links/coupled_shear.hpp) against what it must reduce to and against
// closed forms: one direction is BilinearSpring to the bit; a diagonal push yields at F_y, not at
// the sqrt(2) F_y of two uniaxial springs; a steady circular orbit dissipates
// 2 pi F_y sqrt(r^2 - delta_y^2) a turn at |F| = F_y; the consistent tangent matches central
// differences of the force.
#include "links/coupled_shear.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>

#include "links/bilinear_spring.hpp"
#include "links/elastic_spring.hpp"
#include "links/law_registry.hpp"

namespace pound::links {
namespace {

constexpr double kStiffness = 2.0e7, kYield = 3.0e5;

CoupledShear bearing(double hardening, int tangents = 2) {
  const ShearNumbers numbers{kStiffness, kYield, hardening};
  return {std::make_unique<ElasticSpring>(1e10), {numbers, numbers}, tangents};
}

// A rectangular column's hinge: about t_2 three times as stiff and twice as strong as about t_1.
constexpr double kStiffness2 = 3.0 * kStiffness, kYield2 = 2.0 * kYield;
CoupledShear elliptic(double hardening) {
  return {std::make_unique<ElasticSpring>(1e10),
          {ShearNumbers{kStiffness, kYield, hardening}, {kStiffness2, kYield2, hardening}},
          2};
}

FrictionResponse push(CoupledShear& law, double x, double y) {
  const std::array<LinkKinematics, 2> slide{LinkKinematics{x, 0.0, 0.0}, {y, 0.0, 0.0}};
  return law.set_trial({}, std::span<const LinkKinematics>(slide.data(), 2));
}

TEST(CoupledShear, OneDirectionIsTheBilinearSpringToTheBit) {
  BilinearSpring uniaxial(kStiffness, kYield, 0.1);
  CoupledShear coupled = bearing(0.1, 1);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> step(-0.01, 0.01);
  double s = 0.0;
  int differences = 0;
  for (int k = 0; k < 5000; ++k) {
    s += step(random);
    const LawResponse expected = uniaxial.set_trial({s, 0.0, 0.0});
    const LinkKinematics slide{s, 0.0, 0.0};
    const FrictionResponse got = coupled.set_trial({}, std::span<const LinkKinematics>(&slide, 1));
    differences += got.tangential_force[0] != expected.force ||
                   got.tangential_on_slip[0][0].stiffness != expected.stiffness;
    uniaxial.commit();
    coupled.commit();
  }
  EXPECT_EQ(differences, 0);
}

// Pushed along 45 degrees far past yield with no hardening: the coupled bearing holds |F| = F_y
// along the push; two uniaxial springs would each reach F_y, sqrt(2) F_y together.
TEST(CoupledShear, ADiagonalPushYieldsAtTheYieldForceNotRootTwoTimesIt) {
  CoupledShear coupled = bearing(0.0);
  BilinearSpring x(kStiffness, kYield, 0.0), y(kStiffness, kYield, 0.0);
  const double reach = 20.0 * kYield / kStiffness;
  FrictionResponse last;
  double uniaxial = 0.0;
  for (int k = 1; k <= 400; ++k) {
    const double s = reach * k / 400.0 / std::numbers::sqrt2;
    last = push(coupled, s, s);
    coupled.commit();
    uniaxial = std::hypot(x.set_trial({s, 0.0, 0.0}).force, y.set_trial({s, 0.0, 0.0}).force);
    x.commit();
    y.commit();
  }
  const double resultant = std::hypot(last.tangential_force[0], last.tangential_force[1]);
  const double off_line = std::abs(last.tangential_force[0] - last.tangential_force[1]) / kYield;
  std::cout << fmt::format(
      "diagonal push to 20 delta_y: coupled |F| / F_y - 1 = {:.1e} (off the push {:.1e}); "
      "uncoupled |F| / F_y = {:.6f}\n",
      resultant / kYield - 1.0, off_line, uniaxial / kYield);
  EXPECT_LT(std::abs(resultant / kYield - 1.0), 1e-14);
  EXPECT_LT(off_line, 1e-14);
  EXPECT_NEAR(uniaxial / kYield, std::numbers::sqrt2, 1e-14);
}

// The tangent of a yielding trial (b = 0.1, from a bent history) against central differences of
// the force in each direction (step 1e-7 of the deformation: truncation ~1e-14 relative, round-off
// ~1e-9): elastic k I before yield, and the radial return's tangent after.
TEST(CoupledShear, TheTangentIsTheForcesDerivative) {
  double worst = 0.0;
  for (const std::array<double, 2> target : {std::array{0.004, 0.003}, std::array{0.02, -0.011}})
    for (const bool ellipse : {false, true}) {
      CoupledShear law = ellipse ? elliptic(0.1) : bearing(0.1);
      push(law, 0.012, 0.0);  // a plastic history along x first
      law.commit();
      const FrictionResponse at = push(law, target[0], target[1]);
      const double h = 1e-7;
      for (int b = 0; b < 2; ++b) {
        std::array<double, 2> plus = target, minus = target;
        plus[static_cast<std::size_t>(b)] += h;
        minus[static_cast<std::size_t>(b)] -= h;
        const FrictionResponse up = push(law, plus[0], plus[1]);
        const FrictionResponse down = push(law, minus[0], minus[1]);
        for (std::size_t a = 0; a < 2; ++a) {
          const double difference = (up.tangential_force[a] - down.tangential_force[a]) / (2 * h);
          worst = std::max(
              worst, std::abs(difference - at.tangential_on_slip[a][b].stiffness) / kStiffness);
        }
      }
    }
  std::cout << fmt::format(
      "coupled shear tangent against central differences (circle and ellipse): {:.1e} of k_1\n",
      worst);
  EXPECT_LT(worst, 1e-7);
}

// Driven around a circle of radius r = 5 delta_y (b = 0): in the steady state the plastic
// deformation trails the displacement by phi = asin(delta_y / r) on a circle of radius r cos phi,
// the force |F| = F_y points along its slip (ahead of the displacement by pi / 2 - phi), and a
// turn dissipates 2 pi F_y sqrt(r^2 - delta_y^2). 20,000 steps a turn: the backward-Euler return's
// error in the work is O(step), about 1e-4 here.
TEST(CoupledShear, ACircularOrbitDissipatesTheClosedFormAtTheYieldForce) {
  CoupledShear law = bearing(0.0);
  const double yield_deformation = kYield / kStiffness, radius = 5.0 * yield_deformation;
  const int per_turn = 20000;
  double work = 0.0, largest_force_error = 0.0, lead = 0.0;
  std::array<double, 2> previous_s{radius, 0.0}, previous_force{0.0, 0.0};
  for (int k = 0; k <= 3 * per_turn; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / per_turn;
    const std::array<double, 2> s{radius * std::cos(angle), radius * std::sin(angle)};
    const FrictionResponse response = push(law, s[0], s[1]);
    law.commit();
    const std::array<double, 2> force{response.tangential_force[0], response.tangential_force[1]};
    if (k > 2 * per_turn) {  // the third turn
      for (std::size_t a = 0; a < 2; ++a)
        work += 0.5 * (force[a] + previous_force[a]) * (s[a] - previous_s[a]);
      largest_force_error =
          std::max(largest_force_error, std::abs(std::hypot(force[0], force[1]) / kYield - 1.0));
      lead = std::atan2(force[1], force[0]) - angle;
    }
    previous_s = s;
    previous_force = force;
  }
  const double expected = 2.0 * std::numbers::pi * kYield *
                          std::sqrt(radius * radius - yield_deformation * yield_deformation);
  lead = std::remainder(lead, 2.0 * std::numbers::pi);
  const double expected_lead = 0.5 * std::numbers::pi - std::asin(yield_deformation / radius);
  std::cout << fmt::format(
      "circular orbit r = 5 delta_y, third turn: work {:.6e} against {:.6e} ({:.1e}), |F| / F_y "
      "- 1 up to {:.1e}, force ahead by {:.6f} rad against {:.6f}\n",
      work, expected, work / expected - 1.0, largest_force_error, lead, expected_lead);
  EXPECT_LT(std::abs(work / expected - 1.0), 5e-4);
  EXPECT_LT(largest_force_error, 1e-13);
  EXPECT_NEAR(lead, expected_lead, 5e-4);
}

TEST(CoupledShear, RevertForgetsTheTrialAndCopiesKeepTheCommittedState) {
  CoupledShear law = bearing(0.05);
  push(law, 0.05, 0.02);
  law.commit();
  const std::array<double, 2> plastic{law.plastic_deformation()[0], law.plastic_deformation()[1]};
  EXPECT_GT(std::hypot(plastic[0], plastic[1]), 0.0);
  push(law, -0.2, 0.3);
  law.revert();
  CoupledShear copy(law);
  const FrictionResponse from_law = push(law, 0.01, 0.01);
  const FrictionResponse from_copy = push(copy, 0.01, 0.01);
  EXPECT_EQ(from_law.tangential_force[0], from_copy.tangential_force[0]);
  EXPECT_EQ(from_law.tangential_force[1], from_copy.tangential_force[1]);
  EXPECT_EQ(law.plastic_deformation()[0], plastic[0]);
}

// An elliptic surface: each direction alone is that direction's bilinear law to round-off (the
// two-direction return computes what the uniaxial law does in another order; the second is also
// scaled into the first's units and back), over a random history that yields both ways.
TEST(CoupledShear, EachAxisOfAnEllipseIsItsOwnBilinearLaw) {
  for (const std::size_t along : {std::size_t{0}, std::size_t{1}}) {
    BilinearSpring uniaxial(along == 0 ? kStiffness : kStiffness2, along == 0 ? kYield : kYield2,
                            0.1);
    CoupledShear law = elliptic(0.1);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> step(-0.01, 0.01);
    double s = 0.0, worst_force = 0.0, worst_tangent = 0.0;
    for (int k = 0; k < 5000; ++k) {
      s += step(random);
      const LawResponse expected = uniaxial.set_trial({s, 0.0, 0.0});
      const FrictionResponse got = along == 0 ? push(law, s, 0.0) : push(law, 0.0, s);
      worst_force = std::max(worst_force, std::abs(got.tangential_force[along] - expected.force));
      worst_tangent =
          std::max(worst_tangent,
                   std::abs(got.tangential_on_slip[along][along].stiffness - expected.stiffness));
      uniaxial.commit();
      law.commit();
    }
    std::cout << fmt::format(
        "ellipse along t_{}: force off the bilinear law by {:.1e} of F_y, tangent {:.1e} of k\n",
        along + 1, worst_force / (along == 0 ? kYield : kYield2),
        worst_tangent / (along == 0 ? kStiffness : kStiffness2));
    EXPECT_LT(worst_force, 1e-13 * (along == 0 ? kYield : kYield2));
    EXPECT_LT(worst_tangent, 1e-14 * (along == 0 ? kStiffness : kStiffness2));
  }
}

// Pushed far past yield (b = 0) along s = r (delta_y1 cos a, delta_y2 sin a), a ray in yield
// units, the force stops at (F_y1 cos a, F_y2 sin a): on the ellipse, at the point the ray meets.
TEST(CoupledShear, ARayPushOnAnEllipseStopsWhereTheRayMeetsIt) {
  double worst = 0.0;
  for (const double angle : {0.3, 1.0, 2.2, 4.0}) {
    CoupledShear law = elliptic(0.0);
    FrictionResponse last;
    for (int k = 1; k <= 200; ++k) {
      const double r = 20.0 * k / 200.0;
      last = push(law, r * kYield / kStiffness * std::cos(angle),
                  r * kYield2 / kStiffness2 * std::sin(angle));
      law.commit();
    }
    worst = std::max({worst, std::abs(last.tangential_force[0] / kYield - std::cos(angle)),
                      std::abs(last.tangential_force[1] / kYield2 - std::sin(angle))});
  }
  std::cout << fmt::format(
      "ray pushes to 20 delta_y on an ellipse: force off (F_y1 cos a, F_y2 "
      "sin a) by {:.1e} of F_y\n",
      worst);
  EXPECT_LT(worst, 1e-14);
}

// Rayleigh damping of the shear: on the initial stiffness a dashpot a1 k_a along each direction;
// on the committed tangent a1 times the 2 x 2 tangent of the last converged step, held through
// the next; its work the trapezoid of its force over the slide.
TEST(CoupledShear, ItsDampingIsTheInitialOrTheCommittedStiffnessTimesA1) {
  const double a1 = 0.01;
  const auto trial = [](CoupledShear& law, double x, double y, double rate_x, double rate_y) {
    const std::array<LinkKinematics, 2> slide{LinkKinematics{x, rate_x, 0.0}, {y, rate_y, 0.0}};
    return law.set_trial({}, std::span<const LinkKinematics>(slide.data(), 2));
  };
  CoupledShear initial = elliptic(0.1);
  initial.set_damping({a1, DampingStiffness::initial});
  trial(initial, 0.0, 0.0, 0.3, 0.5);  // the slide the work starts from
  initial.commit();
  const FrictionResponse elastic = trial(initial, 1e-4, -2e-4, 0.3, 0.5);
  EXPECT_DOUBLE_EQ(elastic.tangential_force[0], kStiffness * 1e-4 + a1 * kStiffness * 0.3);
  EXPECT_DOUBLE_EQ(elastic.tangential_force[1], -kStiffness2 * 2e-4 + a1 * kStiffness2 * 0.5);
  EXPECT_EQ(elastic.tangential_on_slip[0][0].damping, a1 * kStiffness);
  EXPECT_EQ(elastic.tangential_on_slip[1][1].damping, a1 * kStiffness2);
  EXPECT_EQ(elastic.tangential_on_slip[0][1].damping, 0.0);
  initial.commit();
  EXPECT_DOUBLE_EQ(initial.viscous_part().work,
                   a1 * (kStiffness * 0.3 * 1e-4 + kStiffness2 * 0.5 * -2e-4));

  CoupledShear committed = elliptic(0.1);
  committed.set_damping({a1, DampingStiffness::committed});
  const FrictionResponse yielding = trial(committed, 0.05, 0.03, 0.0, 0.0);
  committed.commit();
  const FrictionResponse next = trial(committed, 0.05, 0.03, 1.0, 0.0);
  for (std::size_t a = 0; a < 2; ++a)
    for (std::size_t b = 0; b < 2; ++b)
      EXPECT_DOUBLE_EQ(next.tangential_on_slip[a][b].damping,
                       a1 * yielding.tangential_on_slip[a][b].stiffness);
  const double viscous = a1 * yielding.tangential_on_slip[1][0].stiffness;
  EXPECT_NEAR(next.tangential_force[1] - yielding.tangential_force[1], viscous, 1e-12 * kYield2);
}

TEST(CoupledShear, TwoDirectionsMakeOneLawOnlyWithOneHardeningRatio) {
  const ShearNumbers first{1e6, 1e4, 0.1};
  EXPECT_FALSE(CoupledShear::mismatch(first, {3e6, 2e4, 0.1}));
  const std::optional<std::string> hardening = CoupledShear::mismatch(first, {3e6, 2e4, 0.2});
  ASSERT_TRUE(hardening);
  EXPECT_NE(hardening->find("0.1 and 0.2"), std::string::npos) << *hardening;
  EXPECT_TRUE(CoupledShear::mismatch(first, {3e6, std::numeric_limits<double>::infinity(), 0.1}));
}

// The numbers come from the uniaxial laws' own: lead_rubber's k_u, F_y = Q_d k_u / (k_u - k_d),
// b = k_d / k_u; an elastic spring never yields; a Bouc-Wen law's F_y is k z_max / A (or its
// yield_force), with its shape; a Takeda law has no coupled form.
TEST(CoupledShear, TakesItsNumbersFromTheUniaxialLaws) {
  const LawSource where{"test.json", "/links/0/shear"};
  const auto lead = CoupledShear::numbers_of({"lead_rubber",
                                              {{"characteristic_strength", 1e5},
                                               {"post_yield_stiffness", 1e6},
                                               {"elastic_stiffness", 1e7}}},
                                             where);
  ASSERT_TRUE(lead);
  EXPECT_DOUBLE_EQ(lead->stiffness, 1e7);
  EXPECT_DOUBLE_EQ(lead->yield_force, 1e5 * 1e7 / (1e7 - 1e6));
  EXPECT_DOUBLE_EQ(lead->hardening_ratio, 0.1);
  const auto elastic = CoupledShear::numbers_of({"elastic_spring", {{"stiffness", 3e6}}}, where);
  ASSERT_TRUE(elastic);
  EXPECT_EQ(elastic->yield_force, std::numeric_limits<double>::infinity());
  CoupledShear spring(std::make_unique<ElasticSpring>(1.0), {*elastic, *elastic}, 2);
  const FrictionResponse far = push(spring, 10.0, -4.0);
  EXPECT_EQ(far.tangential_force[0], 3e7);
  EXPECT_EQ(far.tangential_on_slip[0][1].stiffness, 0.0);
  const auto smooth = CoupledShear::numbers_of(
      {"bouc_wen",
       {{"stiffness", 2e7}, {"sharpness", 2.0}, {"beta", 1.0}, {"gamma", 3.0}, {"amplitude", 2.0}}},
      where);
  ASSERT_TRUE(smooth && smooth->smooth);
  EXPECT_DOUBLE_EQ(smooth->yield_deformation(), std::sqrt(2.0 / 4.0) / 2.0);
  EXPECT_DOUBLE_EQ(smooth->initial_stiffness(), 2.0 * 2e7);
  const auto strong = CoupledShear::numbers_of({"bouc_wen",
                                                {{"stiffness", 2e7},
                                                 {"sharpness", 2.0},
                                                 {"beta", 1.0},
                                                 {"gamma", 3.0},
                                                 {"yield_force", 3e5}}},
                                               where);
  ASSERT_TRUE(strong && strong->smooth);
  EXPECT_DOUBLE_EQ(strong->yield_force, 3e5);
  EXPECT_DOUBLE_EQ(strong->smooth->beta / (strong->smooth->beta + strong->smooth->gamma), 0.25);
  EXPECT_FALSE(CoupledShear::numbers_of({"takeda", find_law("takeda")->example}, where));
}

}  // namespace
}  // namespace pound::links
