// Every contact law's consistent tangent against central finite differences, in each of its
// regimes (open, first contact inside the step, loading, unloading, clipped, yielding, ...),
// plus the behaviour each header promises.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>

#include "links/bilinear_impact.hpp"
#include "links/extended_penalty.hpp"
#include "links/hertz.hpp"
#include "links/hertz_damp.hpp"
#include "links/jankowski.hpp"
#include "links/kelvin_voigt.hpp"
#include "links/restitution.hpp"
#include "links/restrainer.hpp"

namespace pound::links {
namespace {

struct Case {
  std::string label;
  std::function<std::unique_ptr<LinkLaw>()> make;
  std::vector<LinkKinematics> history;  // committed one after the other before the trial
  LinkKinematics trial;
};

// Relative error of each tangent component against central differences of the force.
double tangent_error(const Case& c) {
  auto law = c.make();
  for (const LinkKinematics& k : c.history) {
    law->set_trial(k);
    law->commit();
  }
  const LawResponse at = law->set_trial(c.trial);
  const double scale = std::abs(at.force) + 1e-300;
  double worst = 0.0;
  const double analytic[3] = {at.stiffness, at.damping, at.mass};
  for (int variable = 0; variable < 3; ++variable) {
    LinkKinematics plus = c.trial, minus = c.trial;
    double* p[3] = {&plus.penetration, &plus.penetration_rate, &plus.penetration_acceleration};
    double* m[3] = {&minus.penetration, &minus.penetration_rate, &minus.penetration_acceleration};
    const double value = *p[variable];
    const double step = 1e-6 * std::max(std::abs(value), 1e-3);
    *p[variable] += step;
    *m[variable] -= step;
    const double numeric = (law->set_trial(plus).force - law->set_trial(minus).force) / (2 * step);
    // Compare the force change over a unit relative change of the variable.
    const double reach = std::max(std::abs(value), 1e-3);
    worst = std::max(worst, std::abs(numeric - analytic[variable]) * reach / scale);
  }
  law->set_trial(c.trial);
  return worst;
}

LinkKinematics at(double penetration, double rate = 0.0, double acceleration = 0.0) {
  return {penetration, rate, acceleration};
}

std::vector<Case> cases() {
  const auto kv = [] { return std::make_unique<KelvinVoigt>(1e6, 2e3, true); };
  const auto kv_tension = [] { return std::make_unique<KelvinVoigt>(1e6, 2e3, false); };
  const auto hertz = [] { return std::make_unique<Hertz>(1e9); };
  const auto hertz_damp = [] { return std::make_unique<HertzDamp>(1e9, hertz_damp_ratio_ye(0.6)); };
  const auto jankowski = [] {
    return std::make_unique<Jankowski>(1e9, jankowski_damping_ratio(0.6), 250.0);
  };
  const auto bilinear = [] {
    return std::make_unique<BilinearImpact>(BilinearImpact::Calibration{1e9, 0.6, 250.0});
  };
  const auto penalty = [] {
    return std::make_unique<ExtendedPenalty>(ExtendedPenalty::Numbers{1e6, 3e3, 2.0});
  };
  const auto restrainer = [] {
    return std::make_unique<Restrainer>("restrainer", 1e5, 0.01, 500.0, 0.05);
  };
  // A first contact: committed just before touching (delta < 0), trial inside.
  const std::vector<LinkKinematics> approach = {at(-2e-3, 0.5)};
  return {
      {"kelvin_voigt loading", kv, approach, at(1e-3, 0.4)},
      {"kelvin_voigt unloading", kv, {at(-2e-3, 0.5), at(1e-3, 0.1)}, at(5e-4, -0.2)},
      {"kelvin_voigt tension allowed", kv_tension, {at(-2e-3, 0.5), at(1e-3, 0.1)}, at(1e-4, -0.2)},
      {"hertz", hertz, approach, at(1e-3, 0.3)},
      {"hertz_damp first contact", hertz_damp, approach, at(1e-4, 0.45)},
      {"hertz_damp loading", hertz_damp, {at(-2e-3, 0.5), at(1e-4, 0.45)}, at(3e-4, 0.3)},
      {"hertz_damp unloading", hertz_damp, {at(-2e-3, 0.5), at(1e-4, 0.45)}, at(3e-4, -0.3)},
      {"jankowski approaching", jankowski, approach, at(1e-3, 0.3)},
      {"jankowski separating", jankowski, approach, at(1e-3, -0.3)},
      {"bilinear first contact elastic", bilinear, approach, at(1e-6, 0.45)},
      {"bilinear first contact upper line", bilinear, approach, at(1e-3, 0.45)},
      {"bilinear loading upper line", bilinear, {at(-2e-3, 0.5), at(5e-4, 0.4)}, at(8e-4, 0.2)},
      {"bilinear unloading elastic",
       bilinear,
       {at(-2e-3, 0.5), at(5e-4, 0.4), at(8e-4, 0.1)},
       at(7.9e-4, -0.1)},
      {"bilinear unloading lower line",
       bilinear,
       {at(-2e-3, 0.5), at(5e-4, 0.4), at(8e-4, 0.1)},
       at(2e-4, -0.1)},
      {"extended_penalty entering", penalty, approach, at(1e-4, 0.4, -50.0)},
      {"extended_penalty in contact",
       penalty,
       {at(-2e-3, 0.5), at(1e-4, 0.4)},
       at(2e-4, -0.05, -10.0)},
      {"restrainer taut", restrainer, {}, at(-0.012)},
      {"restrainer yielding", restrainer, {}, at(-0.02)},
      {"restrainer yielded and unloading", restrainer, {at(-0.02)}, at(-0.0195)},
  };
}

TEST(ContactLaws, TangentsMatchFiniteDifferencesInEveryRegime) {
  for (const Case& c : cases()) {
    const double error = tangent_error(c);
    std::cout << c.label << ": tangent error " << error << "\n";
    EXPECT_LT(error, 1e-5) << c.label;
  }
}

TEST(ContactLaws, OpenLinksCarryNoForce) {
  for (const Case& c : cases()) {
    if (c.label.starts_with("restrainer")) continue;
    auto law = c.make();
    const LawResponse response = law->set_trial(at(-1e-3, -0.1));
    EXPECT_EQ(response.force, 0.0) << c.label;
    EXPECT_EQ(response.stiffness, 0.0) << c.label;
  }
  Restrainer slack("restrainer", 1e5, 0.01);
  EXPECT_EQ(slack.set_trial(at(-0.005)).force, 0.0);  // within the slack
  EXPECT_EQ(slack.set_trial(at(0.005)).force, 0.0);   // closing: a cable does not push
}

TEST(ContactLaws, KelvinVoigtClipsTensionOnlyWhenAsked) {
  KelvinVoigt clipped(1e6, 2e3, true), exact(1e6, 2e3, false);
  EXPECT_EQ(clipped.set_trial(at(1e-4, -1.0)).force, 0.0);
  EXPECT_DOUBLE_EQ(exact.set_trial(at(1e-4, -1.0)).force, 1e6 * 1e-4 - 2e3);
}

TEST(ContactLaws, ExtendedPenaltyReleasesWhenTheForceWouldTurnTensile) {
  ExtendedPenalty law({1e6, 3e3, 2.0});
  law.set_trial(at(1e-4, 0.4));
  law.commit();
  ASSERT_TRUE(law.in_contact());
  // Still penetrating, but separating fast: the dashpot would pull; the contact is released.
  const LawResponse pulling = law.set_trial(at(1e-4, -1.0));
  EXPECT_EQ(pulling.force, 0.0);
  law.commit();
  EXPECT_FALSE(law.in_contact());
  // A penetrating but separating trial does not re-enter contact.
  EXPECT_EQ(law.set_trial(at(5e-5, -0.1)).force, 0.0);
}

TEST(ContactLaws, ExtendedPenaltyAutomaticNumbersFollowSuzukiToi) {
  const LinkContext context{
      .mass_i = 2.0, .mass_j = 6.0, .stiffness_i = 100.0, .stiffness_j = 300.0};
  const auto numbers = ExtendedPenalty::automatic(context, 1e-3, 1.0);
  EXPECT_DOUBLE_EQ(numbers.alpha0, 300.0 / 1e-3);                                      // eq. 20
  EXPECT_DOUBLE_EQ(numbers.alpha2, numbers.alpha0 * 8.0 / 400.0);                      // eq. 29
  EXPECT_DOUBLE_EQ(numbers.alpha1, 2.0 * std::sqrt(numbers.alpha0 * numbers.alpha2));  // eq. 34
  // Against a rigid wall the rigid side enters with k = m = 0.
  const LinkContext wall{.mass_i = 2.0, .stiffness_i = 100.0, .fixed_j = true};
  const auto rigid = ExtendedPenalty::automatic(wall, 1e-3, 1.0);
  EXPECT_DOUBLE_EQ(rigid.alpha2, rigid.alpha0 * 2.0 / 100.0);
}

TEST(ContactLaws, BilinearLoopPeaksAtTheHertzForceAndDissipatesTheTarget) {
  const BilinearImpact::Calibration calibration{1e9, 0.6, 250.0};
  const double v0 = 0.5;
  const auto c = BilinearImpact::calibrate(calibration, v0);
  const double peak = c.loop.yield_penetration / 0.1;
  const double upper =
      c.loop.k1 * c.loop.yield_penetration + c.loop.k2 * (peak - c.loop.yield_penetration);
  EXPECT_NEAR(upper / (1e9 * std::pow(peak, 1.5)), 1.0, 1e-12);
  const double dissipated =
      (c.loop.k1 - c.loop.k2) * c.loop.yield_penetration * (peak - c.loop.yield_penetration);
  const double energy = 0.5 * 250.0 * v0 * v0;
  EXPECT_NEAR(dissipated / ((1 - 0.36) * energy), 1.0, 1e-12);
  // Loading work 1/2 K_eff delta_m^2 + 1/2 dE absorbs the impact energy.
  const double loading = 0.5 * upper * peak + 0.5 * dissipated;
  EXPECT_NEAR(loading / energy, 1.0, 1e-12);
}

TEST(ContactLaws, YieldedRestrainerComesBackWithMoreSlack) {
  Restrainer cable("restrainer", 1e5, 0.01, 500.0, 0.0);
  const LawResponse yielding = cable.set_trial(at(-0.02));
  EXPECT_NEAR(-yielding.force, 500.0, 1e-9);
  cable.commit();
  EXPECT_NEAR(cable.permanent_deformation(), 0.01 - 500.0 / 1e5, 1e-12);
  EXPECT_EQ(cable.set_trial(at(-0.012)).force, 0.0);  // was taut at 0.012 before yielding
}

}  // namespace
}  // namespace pound::links
