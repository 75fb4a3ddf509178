// A block sliding on a rough floor (2-D, a link with Coulomb friction, gravity as a nodal load)
// against the closed form: it decelerates at mu g, stops after v0^2 / (2 mu g) and then sticks.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "io/model_reader.hpp"

namespace pound {
namespace {

constexpr double kMu = 0.5, kGravity = 9.81, kSpeed = 2.0, kMass = 10.0;

// The block sits on the floor (gap 0); the normal law is critically damped so the start-up
// bounce dies within milliseconds.
std::string block_model(double horizontal_load, double speed) {
  return fmt::format(R"({{
    "dimension": 2,
    "nodes": [{{"id": "block", "x": 0, "y": 0}}, {{"id": "floor", "x": 0, "y": 0}}],
    "masses": [{{"node": "block", "mass": {mass}}}],
    "supports": [{{"node": "floor", "fix": ["x", "y"]}}],
    "loads": [{{"node": "block", "x": {push}, "y": {weight}}}],
    "initial_velocities": [{{"node": "block", "x": {speed}}}],
    "links": [{{"id": "contact", "nodes": ["block", "floor"], "axis": [0, -1],
                "law": {{"type": "kelvin_voigt", "stiffness": 1e7, "damping": 2e4}},
                "friction": {{"coefficient": {mu}}}}}],
    "analysis": {{"time_step": 1e-4, "duration": 0.6}}
  }})",
                     fmt::arg("mass", kMass), fmt::arg("push", horizontal_load),
                     fmt::arg("weight", -kMass * kGravity), fmt::arg("speed", speed),
                     fmt::arg("mu", kMu));
}

struct Slide {
  std::vector<double> time, position, velocity, tangential_force;
};

Slide run(const std::string& text) {
  const builder::BuiltModel built = builder::build(io::parse_model(text, "block.json"));
  assembly::StructuralSystem system(built.model);
  auto integrator = builder::make_integrator(built.analysis);
  TransientAnalysis analysis(system, *integrator, builder::make_transient_settings(built.analysis));
  const Index x = system.dofs().equation(built.node_index.at("block"), 0);
  Slide slide;
  State state;
  state.velocity = system.initial_velocity(built.model);
  analysis.run(state, [&](const State& s, const StepResult&) {
    slide.time.push_back(s.time);
    slide.position.push_back(s.displacement[x]);
    slide.velocity.push_back(s.velocity[x]);
    slide.tangential_force.push_back(s.link_force[1]);
  });
  return slide;
}

TEST(FrictionBlock, DeceleratesAtMuGAndStopsWhereTheClosedFormSays) {
  const Slide slide = run(block_model(0.0, kSpeed));
  const double stop_time = kSpeed / (kMu * kGravity), stop_distance = kSpeed * kSpeed / (2 * kMu * kGravity);
  // Deceleration from the velocity between 0.05 s and 0.35 s (after the start-up transient).
  const auto at = [&](double t) { return static_cast<std::size_t>(std::lround(t / 1e-4)); };
  const double deceleration = (slide.velocity[at(0.05)] - slide.velocity[at(0.35)]) / 0.30;
  const double deceleration_error = deceleration / (kMu * kGravity) - 1.0;
  const double distance_error = slide.position.back() / stop_distance - 1.0;
  std::cout << "deceleration error " << deceleration_error << ", stopping distance error "
            << distance_error << ", final velocity " << slide.velocity.back() << "\n";
  EXPECT_LT(std::abs(deceleration_error), 1e-3);
  EXPECT_LT(std::abs(distance_error), 5e-3);
  EXPECT_LT(std::abs(slide.velocity.back()), 1e-3);   // stuck, not creeping
  EXPECT_GT(slide.time.back(), stop_time + 0.1);
  EXPECT_LT(std::abs(slide.tangential_force.back()), 1e-3 * kMu * kMass * kGravity);
}

TEST(FrictionBlock, APushBelowTheFrictionLimitDoesNotMoveTheBlock) {
  const double push = 0.8 * kMu * kMass * kGravity;
  const Slide slide = run(block_model(push, 0.0));
  std::cout << "displacement under a push of 0.8 mu m g: " << slide.position.back() << "\n";
  // Only the elastic stick deflection push / k_t (k_t = the normal law's 1e7).
  EXPECT_NEAR(slide.position.back(), push / 1e7, 1e-6);
  EXPECT_NEAR(slide.tangential_force.back(), push, 1e-3 * push);
}

}  // namespace
}  // namespace pound
