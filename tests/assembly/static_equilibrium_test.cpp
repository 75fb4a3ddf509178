// Static equilibrium with a contact link against the hand solution: a mass on a spring k = 100,
// pushed by a load towards a wall 0.05 away behind a gap spring of 300.
#include "assembly/static_equilibrium.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "builder/build.hpp"
#include "io/model_reader.hpp"

namespace pound::assembly {
namespace {

StructuralSystem system_under(double load) {
  return StructuralSystem(builder::build(io::parse_model(fmt::format(R"({{
    "nodes": [{{"id": "ground", "x": 0}}, {{"id": "m", "x": 1}}, {{"id": "wall", "x": 2}}],
    "materials": [{{"id": "k", "youngs_modulus": 100, "density": 0}}],
    "elements": [{{"id": "k", "type": "truss", "nodes": ["ground", "m"], "material": "k", "area": 1}}],
    "masses": [{{"node": "m", "mass": 1}}],
    "supports": [{{"node": "ground", "fix": ["x"]}}, {{"node": "wall", "fix": ["x"]}}],
    "loads": [{{"node": "m", "x": {}}}],
    "links": [{{"id": "stop", "nodes": ["m", "wall"], "gap": 0.05,
                "law": {{"type": "gap_spring", "stiffness": 300}}}}],
    "analysis": {{"time_step": 0.001, "duration": 1}}
  }})",
                                                                     load),
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

}  // namespace
}  // namespace pound::assembly
