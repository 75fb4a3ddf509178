// The coupled Bouc-Wen law (links/plane_bouc_wen.hpp, through links/coupled_shear.hpp) against
// what it must reduce to and against closed forms: along any line it is the uniaxial law
// (links/bouc_wen.hpp), for every shape the uniaxial tests use; a rotated path gives the rotated
// force; |z| never passes z_max; a steady circular orbit settles at |z| = z_max, lagging by
// asin(z_max / (A r)), and dissipates 2 pi (1 - a) k z_max sqrt(r^2 - (z_max / A)^2) a turn; the
// consistent tangent matches central differences of the force; an ellipse's axes are their own
// uniaxial laws.
#include "links/plane_bouc_wen.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "links/bouc_wen.hpp"
#include "links/coupled_shear.hpp"
#include "links/elastic_spring.hpp"
#include "support/bouc_wen_shapes.hpp"

namespace pound::links {
namespace {

using Shape = testing::BoucWenShape;
constexpr double kStiffness = testing::kBoucWenStiffness;
constexpr double kZmax = testing::kBoucWenZmax;
constexpr auto shapes = testing::bouc_wen_shapes;

ShearNumbers numbers(const BoucWen::Parameters& p) { return *CoupledShear::numbers_of(BoucWen(p)); }

CoupledShear coupled(const BoucWen::Parameters& p) {
  return {std::make_unique<ElasticSpring>(1e10), {numbers(p), numbers(p)}, 2};
}

std::array<double, 2> push(CoupledShear& law, double x, double y) {
  const std::array<LinkKinematics, 2> slide{LinkKinematics{x, 0.0, 0.0}, {y, 0.0, 0.0}};
  const FrictionResponse out = law.set_trial({}, std::span<const LinkKinematics>(slide.data(), 2));
  return {out.tangential_force[0], out.tangential_force[1]};
}

// A history of reversals between +-4 z_max in random steps of 0.02-0.6 z_max.
std::vector<double> reversals(unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> target(-4.0 * kZmax, 4.0 * kZmax), step(0.02, 0.6);
  std::vector<double> path{0.0};
  for (int turn = 0; turn < 12; ++turn) {
    const double to = target(generator);
    while (std::abs(to - path.back()) > 1e-12) {
      const double move = step(generator) * kZmax;
      path.push_back(std::abs(to - path.back()) < move
                         ? to
                         : path.back() + std::copysign(move, to - path.back()));
    }
  }
  return path;
}

TEST(PlaneBoucWen, AlongALineItIsTheUniaxialLaw) {
  double worst = 0.0, worst_across = 0.0;
  const double angle = 0.61;  // the line, from t_1
  for (const Shape& s : shapes()) {
    CoupledShear plane = coupled(s.parameters);
    BoucWen line(s.parameters);
    double error = 0.0, across = 0.0;
    for (const double delta : reversals(7)) {
      const std::array<double, 2> force =
          push(plane, delta * std::cos(angle), delta * std::sin(angle));
      plane.commit();
      const double reference = line.set_trial({delta, 0.0, 0.0}).force;
      line.commit();
      const double along = force[0] * std::cos(angle) + force[1] * std::sin(angle);
      error = std::max(error, std::abs(along - reference) / (kStiffness * kZmax));
      across = std::max(across, std::abs(force[1] * std::cos(angle) - force[0] * std::sin(angle)) /
                                    (kStiffness * kZmax));
    }
    std::cout << fmt::format(
        "{:<28} along a line against the uniaxial law: {:.1e} of k z_max, "
        "across it {:.1e}\n",
        s.label, error, across);
    worst = std::max(worst, error);
    worst_across = std::max(worst_across, across);
  }
  // Each law is within ~1e-9 z_max of its ODE's exact solution (tests/links/bouc_wen_test.cpp).
  EXPECT_LT(worst, 1e-8);
  EXPECT_LT(worst_across, 1e-13);
}

// A path in the plane, and the same path turned by 2.2 rad: the forces turn with it.
TEST(PlaneBoucWen, ARotatedPathGivesTheRotatedForceAndZStaysInItsBound) {
  double worst = 0.0, largest_z = 0.0;
  const double turn = 2.2;
  for (const Shape& s : shapes()) {
    CoupledShear plane = coupled(s.parameters), turned = coupled(s.parameters);
    PlaneBoucWen alone(numbers(s.parameters), 2);
    std::mt19937 generator(11);
    std::uniform_real_distribution<double> step(-0.7 * kZmax, 0.7 * kZmax);
    std::array<double, 2> at{0.0, 0.0};
    for (int k = 0; k < 400; ++k) {
      at[0] = std::clamp(at[0] + step(generator), -4.0 * kZmax, 4.0 * kZmax);
      at[1] = std::clamp(at[1] + step(generator), -4.0 * kZmax, 4.0 * kZmax);
      const std::array<double, 2> force = push(plane, at[0], at[1]);
      const std::array<double, 2> other =
          push(turned, at[0] * std::cos(turn) - at[1] * std::sin(turn),
               at[0] * std::sin(turn) + at[1] * std::cos(turn));
      plane.commit();
      turned.commit();
      const std::array<double, 2> back{other[0] * std::cos(turn) + other[1] * std::sin(turn),
                                       -other[0] * std::sin(turn) + other[1] * std::cos(turn)};
      worst = std::max(worst,
                       std::hypot(back[0] - force[0], back[1] - force[1]) / (kStiffness * kZmax));
      alone.set_trial({at[0], at[1]});
      alone.commit();
      const Tangential z = alone.hysteretic_deformation();
      largest_z = std::max(largest_z, std::hypot(z[0], z[1]) / alone.saturation());
    }
  }
  std::cout << fmt::format(
      "a path turned 2.2 rad: force turned to {:.1e} of k z_max; largest "
      "|z| / z_max {:.15f}\n",
      worst, largest_z);
  EXPECT_LT(worst, 1e-12);
  EXPECT_LE(largest_z, 1.0 + 1e-12);
  EXPECT_GT(largest_z, 0.99);
}

// Driven around a circle of radius r = 5 z_max / A: in the steady state z has |z| = z_max and
// lags the direction of motion by psi = asin(z_max / (A r)); a turn dissipates
// 2 pi (1 - a) k z_max sqrt(r^2 - (z_max / A)^2) (the elastic part a k s does no work over a
// turn). The law follows the chords of 20,000 steps a turn: O(1 / N^2) off the circle.
TEST(PlaneBoucWen, ACircularOrbitDissipatesTheClosedForm) {
  for (const Shape& s : {shapes()[3], shapes()[5]}) {
    const BoucWen::Parameters& p = s.parameters;
    PlaneBoucWen law(numbers(p), 2);
    const double z_max = law.saturation(), radius = 5.0 * z_max / p.amplitude;
    const int per_turn = 20000;
    double work = 0.0, largest_error = 0.0, lag = 0.0;
    std::array<double, 2> previous_s{radius, 0.0}, previous_force{0.0, 0.0};
    for (int k = 0; k <= 4 * per_turn; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / per_turn;
      const Tangential s_k{radius * std::cos(angle), radius * std::sin(angle)};
      const PlaneResponse response = law.set_trial(s_k);
      law.commit();
      if (k > 3 * per_turn) {  // the fourth turn
        for (std::size_t a = 0; a < 2; ++a)
          work += 0.5 * (response.force[a] + previous_force[a]) * (s_k[a] - previous_s[a]);
        const Tangential z = law.hysteretic_deformation();
        largest_error = std::max(largest_error, std::abs(std::hypot(z[0], z[1]) / z_max - 1.0));
        lag = angle + 0.5 * std::numbers::pi - std::atan2(z[1], z[0]);
      }
      previous_s = {s_k[0], s_k[1]};
      previous_force = {response.force[0], response.force[1]};
    }
    const double expected = 2.0 * std::numbers::pi * (1.0 - p.hardening_ratio) * p.stiffness *
                            z_max * std::sqrt(radius * radius - std::pow(z_max / p.amplitude, 2.0));
    lag = std::remainder(lag, 2.0 * std::numbers::pi);
    const double expected_lag = std::asin(z_max / (p.amplitude * radius));
    std::cout << fmt::format(
        "{}: circular orbit r = 5 z_max / A, fourth turn: work {:.8e} against {:.8e} ({:.1e}), "
        "||z| / z_max - 1| up to {:.1e}, lag {:.8f} rad against {:.8f}\n",
        s.label, work, expected, work / expected - 1.0, largest_error, lag, expected_lag);
    EXPECT_LT(std::abs(work / expected - 1.0), 1e-6);
    EXPECT_LT(largest_error, 1e-6);
    EXPECT_NEAR(lag, expected_lag, 1e-6);
  }
}

// The 2 x 2 tangent against central differences of the force, from states with a history, for
// trials that load, unload, and unload then load (through z . D = 0).
TEST(PlaneBoucWen, TheTangentIsTheForcesDerivative) {
  double worst = 0.0;
  for (const Shape& s : shapes()) {
    CoupledShear law = coupled(s.parameters);
    push(law, 3.0 * kZmax, 0.5 * kZmax);
    law.commit();
    push(law, 2.2 * kZmax, 1.5 * kZmax);
    law.commit();
    for (const std::array<double, 2> target :
         {std::array{2.4 * kZmax, 1.9 * kZmax}, std::array{1.9 * kZmax, 1.2 * kZmax},
          std::array{-0.5 * kZmax, 0.2 * kZmax}}) {
      const std::array<LinkKinematics, 2> slide{LinkKinematics{target[0], 0.0, 0.0},
                                                {target[1], 0.0, 0.0}};
      const FrictionResponse at =
          law.set_trial({}, std::span<const LinkKinematics>(slide.data(), 2));
      const double h = 1e-6 * kZmax;
      for (std::size_t b = 0; b < 2; ++b) {
        std::array<double, 2> plus = target, minus = target;
        plus[b] += h;
        minus[b] -= h;
        const std::array<double, 2> up = push(law, plus[0], plus[1]);
        const std::array<double, 2> down = push(law, minus[0], minus[1]);
        for (std::size_t a = 0; a < 2; ++a) {
          const double difference = (up[a] - down[a]) / (2.0 * h);
          worst = std::max(
              worst, std::abs(difference - at.tangential_on_slip[a][b].stiffness) / kStiffness);
        }
      }
    }
  }
  std::cout << fmt::format("coupled Bouc-Wen tangent against central differences: {:.1e} of k\n",
                           worst);
  EXPECT_LT(worst, 1e-5);
}

// A rectangular column's hinge: about t_2 three times as stiff and twice as strong, one loop
// shape. Pushed along either axis alone it is that axis's uniaxial law; two Bouc-Wen directions
// of different shapes, or a Bouc-Wen and a bilinear one, do not make one law.
TEST(PlaneBoucWen, EachAxisOfAnEllipseIsItsOwnUniaxialLaw) {
  const BoucWen::Parameters one =
      BoucWen::with_yield_force(testing::bouc_wen_shape(2.0, 0.5, 0.5, 0.05), 1e5);
  BoucWen::Parameters two = one;
  two.stiffness = 3.0 * one.stiffness;
  two = BoucWen::with_yield_force(two, 2e5);
  ASSERT_FALSE(CoupledShear::mismatch(numbers(one), numbers(two)));
  double worst = 0.0;
  for (std::size_t axis = 0; axis < 2; ++axis) {
    CoupledShear plane(std::make_unique<ElasticSpring>(1e10), {numbers(one), numbers(two)}, 2);
    BoucWen line(axis == 0 ? one : two);
    for (const double delta : reversals(5)) {
      const double along = 2.0 * delta;  // reaches 8 z_max,1
      const std::array<double, 2> force =
          push(plane, axis == 0 ? along : 0.0, axis == 0 ? 0.0 : along);
      plane.commit();
      const double reference = line.set_trial({along, 0.0, 0.0}).force;
      line.commit();
      worst = std::max(worst, std::abs(force[axis] - reference) / (axis == 0 ? 1e5 : 2e5));
      EXPECT_EQ(force[1 - axis], 0.0);
    }
  }
  std::cout << fmt::format(
      "each axis of a Bouc-Wen ellipse against its uniaxial law: {:.1e} of "
      "F_y\n",
      worst);
  EXPECT_LT(worst, 1e-8);
  BoucWen::Parameters wider = two;
  wider.gamma *= 2.0;
  EXPECT_TRUE(CoupledShear::mismatch(numbers(one), numbers(wider)));
  EXPECT_TRUE(CoupledShear::mismatch(numbers(one), {kStiffness, 1e5, 0.05}));
}

// A move of any length costs a bounded number of sub-steps: past 64 z_max / A of loading z is
// z_max along the move to rounding, and its sensitivity dz/dD = z_max / |D| (I - d d^T) (only
// the move's direction turns z). A push of 60 z_max / A, integrated, and of 1e9 z_max, taken
// as that limit, against the closed form, from a state with z across the move, every shape.
TEST(PlaneBoucWen, AnEnormousMoveSaturatesAtOnce) {
  std::array<double, 2> worst_z{}, worst_tangent{};  // integrated, limit
  for (const Shape& s : shapes()) {
    const BoucWen::Parameters& p = s.parameters;
    for (const std::size_t limit : {0u, 1u}) {
      PlaneBoucWen law(numbers(p), 2);
      law.set_trial({0.5 * kZmax, -0.3 * kZmax});  // a state with z across the move first
      law.commit();
      const double z_max = law.saturation(), a = p.hardening_ratio, k = p.stiffness;
      const double length = limit ? 1e9 * kZmax : 60.0 * z_max / p.amplitude, angle = 2.5;
      const Tangential d{std::cos(angle), std::sin(angle)};
      // The move D = length d from the committed s.
      const PlaneResponse response =
          law.set_trial({0.5 * kZmax + length * d[0], -0.3 * kZmax + length * d[1]});
      law.commit();
      for (std::size_t i = 0; i < 2; ++i) {
        const double z = law.hysteretic_deformation()[i];
        worst_z[limit] = std::max(worst_z[limit], std::abs(z - z_max * d[i]) / z_max);
        for (std::size_t j = 0; j < 2; ++j) {
          const double across = (i == j ? 1.0 : 0.0) - d[i] * d[j];
          const double tangent =
              a * k * (i == j ? 1.0 : 0.0) + (1.0 - a) * k * z_max / length * across;
          worst_tangent[limit] =
              std::max(worst_tangent[limit], std::abs(response.tangent[i][j] - tangent) / k);
        }
      }
    }
  }
  std::cout << fmt::format(
      "a push of 60 z_max / A (integrated): z off z_max d by {:.1e} of z_max, tangent off the "
      "limit's by {:.1e} of k; of 1e9 z_max (the limit): {:.1e}, {:.1e}\n",
      worst_z[0], worst_tangent[0], worst_z[1], worst_tangent[1]);
  EXPECT_LT(worst_z[0], 1e-12);
  EXPECT_LT(worst_tangent[0], 1e-12);
  EXPECT_LT(worst_z[1], 1e-15);
  EXPECT_LT(worst_tangent[1], 1e-15);
}

TEST(PlaneBoucWen, RevertForgetsTheTrialAndCopiesKeepTheCommittedState) {
  const BoucWen::Parameters p = testing::bouc_wen_shape(1.25, 0.1, 0.9, 0.02);
  CoupledShear law = coupled(p), untouched = coupled(p);
  for (CoupledShear* each : {&law, &untouched}) {
    push(*each, 2.0 * kZmax, -1.0 * kZmax);
    each->commit();
  }
  push(law, -3.0 * kZmax, 4.0 * kZmax);
  law.revert();
  CoupledShear copy(law);
  const std::array<double, 2> after = push(law, 1.0 * kZmax, 0.5 * kZmax);
  const std::array<double, 2> expected = push(untouched, 1.0 * kZmax, 0.5 * kZmax);
  const std::array<double, 2> copied = push(copy, 1.0 * kZmax, 0.5 * kZmax);
  EXPECT_EQ(after, expected);
  EXPECT_EQ(copied, expected);
}

}  // namespace
}  // namespace pound::links
