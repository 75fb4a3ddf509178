// A cable restrainer catching a girder that moves away from the abutment, against the closed
// forms of an elastic and of an elastic-perfectly-plastic catch.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "io/model_reader.hpp"

namespace pound {
namespace {

constexpr double kMass = 2.0e5, kSpeed = 0.4, kStiffness = 5.0e7, kSlack = 0.02;

// Returns the largest opening of the joint (girder moving away from the fixed abutment).
double largest_opening(const std::string& law) {
  const std::string text = fmt::format(R"({{
    "nodes": [{{"id": "girder", "x": 0}}, {{"id": "abutment", "x": 0}}],
    "masses": [{{"node": "girder", "mass": {}}}],
    "supports": [{{"node": "abutment", "fix": ["x"]}}],
    "initial_velocities": [{{"node": "girder", "x": {}}}],
    "links": [{{"id": "cable", "nodes": ["girder", "abutment"], "axis": [-1], "law": {}}}],
    "analysis": {{"time_step": 1e-5, "duration": 0.5}},
    "recorders": []
  }})",
                                       kMass, kSpeed, law);
  const builder::BuiltModel built = builder::build(io::parse_model(text, "cable.json"));
  assembly::StructuralSystem system(built.model);
  auto integrator = builder::make_integrator(built.analysis);
  integrators::TransientAnalysis analysis(system, *integrator,
                                          builder::make_transient_settings(built.analysis));
  integrators::State state;
  state.velocity = system.initial_velocity(built.model);
  double opening = 0.0;
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    opening = std::max(opening, -s.link_penetration[0]);
  });
  return opening;
}

TEST(Restrainer, ElasticCableStretchesByVSqrtMOverK) {
  const double opening = largest_opening(
      fmt::format(R"({{"type": "restrainer", "stiffness": {}, "slack": {}}})", kStiffness, kSlack));
  const double expected = kSlack + kSpeed * std::sqrt(kMass / kStiffness);
  std::cout << "opening " << opening << ", closed form " << expected << "\n";
  EXPECT_NEAR(opening / expected, 1.0, 1e-4);
}

TEST(Restrainer, YieldingCableAbsorbsTheKineticEnergyPlastically) {
  const double yield = 1.0e6;  // below the elastic peak k v sqrt(m/k) = 1.26e6
  const double opening = largest_opening(
      fmt::format(R"({{"type": "restrainer", "stiffness": {}, "slack": {}, "yield_force": {}}})",
                  kStiffness, kSlack, yield));
  // 1/2 m v^2 = 1/2 T_y^2 / k + T_y x_p
  const double energy = 0.5 * kMass * kSpeed * kSpeed;
  const double plastic = (energy - 0.5 * yield * yield / kStiffness) / yield;
  const double expected = kSlack + yield / kStiffness + plastic;
  std::cout << "opening " << opening << ", closed form " << expected << "\n";
  EXPECT_NEAR(opening / expected, 1.0, 1e-4);
}

}  // namespace
}  // namespace pound
