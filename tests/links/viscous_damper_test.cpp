// The fluid viscous damper: its force on both sides of the linear zone, its tangent against
// finite differences, and the energy it dissipates in a harmonic cycle against the closed form.
#include "links/viscous_damper.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "core/errors.hpp"
#include "links/law_registry.hpp"

namespace pound::links {
namespace {

// A seismic damper: c = 2e6 N (s/m)^0.35, alpha = 0.35, linear below 1 mm/s.
constexpr double kCoefficient = 2e6, kExponent = 0.35, kLinear = 1e-3;

TEST(ViscousDamper, ForceFollowsThePowerLawAndIsLinearAtRest) {
  ViscousDamper damper(kCoefficient, kExponent, kLinear);
  EXPECT_DOUBLE_EQ(damper.set_trial({0.0, 0.4, 0.0}).force,
                   kCoefficient * std::pow(0.4, kExponent));
  EXPECT_DOUBLE_EQ(damper.set_trial({0.0, -0.4, 0.0}).force,
                   -kCoefficient * std::pow(0.4, kExponent));
  EXPECT_EQ(damper.set_trial({0.05, 0.0, 0.0}).force, 0.0);  // no stiffness
  // Continuous at the edge of the linear zone; finite tangent at rest.
  const double edge = kCoefficient * std::pow(kLinear, kExponent);
  EXPECT_NEAR(damper.set_trial({0.0, kLinear * (1 - 1e-12), 0.0}).force, edge, 1e-9 * edge);
  EXPECT_DOUBLE_EQ(damper.set_trial({0.0, 0.0, 0.0}).damping, edge / kLinear);
}

// dF/d(delta_dot) against central differences, in both branches and both directions.
TEST(ViscousDamper, TangentMatchesFiniteDifferences) {
  ViscousDamper damper(kCoefficient, kExponent, kLinear);
  for (double rate : {-0.7, -2e-4, 3e-4, 0.05, 1.3}) {
    const double step = 1e-7 * std::abs(rate);
    const double numeric = (damper.set_trial({0.0, rate + step, 0.0}).force -
                            damper.set_trial({0.0, rate - step, 0.0}).force) /
                           (2 * step);
    const LawResponse response = damper.set_trial({0.0, rate, 0.0});
    const double error = std::abs(response.damping / numeric - 1.0);
    std::cout << "rate " << rate << ": tangent error " << error << "\n";
    EXPECT_LT(error, 1e-6) << rate;
    EXPECT_EQ(response.stiffness, 0.0);
  }
}

// One cycle delta = X sin(w t): W = c w^a X^(1+a) 2^(2+a) G(1+a/2)^2 / G(2+a), by the trapezoidal
// rule over 2e5 steps (error ~ (2 pi / 2e5)^2 ~ 1e-9) with a linear zone at 1e-6 of the peak
// speed (error ~ (1e-6)^(1+a) ~ 1e-8).
TEST(ViscousDamper, DissipatesTheClosedFormEnergyPerCycle) {
  const double amplitude = 0.05, frequency = 2.0 * std::numbers::pi;
  for (double alpha : {1.0, kExponent}) {
    ViscousDamper damper(kCoefficient, alpha, 1e-6 * frequency * amplitude);
    const int steps = 200000;
    const double dt = 1.0 / steps;
    double work = 0.0, previous_force = 0.0, previous_delta = 0.0;
    for (int k = 0; k <= steps; ++k) {
      const double t = k * dt;
      const double delta = amplitude * std::sin(frequency * t);
      const double force =
          damper.set_trial({delta, amplitude * frequency * std::cos(frequency * t), 0.0}).force;
      if (k > 0) work += 0.5 * (force + previous_force) * (delta - previous_delta);
      previous_force = force;
      previous_delta = delta;
    }
    const double exact = kCoefficient * std::pow(frequency, alpha) *
                         std::pow(amplitude, 1 + alpha) * std::pow(2.0, 2 + alpha) *
                         std::pow(std::tgamma(1 + alpha / 2), 2) / std::tgamma(2 + alpha);
    std::cout << "alpha " << alpha << ": work " << work << " against " << exact
              << ", relative error " << work / exact - 1.0 << "\n";
    EXPECT_NEAR(work / exact, 1.0, 1e-7);
  }
}

TEST(ViscousDamper, AnExponentBelowOneNeedsItsLinearZone) {
  const LawSpec law{"viscous_damper", {{"coefficient", 1e6}, {"exponent", 0.5}}};
  try {
    make_law(law, {"m.json", "/links/2/law"});
    FAIL() << "accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "/links/2/law");
    EXPECT_NE(error.reason().find("linear_velocity"), std::string::npos) << error.reason();
  }
  EXPECT_NO_THROW(make_law({"viscous_damper", {{"coefficient", 1e6}}}, {}));
}

}  // namespace
}  // namespace pound::links
