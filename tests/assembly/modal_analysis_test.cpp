// Modes of small spring-mass chains against their closed forms: eigenvalues, mass-normalised
// shapes, links at their initial tangent, rigid-body modes left out of the periods; and the
// Lanczos path of larger models against the dense one.
#include "assembly/modal_analysis.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <stdexcept>

#include "assembly/not_positive_definite.hpp"
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

// Fewer modes than asked come with the reason: the DOFs with mass, the rigid-body modes left out,
// or the caps past 4,000 DOFs.
TEST(ModalAnalysis, FewerModesThanAskedSayWhy) {
  EXPECT_EQ(fewer_modes_reason(2, 2, 2, 2), "");
  EXPECT_EQ(fewer_modes_reason(2, 2, 12, 2), "the model has 2 DOFs with mass, hence 2 modes");
  EXPECT_EQ(fewer_modes_reason(3, 1, 12, 1), "the model has 1 DOF with mass, hence 1 mode");
  EXPECT_EQ(fewer_modes_reason(4, 4, 5, 3),
            "1 of the model's 4 modes (one per DOF with mass) stores no strain energy (a part "
            "free to move as a whole, or a mechanism) and is not listed");
  EXPECT_EQ(fewer_modes_reason(310, 310, 400, 270),
            "40 of the model's 310 modes (one per DOF with mass) store no strain energy (a part "
            "free to move as a whole, or a mechanism) and are not listed");
  EXPECT_EQ(fewer_modes_reason(6000, 6000, 800, 500),
            "past 4000 DOFs at most the first 500 modes are found");
  EXPECT_EQ(fewer_modes_reason(6000, 6000, 400, 300),
            "past 4000 DOFs the search stops at 2000 modes, and the others among them are "
            "rigid-body or mechanism modes (no strain energy), which are not listed");
  // Up to 4,000 DOFs every mode is found: a model of 3,000 DOFs lists all of its vibration modes.
  EXPECT_EQ(fewer_modes_reason(3000, 3000, 800, 500),
            "2500 of the model's 3000 modes (one per DOF with mass) store no strain energy (a "
            "part free to move as a whole, or a mechanism) and are not listed");
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

// --- Past 300 DOFs vibration_modes takes shift-invert Lanczos (Spectra) on the sparse matrices.

// A plane steel frame of `bays` x `storeys` bays of 4 m by 3 m storeys, fixed at its base (3 DOFs
// a node: with lumped masses its rotations are massless, with consistent ones every DOF has
// mass).
std::string frame(int bays, int storeys, const std::string& mass) {
  std::string nodes, members;
  const auto add_member = [&](const std::string& a, const std::string& b) {
    members += fmt::format(
        "{}{{\"id\": \"{}-{}\", \"type\": \"beam\", \"nodes\": [\"{}\", \"{}\"], \"material\": "
        "\"steel\", \"area\": 0.01, \"inertia\": 1e-4, \"mass\": \"{}\"}}",
        members.empty() ? "" : ", ", a, b, a, b, mass);
  };
  std::string supports;
  for (int j = 0; j <= storeys; ++j)
    for (int i = 0; i <= bays; ++i) {
      const std::string id = fmt::format("n{}_{}", i, j);
      nodes += fmt::format("{}{{\"id\": \"{}\", \"x\": {}, \"y\": {}}}", nodes.empty() ? "" : ", ",
                           id, 4 * i, 3 * j);
      if (j == 0)
        supports += fmt::format("{}{{\"node\": \"{}\", \"fix\": [\"x\", \"y\", \"rz\"]}}",
                                supports.empty() ? "" : ", ", id);
      else
        add_member(fmt::format("n{}_{}", i, j - 1), id);
      if (j > 0 && i > 0) add_member(fmt::format("n{}_{}", i - 1, j), id);
    }
  return fmt::format(R"({{"dimension": 2, "nodes": [{}],
    "materials": [{{"id": "steel", "youngs_modulus": 2e11, "density": 7850}}],
    "elements": [{}], "supports": [{}], "analysis": {{"time_step": 0.001, "duration": 1}}}})",
                     nodes, members, supports);
}

// The first `count` vibration modes against the dense solve: the largest relative difference of
// w^2, and checks of the Lanczos shapes (mass-orthonormal, K phi = w^2 M phi, and where a mode is
// apart from its neighbours the dense shape up to its sign).
void compare_with_dense(const StructuralSystem& system, int count, const std::string& name) {
  const Modes lanczos = vibration_modes(system, count);
  const Modes dense = modal_analysis(system);
  ASSERT_EQ(lanczos.omega_squared.size(), count) << name;
  const Matrix mass = Matrix(system.mass_matrix());
  const Eigen::SparseMatrix<double>& stiffness = system.stiffness();
  double worst = 0.0, worst_residual = 0.0, worst_shape = 0.0;
  for (Index k = 0; k < count; ++k) {
    const double exact = dense.omega_squared[k];
    worst = std::max(worst, std::abs(lanczos.omega_squared[k] / exact - 1.0));
    const Vector shape = lanczos.shapes.col(k);
    const Vector force = stiffness * shape;
    worst_residual = std::max(
        worst_residual, (force - lanczos.omega_squared[k] * mass * shape).norm() / force.norm());
    const bool apart = (k == 0 || dense.omega_squared[k - 1] < 0.999 * exact) &&
                       dense.omega_squared[k + 1] > 1.001 * exact;
    if (apart)  // 1 - |cos| of the angle between the two shapes in M's inner product
      worst_shape =
          std::max(worst_shape, std::abs(std::abs(shape.dot(mass * dense.shapes.col(k))) - 1.0));
  }
  const double orthonormal_error =
      (lanczos.shapes.transpose() * mass * lanczos.shapes - Matrix::Identity(count, count))
          .cwiseAbs()
          .maxCoeff();
  std::cout << name << ": " << system.size() << " DOFs, w^2 against the dense solve " << worst
            << ", residual |K phi - w^2 M phi| / |K phi| " << worst_residual
            << ", 1 - |cos| against the dense shape " << worst_shape << ", |Phi^T M Phi - I| "
            << orthonormal_error << "\n";
  EXPECT_LT(worst, 1e-10) << name;
  EXPECT_LT(worst_residual, 1e-8) << name;
  EXPECT_LT(worst_shape, 1e-12) << name;
  EXPECT_LT(orthonormal_error, 1e-10) << name;
}

// 12 bays by 10 storeys: 390 DOFs, the largest w^2 about 1e6 times the first (so both solves are
// good to about 1e-10 of w^2). With lumped masses the 130 rotations are massless (a mass of
// 1e-12 of the largest in the Lanczos pencil, recovered statically; condensed in the dense
// one).
TEST(ModalAnalysis, LanczosGivesTheDenseModesOfALargeFrame) {
  for (const std::string mass : {"lumped", "consistent"}) {
    const StructuralSystem system = system_of(frame(12, 10, mass));
    ASSERT_GT(system.size(), 300);
    compare_with_dense(system, 10, "frame, " + mass + " masses");
  }
}

// 310 masses on a line, the first 270 in a chain of springs from the ground and 40 free: 40
// rigid-body modes come out of the Lanczos solve first, so it asks for more until the chain's
// modes are found.
TEST(ModalAnalysis, LanczosLooksPastRigidBodyModes) {
  constexpr int kChain = 270;
  std::string nodes = R"({"id": "ground", "x": 0})", elements, masses;
  for (int i = 1; i <= 310; ++i) {
    nodes += fmt::format(R"(, {{"id": "m{}", "x": {}}})", i, i);
    masses += fmt::format(R"({}{{"node": "m{}", "mass": 1}})", i > 1 ? ", " : "", i);
    if (i <= kChain)
      elements += fmt::format(
          R"({}{{"id": "k{}", "type": "truss", "nodes": ["{}", "m{}"], "material": "k", "area": 1}})",
          i > 1 ? ", " : "", i, i == 1 ? std::string("ground") : fmt::format("m{}", i - 1), i);
  }
  const StructuralSystem system = system_of(fmt::format(R"({{"dimension": 1, "nodes": [{}],
    "materials": [{{"id": "k", "youngs_modulus": 100, "density": 0}}], "elements": [{}],
    "masses": [{}], "supports": [{{"node": "ground", "fix": ["x"]}}],
    "analysis": {{"time_step": 0.001, "duration": 1}}}})",
                                                        nodes, elements, masses));
  // A fixed-free chain of N equal springs k and masses m: w_j = 2 sqrt(k/m) sin((2j-1) pi /
  // (2 (2N + 1))).
  const std::vector<double> periods = natural_periods(system, 3);
  ASSERT_EQ(periods.size(), 3u);
  for (int j = 1; j <= 3; ++j) {
    const double exact =
        2.0 * std::numbers::pi /
        (2.0 * 10.0 * std::sin((2 * j - 1) * std::numbers::pi / (2.0 * (2 * kChain + 1))));
    std::cout << "mode " << j << ": period " << periods[j - 1] << ", relative error "
              << periods[j - 1] / exact - 1.0 << "\n";
    EXPECT_NEAR(periods[j - 1] / exact, 1.0, 1e-9) << "mode " << j;
  }
  // Asking for more modes than the chain has gives all of its 270 (the free masses have none).
  EXPECT_EQ(vibration_modes(system, 400).omega_squared.size(), kChain);
}

// Two massless pads tied to each other vertically and to nothing else that holds them
// vertically: K_00 is singular though no diagonal is 0. The Lanczos path refuses it as the dense
// condensation does, naming one of the two DOFs.
TEST(ModalAnalysis, LanczosRefusesAMasslessMechanism) {
  std::string nodes = R"({"id": "ground", "x": 0, "y": 0})", elements, masses, supports;
  for (int i = 1; i <= 320; ++i) {
    nodes += fmt::format(R"(, {{"id": "m{}", "x": {}, "y": 0}})", i, i);
    masses += fmt::format(R"({}{{"node": "m{}", "mass": 1}})", i > 1 ? ", " : "", i);
    supports += fmt::format(R"(, {{"node": "m{}", "fix": ["y"]}})", i);
    elements += fmt::format(
        R"({}{{"id": "k{}", "type": "truss", "nodes": ["{}", "m{}"], "material": "k", "area": 1}})",
        i > 1 ? ", " : "", i, i == 1 ? std::string("ground") : fmt::format("m{}", i - 1), i);
  }
  nodes += R"(, {"id": "pad", "x": 321, "y": 0}, {"id": "top", "x": 321, "y": 1})";
  elements +=
      R"(, {"id": "arm", "type": "truss", "nodes": ["m320", "pad"], "material": "k", "area": 1},
      {"id": "post", "type": "truss", "nodes": ["pad", "top"], "material": "k", "area": 1})";
  supports += R"(, {"node": "top", "fix": ["x"]})";
  const StructuralSystem system = system_of(fmt::format(R"({{"dimension": 2, "nodes": [{}],
    "materials": [{{"id": "k", "youngs_modulus": 100, "density": 0}}], "elements": [{}],
    "masses": [{}], "supports": [{{"node": "ground", "fix": ["x", "y"]}}{}],
    "analysis": {{"time_step": 0.001, "duration": 1}}}})",
                                                        nodes, elements, masses, supports));
  ASSERT_GT(system.size(), 300);
  EXPECT_THROW(modal_analysis(system), NotPositiveDefinite);
  try {
    vibration_modes(system, 3);
    ADD_FAILURE() << "a massless mechanism gave modes";
  } catch (const NotPositiveDefinite& error) {
    const Index pad = system.dofs().own_equation(321, 1), top = system.dofs().own_equation(322, 1);
    EXPECT_TRUE(error.equation() == pad || error.equation() == top) << error.what();
  }
}

}  // namespace
}  // namespace pound::assembly
