// The block on a moving belt (models/block_on_belt.json): the scene's numbers, the static
// initial state, and the spring-mass motion of the block against the rigid-block closed form.
#include "verification/block_belt.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "io/model_reader.hpp"

namespace pound::verification {
namespace {

builder::ModelSpec belt_model() {
  return io::read_model_file(std::string(POUND_SOURCE_DIR) + "/models/block_on_belt.json");
}

// The bundled belt with its surface a hard contact (restitution 0, the same friction) under
// `integrator` at a fixed step.
builder::ModelSpec hard_belt_model(const std::string& integrator, double time_step) {
  std::ifstream file(std::string(POUND_SOURCE_DIR) + "/models/block_on_belt.json");
  std::stringstream text;
  text << file.rdbuf();
  nlohmann::json model = nlohmann::json::parse(text.str());
  model["surfaces"][0]["law"] = {{"type", "hard_contact"}, {"restitution", 0.0}};
  model["analysis"]["integrator"] = integrator;
  model["analysis"]["time_step"] = time_step;
  return io::parse_model(model.dump(), "hard_belt.json");
}

// The worst elongation error, over Pi, against the rigid block on its spring sliding at mu P:
// 1 + Pi sin(omega t), time in spring periods.
double rigid_block_error(const BlockBeltPoint& point, double speed) {
  double worst = 0.0;
  for (std::size_t k = 0; k < point.time.size(); ++k) {
    const double exact = 1.0 + speed * std::sin(2 * std::numbers::pi * point.time[k]);
    worst = std::max(worst, std::abs(point.elongation[k] - exact) / speed);
  }
  return worst;
}

TEST(BlockBelt, ReadsTheScenesNumbersOffTheModel) {
  const BlockBeltScene scene = block_belt_scene(belt_model());
  EXPECT_NEAR(scene.mass, 7.85e-9 * 40 * 20 * 10, 1e-18);
  EXPECT_NEAR(scene.spring_stiffness, 2451.66, 1e-9);
  EXPECT_NEAR(scene.pressing_force, 0.980665 * 40 * 10, 1e-9);
  EXPECT_EQ(scene.friction_coefficient, 0.1);
  // The springs pull mu P at t = 0 (Suzuki & Toi's initial state).
  EXPECT_NEAR(scene.pretension, 0.1 * scene.pressing_force, 1e-9);
  EXPECT_NEAR(scene.belt_speed(1.0) * std::sqrt(scene.mass * scene.spring_stiffness) /
                  (scene.friction_coefficient * scene.pressing_force),
              1.0, 1e-15);
}

TEST(BlockBelt, AModelWithoutABeltIsRefused) {
  builder::ModelSpec spec = belt_model();
  spec.surfaces.clear();
  EXPECT_THROW(block_belt_scene(spec), InputError);
}

// While the block slides without leaving the belt, friction is mu P and the block is a mass on
// a spring driven by a constant force: from the initial state (spring at mu P, block at the
// belt's speed) the elongation is mu P / k_s (1 + Pi sin(omega t)), omega = sqrt(k_s / m).
// At Pi = 100 and 1000 the oscillation is slow against the block's own waves (the spring
// period is 1 ms, a wave crosses the block in 8 us), so the elastic block must follow it.
TEST(BlockBelt, TheBlockOscillatesOnItsSpringAsARigidBlockWouldAtHighSpeed) {
  BlockBeltOptions options;
  options.periods = 1.0;
  for (double speed : {100.0, 1000.0}) {
    const BlockBeltPoint point = run_block_belt(belt_model(), speed, options);
    ASSERT_GT(point.time.size(), 100u);
    EXPECT_NEAR(point.elongation.front(), 1.0, 1e-3);  // the static initial state
    const double worst = rigid_block_error(point, speed);
    std::cout << fmt::format(
        "Pi = {:g}: elongation against 1 + Pi sin(omega t): worst error "
        "{:.2e} of Pi over one period ({} steps)\n",
        speed, worst, point.steps);
    EXPECT_LT(worst, 0.01);
    EXPECT_NEAR(point.friction_ratio, 1.0, 0.05);
  }
}

// The same with hard contacts under the implicit integrators (Newmark + Newton with the contacts'
// semismooth rows), started from the static state with the contacts held and slipping at mu P:
// before, Newton failed on this scene with penalty friction (41 contacts flipping between stick
// and slip at every step, even at dt = 5e-8).
TEST(BlockBelt, HardContactsUnderImplicitIntegratorsFollowTheRigidBlock) {
  BlockBeltOptions options;
  options.periods = 1.0;
  for (const char* integrator : {"newmark_average_acceleration", "hht", "generalized_alpha"}) {
    for (double speed : {100.0, 1000.0}) {
      const BlockBeltPoint point =
          run_block_belt(hard_belt_model(integrator, 1e-6), speed, options);
      ASSERT_GT(point.time.size(), 100u);
      const double worst = rigid_block_error(point, speed);
      std::cout << fmt::format(
          "{}, hard contacts, Pi = {:g}: start {:.2e} off mu P; elongation against "
          "1 + Pi sin(omega t): worst error {:.2e} of Pi; mu_dyn/mu_st {:.5f}; peak lift {:.1e} "
          "({} steps)\n",
          integrator, speed, point.elongation.front() - 1.0, worst, point.friction_ratio,
          point.peak_lift, point.steps);
      EXPECT_NEAR(point.elongation.front(), 1.0, 1e-9);  // the static state: the springs at mu P
      EXPECT_LT(worst, 0.01);
      EXPECT_NEAR(point.friction_ratio, 1.0, 0.01);
    }
  }
}

// Where the block vibrates (Pi = 0.1, 4 spring periods), Newmark with hard contacts runs to the
// end with its energy watched (the sweep now weighs an implicit step's contact forces as its
// impulses, as `pound run` does: it stopped at Pi = 0.05 on a balance measured with the
// trapezoidal rule) and finds the apparent friction falling as central difference does with the
// same contacts (0.848) and with penalty contacts (0.821, README).
TEST(BlockBelt, HardContactsUnderNewmarkFindTheFrictionFallingWhereTheBlockVibrates) {
  BlockBeltOptions options;
  options.periods = 4.0;
  const BlockBeltPoint point =
      run_block_belt(hard_belt_model("newmark_average_acceleration", 1e-6), 0.1, options);
  std::cout << fmt::format(
      "Newmark, hard contacts, Pi = 0.1: mu_dyn/mu_st {:.4f}, sticking share {:.3f}, lift "
      "{:.3f} ({} steps)\n",
      point.friction_ratio, point.stick_share, point.lift_fraction, point.steps);
  EXPECT_LT(point.friction_ratio, 0.95);
  EXPECT_GT(point.friction_ratio, 0.7);
  EXPECT_GT(point.stick_share, 0.05);
}

// The curve's first half (Suzuki & Toi's Fig. 16): at very low speed the block hardly vibrates
// and the apparent friction is the local mu; at Pi = 0.1 the block vibrates normal to the belt,
// part of its contacts stick while the rest slip, and the spring settles below mu P.
TEST(BlockBelt, ApparentFrictionIsMuAtLowSpeedAndFallsWhereTheBlockVibrates) {
  BlockBeltOptions options;
  options.periods = 2.0;
  const BlockBeltPoint slow = run_block_belt(belt_model(), 0.001, options);
  const BlockBeltPoint faster = run_block_belt(belt_model(), 0.1, options);
  std::cout << fmt::format(
      "Pi = 0.001: mu_dyn/mu_st {:.4f}, lift {:.3f}; Pi = 0.1: {:.4f}, lift "
      "{:.3f}, sticking share {:.3f}\n",
      slow.friction_ratio, slow.lift_fraction, faster.friction_ratio, faster.lift_fraction,
      faster.stick_share);
  EXPECT_GT(slow.friction_ratio, 0.95);
  EXPECT_LT(slow.lift_fraction, 0.01);
  EXPECT_FALSE(slow.tumbling);
  EXPECT_LT(faster.friction_ratio, 0.9);
  EXPECT_GT(faster.lift_fraction, 0.1);
  EXPECT_GT(faster.stick_share, 0.05);
  // Contacts keep switching from stick to slip (at the block's own high frequencies).
  std::cout << fmt::format(
      "stick-to-slip switches per contact per spring period: {:.0f} at "
      "Pi = 0.1\n",
      faster.stick_slip_rate);
  EXPECT_GT(faster.stick_slip_rate, 10.0);
}

}  // namespace
}  // namespace pound::verification
