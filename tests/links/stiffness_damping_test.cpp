// Stiffness-proportional damping of a yielding spring: a linear dashpot a1 k0 with the initial
// stiffness; with the committed tangent no viscous force while the spring yields (the spurious
// damping force of initial-stiffness damping) and a1 k back once it unloads; its tangents
// against finite differences; its viscous work over a harmonic cycle against the closed form.
#include "links/stiffness_damping.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "links/bilinear_spring.hpp"

namespace pound::links {
namespace {

// An elastic-perfectly-plastic spring: k = 1e6, F_y = 1e3 (delta_y = 1 mm); a1 = 0.01 s.
constexpr double kStiffness = 1e6, kYield = 1e3, kA1 = 0.01;

StiffnessDamping damped(DampingStiffness stiffness, double hardening = 0.0) {
  return StiffnessDamping(std::make_unique<BilinearSpring>(kStiffness, kYield, hardening), kA1,
                          stiffness);
}

// Sets a trial and commits it, as a converged step does.
LawResponse step(LinkLaw& law, double delta, double rate) {
  const LawResponse response = law.set_trial({delta, rate, 0.0});
  law.commit();
  return response;
}

TEST(StiffnessDamping, InitialIsALinearDashpotOfTheElasticStiffness) {
  StiffnessDamping law = damped(DampingStiffness::initial);
  EXPECT_EQ(law.name(), "bilinear_spring");  // results name the member's own law
  const LawResponse elastic = step(law, 5e-4, 0.2);
  EXPECT_DOUBLE_EQ(elastic.force, 500.0 + kA1 * kStiffness * 0.2);
  EXPECT_DOUBLE_EQ(elastic.damping, kA1 * kStiffness);
  // Yielding, the dashpot stays: the force passes F_y by a1 k0 v (Charney's spurious force).
  step(law, 2e-3, 0.2);
  const LawResponse yielding = step(law, 3e-3, 0.2);
  std::cout << "initial-stiffness damping while yielding: F / F_y = " << yielding.force / kYield
            << "\n";
  EXPECT_DOUBLE_EQ(yielding.force, kYield + kA1 * kStiffness * 0.2);
  EXPECT_DOUBLE_EQ(yielding.stiffness, 0.0);
}

TEST(StiffnessDamping, CommittedFollowsTheTangentOfTheLastConvergedStep) {
  StiffnessDamping law = damped(DampingStiffness::committed);
  // At rest the committed tangent is k0.
  EXPECT_DOUBLE_EQ(step(law, 5e-4, 0.2).force, 500.0 + kA1 * kStiffness * 0.2);
  // The step that yields still uses the elastic tangent committed before it ...
  EXPECT_DOUBLE_EQ(step(law, 2e-3, 0.2).force, kYield + kA1 * kStiffness * 0.2);
  // ... the next one the plastic tangent 0: the force is the yield force exactly.
  const LawResponse yielding = step(law, 3e-3, 0.2);
  EXPECT_EQ(yielding.force, kYield);
  EXPECT_EQ(yielding.damping, 0.0);
  EXPECT_EQ(law.coefficient(), 0.0);
  // Unloading: the reversal step has the plastic tangent committed before it, the next k0.
  const LawResponse reversal = step(law, 2.5e-3, -0.1);
  EXPECT_DOUBLE_EQ(reversal.force, kYield - kStiffness * 5e-4);
  EXPECT_DOUBLE_EQ(law.coefficient(), kA1 * kStiffness);
  const LawResponse unloading = step(law, 2.0e-3, -0.1);
  EXPECT_DOUBLE_EQ(unloading.force, kYield - kStiffness * 1e-3 - kA1 * kStiffness * 0.1);
}

// A softening tangent would give negative damping, which creates energy: it is taken as 0.
TEST(StiffnessDamping, NeverDampsWithANegativeTangent) {
  StiffnessDamping law = damped(DampingStiffness::committed, -0.05);
  step(law, 2e-3, 0.1);
  step(law, 3e-3, 0.1);
  EXPECT_EQ(law.coefficient(), 0.0);
  EXPECT_EQ(step(law, 4e-3, 0.1).damping, 0.0);
}

// dF/d(delta) and dF/d(delta_dot) against central differences, elastic and yielding, in both
// modes (within a step the coefficient is fixed, so the tangent is exact).
TEST(StiffnessDamping, TangentsMatchFiniteDifferences) {
  double worst = 0.0;
  for (DampingStiffness mode : {DampingStiffness::initial, DampingStiffness::committed})
    for (double delta : {3e-4, -6e-4, 2.5e-3, -4e-3}) {
      StiffnessDamping law = damped(mode, 0.02);
      step(law, 0.5 * delta, 0.1);
      const double rate = 0.15, h_delta = 1e-9, h_rate = 1e-6;
      const LawResponse at = law.set_trial({delta, rate, 0.0});
      const double stiffness = (law.set_trial({delta + h_delta, rate, 0.0}).force -
                                law.set_trial({delta - h_delta, rate, 0.0}).force) /
                               (2 * h_delta);
      const double damping = (law.set_trial({delta, rate + h_rate, 0.0}).force -
                              law.set_trial({delta, rate - h_rate, 0.0}).force) /
                             (2 * h_rate);
      worst = std::max({worst, std::abs(stiffness - at.stiffness) / kStiffness,
                        std::abs(damping - at.damping) / (kA1 * kStiffness)});
    }
  std::cout << "tangents against central differences: worst relative error " << worst << "\n";
  EXPECT_LT(worst, 1e-6);
}

// Over a cycle delta = A sin(w t) of an elastic spring, a dashpot c dissipates pi c w A^2; the
// viscous work (trapezoidal in delta, as the energy balance) converges to it at second order.
TEST(StiffnessDamping, ViscousWorkOfACycleIsTheDashpotsClosedForm) {
  const double amplitude = 5e-4, omega = 2 * std::numbers::pi;  // elastic throughout
  const double exact = std::numbers::pi * kA1 * kStiffness * omega * amplitude * amplitude;
  double previous_error = 0.0;
  for (int steps : {400, 800}) {
    StiffnessDamping law = damped(DampingStiffness::committed);
    for (int k = 0; k <= steps; ++k) {
      const double t = 2 * std::numbers::pi / omega * k / steps;
      step(law, amplitude * std::sin(omega * t), amplitude * omega * std::cos(omega * t));
    }
    const double error = std::abs(law.viscous_part().work - exact) / exact;
    std::cout << steps << " steps a cycle: viscous work error " << error << "\n";
    EXPECT_LT(error, 1e-4);
    if (previous_error > 0.0) {
      EXPECT_NEAR(previous_error / error, 4.0, 0.1);
    }
    previous_error = error;
    EXPECT_NEAR(law.viscous_part().force, kA1 * kStiffness * amplitude * omega, 1e-9);
  }
}

TEST(StiffnessDamping, RevertAndCloneKeepTheCommittedState) {
  StiffnessDamping law = damped(DampingStiffness::committed);
  step(law, 2e-3, 0.2);
  step(law, 3e-3, 0.2);
  const double work = law.viscous_part().work;
  law.set_trial({1e-3, -5.0, 0.0});
  law.revert();
  const std::unique_ptr<LinkLaw> copy = law.clone();
  for (LinkLaw* each : {static_cast<LinkLaw*>(&law), copy.get()}) {
    EXPECT_EQ(each->viscous_part().work, work);
    EXPECT_EQ(each->set_trial({4e-3, 0.2, 0.0}).force, kYield);  // still yielding, tangent 0
    EXPECT_EQ(each->yield_deformation(), 1e-3);
  }
}

}  // namespace
}  // namespace pound::links
