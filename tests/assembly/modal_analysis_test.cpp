// Modes of small spring-mass chains against their closed forms: eigenvalues, mass-normalised
// shapes, links at their initial tangent, rigid-body modes left out of the periods.
#include "assembly/modal_analysis.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "builder/build.hpp"
#include "io/model_reader.hpp"

namespace pound::assembly {
namespace {

// ground (fixed) -k1- m1 -k2- m2, k = 100 (trusses of E A / L = 100), unit masses, plus `links`
// from m2 to a fixed wall.
std::string chain(const std::string& links) {
  return fmt::format(R"({{
    "nodes": [{{"id": "ground", "x": 0}}, {{"id": "m1", "x": 1}}, {{"id": "m2", "x": 2}},
              {{"id": "wall", "x": 3}}],
    "materials": [{{"id": "k", "youngs_modulus": 100, "density": 0}}],
    "elements": [{{"id": "k1", "type": "truss", "nodes": ["ground", "m1"], "material": "k", "area": 1}},
                 {{"id": "k2", "type": "truss", "nodes": ["m1", "m2"], "material": "k", "area": 1}}],
    "masses": [{{"node": "m1", "mass": 1}}, {{"node": "m2", "mass": 1}}],
    "supports": [{{"node": "ground", "fix": ["x"]}}, {{"node": "wall", "fix": ["x"]}}],
    "links": [{}],
    "analysis": {{"time_step": 0.001, "duration": 1}}
  }})",
                     links);
}

StructuralSystem system_of(const std::string& text) {
  return StructuralSystem(builder::build(io::parse_model(text, "chain.json")).model);
}

TEST(ModalAnalysis, TwoMassChainHasItsClosedFormEigenvaluesAndNormalisedShapes) {
  // K = 100 [[2, -1], [-1, 1]], M = I: w^2 = 100 (3 -/+ sqrt 5) / 2. An open contact link adds
  // nothing.
  const StructuralSystem system = system_of(chain(
      R"({"id": "stop", "nodes": ["m2", "wall"], "gap": 0.1, "law": {"type": "gap_spring", "stiffness": 1e6}})"));
  const Modes modes = modal_analysis(system);
  ASSERT_EQ(modes.omega_squared.size(), 2);
  EXPECT_NEAR(modes.omega_squared[0], 50.0 * (3.0 - std::sqrt(5.0)), 1e-10);
  EXPECT_NEAR(modes.omega_squared[1], 50.0 * (3.0 + std::sqrt(5.0)), 1e-10);
  const Matrix mass = Matrix(system.mass_matrix());
  const Matrix orthonormality = modes.shapes.transpose() * mass * modes.shapes;
  EXPECT_TRUE(orthonormality.isIdentity(1e-12)) << orthonormality;
  const Matrix stiffness = Matrix(system.stiffness());
  for (Index k = 0; k < 2; ++k) {
    const Vector residual =
        stiffness * modes.shapes.col(k) - modes.omega_squared[k] * mass * modes.shapes.col(k);
    EXPECT_LT(residual.norm(), 1e-10) << "mode " << k;
  }
  const std::vector<double> periods = natural_periods(system, 2);
  ASSERT_EQ(periods.size(), 2u);
  EXPECT_NEAR(periods[0], 2 * std::numbers::pi / std::sqrt(50.0 * (3.0 - std::sqrt(5.0))), 1e-12);
}

TEST(ModalAnalysis, AStructuralSpringLinkCountsAtItsStiffness) {
  // An elastic spring of 50 from m2 to the wall: K = [[200, -100], [-100, 150]],
  // w^2 = (350 -/+ sqrt(50^2 + 4 100^2)) / 2.
  const StructuralSystem system = system_of(chain(
      R"({"id": "bearing", "nodes": ["m2", "wall"], "law": {"type": "elastic_spring", "stiffness": 50}})"));
  const Modes modes = modal_analysis(system);
  const double root = std::sqrt(50.0 * 50.0 + 4.0 * 100.0 * 100.0);
  EXPECT_NEAR(modes.omega_squared[0], (350.0 - root) / 2.0, 1e-10);
  EXPECT_NEAR(modes.omega_squared[1], (350.0 + root) / 2.0, 1e-10);
}

TEST(ModalAnalysis, PeriodsLeaveRigidBodyModesOut) {
  // Two unit masses joined by k = 100, nothing holding them: w^2 = 0 and 200.
  const StructuralSystem system = system_of(R"({
    "nodes": [{"id": "a", "x": 0}, {"id": "b", "x": 1}],
    "materials": [{"id": "k", "youngs_modulus": 100, "density": 0}],
    "elements": [{"id": "k", "type": "truss", "nodes": ["a", "b"], "material": "k", "area": 1}],
    "masses": [{"node": "a", "mass": 1}, {"node": "b", "mass": 1}],
    "analysis": {"time_step": 0.001, "duration": 1}
  })");
  const Modes modes = modal_analysis(system);
  EXPECT_NEAR(modes.omega_squared[0], 0.0, 1e-10);
  EXPECT_NEAR(modes.omega_squared[1], 200.0, 1e-10);
  const std::vector<double> periods = natural_periods(system, 2);
  ASSERT_EQ(periods.size(), 1u);
  EXPECT_NEAR(periods[0], 2 * std::numbers::pi / std::sqrt(200.0), 1e-12);
}

TEST(ModalAnalysis, RefusesMoreDofsThanTheDenseSolveIsFor) {
  const StructuralSystem system = system_of(chain(""));
  EXPECT_THROW(modal_analysis(system, 1), std::length_error);
}

// A spring of 1e300 on a unit mass: w^2 = 1e300 is no structure's, and the dense solver's
// squares of it overflow (it iterated a minute before failing: a mutation test's "hang"). Refused
// at once, with the spring counted in the diagonal that names the DOF.
TEST(ModalAnalysis, AnOverflowingStiffnessToMassRatioIsRefusedAtOnce) {
  const StructuralSystem system = system_of(chain(
      R"({"id": "bearing", "nodes": ["m2", "wall"], "law": {"type": "elastic_spring", "stiffness": 1e300}})"));
  try {
    modal_analysis(system);
    ADD_FAILURE() << "w^2 = 1e300 gave modes";
  } catch (const ModalAnalysisError& error) {
    EXPECT_NE(std::string(error.what()).find("overflows the number range"), std::string::npos)
        << error.what();
  }
  const Vector diagonal = stiffness_diagonal_with_links(system);
  EXPECT_EQ(diagonal[1], 100.0 + 1e300);
  EXPECT_EQ(diagonal[0], 200.0);
}

}  // namespace
}  // namespace pound::assembly
