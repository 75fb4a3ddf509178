// A block sliding on a rough floor (2-D, a link with Coulomb friction, gravity as a nodal load)
// against the closed form: it decelerates at mu g, stops after v0^2 / (2 mu g) and then sticks.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "assembly/static_equilibrium.hpp"
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
  integrators::TransientAnalysis analysis(system, *integrator,
                                          builder::make_transient_settings(built.analysis));
  const Index x = system.dofs().equation(built.node_index.at("block"), 0);
  Slide slide;
  integrators::State state;
  state.velocity = system.initial_velocity(built.model);
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    slide.time.push_back(s.time);
    slide.position.push_back(s.displacement[x]);
    slide.velocity.push_back(s.velocity[x]);
    slide.tangential_force.push_back(s.link_force[1]);
  });
  return slide;
}

TEST(FrictionBlock, DeceleratesAtMuGAndStopsWhereTheClosedFormSays) {
  const Slide slide = run(block_model(0.0, kSpeed));
  const double stop_time = kSpeed / (kMu * kGravity),
               stop_distance = kSpeed * kSpeed / (2 * kMu * kGravity);
  // Deceleration from the velocity between 0.05 s and 0.35 s (after the start-up transient).
  const auto at = [&](double t) { return static_cast<std::size_t>(std::lround(t / 1e-4)); };
  const double deceleration = (slide.velocity[at(0.05)] - slide.velocity[at(0.35)]) / 0.30;
  const double deceleration_error = deceleration / (kMu * kGravity) - 1.0;
  const double distance_error = slide.position.back() / stop_distance - 1.0;
  std::cout << "deceleration error " << deceleration_error << ", stopping distance error "
            << distance_error << ", final velocity " << slide.velocity.back() << "\n";
  EXPECT_LT(std::abs(deceleration_error), 1e-3);
  EXPECT_LT(std::abs(distance_error), 5e-3);
  EXPECT_LT(std::abs(slide.velocity.back()), 1e-3);  // stuck, not creeping
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

// The same closed form for an elastic block of quads (2 x 2 elements, 1 m x 0.5 m, E = 10 MPa)
// sliding on a rigid floor: gravity as nodal loads (the lumped masses times g), the floor a
// surface with the extended penalty and mu = 0.3, the static state under gravity first, then
// the block launched at 2 m/s (central difference at 0.8 of its stable step).
TEST(FrictionBlock, AnElasticBlockOfQuadsDeceleratesAtMuGToo) {
  constexpr double mu = 0.3, g = 9.81, speed = 2.0, mass = 1000.0 * 1.0 * 0.5 * 1.0;
  std::string loads;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) {
      const double share = (i == 1 ? 2.0 : 1.0) * (j == 1 ? 2.0 : 1.0) / 16.0;
      loads += fmt::format("{}{{\"node\": \"b.{}.{}\", \"y\": {}}}", loads.empty() ? "" : ",", i, j,
                           -share * mass * g);
    }
  const std::string text = fmt::format(R"({{
    "dimension": 2,
    "materials": [{{"id": "m", "youngs_modulus": 1e7, "poisson_ratio": 0.25, "density": 1000}}],
    "generators": [{{"type": "block", "id": "b", "width": 1.0, "height": 0.5, "elements": [2, 2],
                    "material": "m", "thickness": 1.0, "initial_velocity": [{}, 0.0]}}],
    "loads": [{}],
    "surfaces": [{{"id": "floor", "point": [0, 0], "normal": [0, 1], "nodes": ["b.bottom"],
                  "law": {{"type": "extended_penalty"}}, "friction": {{"coefficient": {}}}}}],
    "analysis": {{"integrator": "central_difference", "time_step": "auto", "duration": 0.9,
                 "initial_state": "static"}}
  }})",
                                       speed, loads, mu);
  const builder::BuiltModel built = builder::build(io::parse_model(text, "quads.json"));
  assembly::StructuralSystem system(built.model);
  builder::BuiltModel settled = built;
  builder::settle_time_step(settled.analysis, settled.model, system, "quads.json");
  auto integrator = builder::make_integrator(settled.analysis);
  integrators::TransientAnalysis analysis(system, *integrator,
                                          builder::make_transient_settings(settled.analysis));
  const Vector mass_vector = system.mass_matrix().diagonal();
  // Centroid velocity and position along x.
  std::vector<double> time, velocity, position;
  integrators::State state;
  state.velocity = system.initial_velocity(built.model);
  state.displacement = assembly::static_equilibrium(system, 0.0).displacement;
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    double momentum = 0.0, moment = 0.0, total = 0.0;
    for (Index node = 0; node < static_cast<Index>(built.model.nodes.size()); ++node)
      if (const Index x = system.dofs().equation(node, 0); x >= 0) {
        momentum += mass_vector[x] * s.velocity[x];
        moment += mass_vector[x] * s.displacement[x];
        total += mass_vector[x];
      }
    time.push_back(s.time);
    velocity.push_back(momentum / total);
    position.push_back(moment / total);
  });
  const double stop_time = speed / (mu * g), stop_distance = speed * speed / (2 * mu * g);
  // Mean deceleration by a least-squares line through the velocity over [0.1, 0.5] s.
  double st = 0, sv = 0, stt = 0, stv = 0, count = 0;
  for (std::size_t k = 0; k < time.size(); ++k)
    if (time[k] >= 0.1 && time[k] <= 0.5) {
      st += time[k], sv += velocity[k], stt += time[k] * time[k], stv += time[k] * velocity[k];
      ++count;
    }
  const double deceleration = -(count * stv - st * sv) / (count * stt - st * st);
  const double deceleration_error = deceleration / (mu * g) - 1.0;
  const double distance_error = position.back() / stop_distance - 1.0;
  std::cout << fmt::format(
      "quad block: deceleration error {:.2e}, stopping distance error {:.2e}, "
      "final velocity {:.2e} m/s (stops at {:.3f} s)\n",
      deceleration_error, distance_error, velocity.back(), stop_time);
  // The block rocks a little on the penalty contact as it brakes (front nodes loaded more):
  // the mean deceleration is mu g within 0.5 %, the stopping distance within 2 %.
  EXPECT_LT(std::abs(deceleration_error), 0.005);
  EXPECT_LT(std::abs(distance_error), 0.02);
  EXPECT_LT(std::abs(velocity.back()), 0.05 * speed);
}

}  // namespace
}  // namespace pound
