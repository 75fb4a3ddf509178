// Static equilibrium with a contact link against the hand solution: a mass on a spring k = 100,
// pushed by a load towards a wall 0.05 away behind a gap spring of 300, or a hard contact; a
// block on a rough floor (hard contact with friction) pushed sideways; a block on a belt.
#include "assembly/static_equilibrium.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "builder/build.hpp"
#include "core/errors.hpp"
#include "io/model_reader.hpp"
#include "links/hard_contact.hpp"

namespace pound::assembly {
namespace {

StructuralSystem system_under(
    double load, const std::string& law = R"({"type": "gap_spring", "stiffness": 300})") {
  return StructuralSystem(builder::build(io::parse_model(fmt::format(R"({{
    "nodes": [{{"id": "ground", "x": 0}}, {{"id": "m", "x": 1}}, {{"id": "wall", "x": 2}}],
    "materials": [{{"id": "k", "youngs_modulus": 100, "density": 0}}],
    "elements": [{{"id": "k", "type": "truss", "nodes": ["ground", "m"], "material": "k", "area": 1}}],
    "masses": [{{"node": "m", "mass": 1}}],
    "supports": [{{"node": "ground", "fix": ["x"]}}, {{"node": "wall", "fix": ["x"]}}],
    "loads": [{{"node": "m", "x": {}}}],
    "links": [{{"id": "stop", "nodes": ["m", "wall"], "gap": 0.05,
                "law": {}}}],
    "analysis": {{"time_step": 0.001, "duration": 1}}
  }})",
                                                                     load, law),
                                                         "spring.json"))
                              .model);
}

TEST(StaticEquilibrium, ALoadThatClosesTheGapIsCarriedByTheSpringAndTheLink) {
  // 100 u + 300 (u - 0.05) = 10: u = 25 / 400.
  StructuralSystem system = system_under(10.0);
  const StaticEquilibrium solution = static_equilibrium(system, 0.0);
  ASSERT_EQ(solution.displacement.size(), 1);
  EXPECT_NEAR(solution.displacement[0], 25.0 / 400.0, 1e-12);
  EXPECT_GE(solution.iterations, 1);
  EXPECT_LT(solution.unbalanced_force, 1e-9);
  EXPECT_TRUE(system.links().law(0).in_contact());  // the state at the solution is committed
}

TEST(StaticEquilibrium, ALoadThatLeavesTheGapOpenIsCarriedByTheSpringAlone) {
  StructuralSystem system = system_under(2.0);
  const StaticEquilibrium solution = static_equilibrium(system, 0.0);
  EXPECT_NEAR(solution.displacement[0], 0.02, 1e-14);
  EXPECT_FALSE(system.links().law(0).in_contact());
}

// The hard contact's force, as the static solve left it (committed).
double hard_force(StructuralSystem& system, Index link) {
  return system.links().hard_contact(link)->set_trial({}).force;
}

// A hard contact's rows' forces as imposed (its friction's on the row after the normal one).
Vector imposed_forces(StructuralSystem& system) {
  integrators::LinkSet& links = system.links();
  const Vector zero = Vector::Zero(links.size());
  Vector force;
  Matrix tangent;
  links.set_trial(zero, zero, zero, 0.0, 0.0, force, tangent);
  return force;
}

constexpr const char* kHardContact = R"({"type": "hard_contact", "restitution": 0})";

// A hard contact is a constraint in the static solve: the mass stops at the wall (u = 0.05
// exactly) and the contact carries the rest of the load, 10 - 100 x 0.05 = 5.
TEST(StaticEquilibrium, AHardContactStopsTheMassAtTheWallAndCarriesTheRestOfTheLoad) {
  StructuralSystem system = system_under(10.0, kHardContact);
  const StaticEquilibrium solution = static_equilibrium(system, 0.0);
  const double force = hard_force(system, 0);
  std::cout << fmt::format(
      "hard contact at the wall: u - 0.05 = {:.1e}, force - 5 = {:.1e} ({} "
      "iterations)\n",
      solution.displacement[0] - 0.05, force - 5.0, solution.iterations);
  EXPECT_NEAR(solution.displacement[0], 0.05, 1e-15);
  EXPECT_NEAR(force, 5.0, 1e-12);
  EXPECT_TRUE(system.links().law(0).in_contact());
  EXPECT_LT(solution.unbalanced_force, 1e-9);

  StructuralSystem short_of_it = system_under(2.0, kHardContact);
  EXPECT_NEAR(static_equilibrium(short_of_it, 0.0).displacement[0], 0.02, 1e-15);
  EXPECT_FALSE(short_of_it.links().law(0).in_contact());
  EXPECT_EQ(hard_force(short_of_it, 0), 0.0);
}

// A 10 kg block (weight 98.1) on a floor through a hard contact with mu = 0.5, pushed sideways
// by P: below mu W it sticks where it stands, friction carrying P; above, nothing holds it.
StructuralSystem block_on_floor(double push, const std::string& belt_velocity = "") {
  const std::string floor =
      belt_velocity.empty()
          ? R"("links": [{"id": "floor", "nodes": ["block", "ground"], "axis": [0, -1],
                          "law": {"type": "hard_contact", "restitution": 0},
                          "friction": {"coefficient": 0.5}}],)"
          : fmt::format(R"("surfaces": [{{"id": "belt", "point": [0, 0], "normal": [0, 1],
                            "velocity": [{}, 0], "nodes": ["block"],
                            "law": {{"type": "hard_contact", "restitution": 0}},
                            "friction": {{"coefficient": 0.5}}}}],
                           "links": [{{"id": "spring", "nodes": ["anchor", "block"],
                                      "axis": [1, 0],
                                      "law": {{"type": "elastic_spring", "stiffness": 1000}}}}],)",
                        belt_velocity);
  return StructuralSystem(builder::build(io::parse_model(fmt::format(R"({{
    "dimension": 2,
    "nodes": [{{"id": "block", "x": 0, "y": 0}}, {{"id": "ground", "x": 0, "y": 0}},
              {{"id": "anchor", "x": -1, "y": 0}}],
    "masses": [{{"node": "block", "mass": 10}}],
    "supports": [{{"node": "ground", "fix": ["x", "y"]}}, {{"node": "anchor", "fix": ["x", "y"]}}],
    "loads": [{{"node": "block", "x": {}, "y": -98.1}}],
    {}
    "analysis": {{"time_step": 0.001, "duration": 1}}
  }})",
                                                                     push, floor),
                                                         "block.json"))
                              .model);
}

TEST(StaticEquilibrium, ABlockOnARoughFloorSticksBelowMuWAndIsAMechanismAbove) {
  StructuralSystem system = block_on_floor(30.0);
  const StaticEquilibrium solution = static_equilibrium(system, 0.0);
  const double normal = hard_force(system, 0);
  const double tangential = imposed_forces(system)[1];
  std::cout << fmt::format(
      "block pushed by 30 < mu W = 49.05: moved {:.1e}, normal force - W = "
      "{:.1e}, friction - P = {:.1e}\n",
      solution.displacement.cwiseAbs().maxCoeff(), normal - 98.1, std::abs(tangential) - 30.0);
  EXPECT_LT(solution.displacement.cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(normal, 98.1, 1e-12);
  EXPECT_NEAR(std::abs(tangential), 30.0, 1e-12);

  StructuralSystem pushed_off = block_on_floor(60.0);
  try {
    static_equilibrium(pushed_off, 0.0);
    ADD_FAILURE() << "a block pushed past mu W found a static state";
  } catch (const SolveError& error) {
    std::cout << "pushed by 60 > mu W: " << error.what() << "\n";
    EXPECT_NE(std::string(error.what()).find("mechanism"), std::string::npos);
  }
}

// On a belt moving at +1 m/s the block slips at mu W = 49.05 in the belt's direction, held by
// its spring (k = 1000): u_x = 0.04905 exactly, as the penalty friction gives it.
TEST(StaticEquilibrium, ABlockOnABeltSlipsAtMuWInTheBeltsDirection) {
  for (const char* velocity : {"1", "-1"}) {
    StructuralSystem system = block_on_floor(0.0, velocity);
    const StaticEquilibrium solution = static_equilibrium(system, 0.0);
    const double sign = velocity[0] == '-' ? -1.0 : 1.0;
    const Index x = system.dofs().equation(0, 0), y = system.dofs().equation(0, 1);
    std::cout << fmt::format("block on a belt at {} m/s: u_x - mu W / k = {:.1e}, u_y = {:.1e}\n",
                             velocity, solution.displacement[x] - sign * 0.04905,
                             solution.displacement[y]);
    EXPECT_NEAR(solution.displacement[x], sign * 0.04905, 1e-15);
    EXPECT_NEAR(solution.displacement[y], 0.0, 1e-15);
    for (Index k = 0; k < system.links().count(); ++k)
      if (system.links().has_friction(k)) {
        EXPECT_TRUE(system.links().friction(k)->slipping());
      }
  }
}

}  // namespace
}  // namespace pound::assembly
