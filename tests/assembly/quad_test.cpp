// The four-node quadrilateral (assembly/quad): rigid-body modes, the patch test on a
// distorted mesh (displacement and force forms), the mass, and plane stress against plane strain.
#include "assembly/quad.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <iostream>

#include "assembly/static_equilibrium.hpp"
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "io/model_reader.hpp"

namespace pound::assembly {
namespace {

constexpr double kE = 210000.0, kNu = 0.3, kThickness = 2.0, kDensity = 7.8e-9;

const QuadCorners kDistorted{{{0.0, 0.0}, {2.2, 0.3}, {1.9, 1.7}, {-0.2, 1.2}}};

Quad steel(const QuadCorners& corners = kDistorted, bool plane_strain = false,
           bool consistent_mass = false) {
  std::array<model::ElementNode, 4> nodes;
  for (std::size_t a = 0; a < 4; ++a) nodes[a] = {static_cast<Index>(a), corners[a]};
  return Quad("q", nodes,
              {.youngs_modulus = kE,
               .poisson_ratio = kNu,
               .thickness = kThickness,
               .density = kDensity,
               .plane_strain = plane_strain},
              consistent_mass, std::nullopt);
}

TEST(Quad, HasExactlyThreeRigidBodyModes) {
  const Matrix k = steel().stiffness();
  EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
  const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Matrix>(k).eigenvalues();
  const double largest = eigenvalues.maxCoeff();
  int zero = 0;
  for (int i = 0; i < 8; ++i) zero += std::abs(eigenvalues[i]) < 1e-12 * largest;
  EXPECT_EQ(zero, 3);
  EXPECT_GT(eigenvalues[3], 1e-6 * largest);  // no spurious zero-energy (hourglass) mode
  // Translations and the rotation (u = -theta y, v = theta x) carry no force.
  Vector rotation(8);
  for (int a = 0; a < 4; ++a) {
    rotation[2 * a] = -kDistorted[a][1];
    rotation[2 * a + 1] = kDistorted[a][0];
  }
  const double error = (k * rotation).norm() / (k.norm() * rotation.norm());
  std::cout << fmt::format("rotation force / (|K| |u|) = {:.2e}\n", error);
  EXPECT_LT(error, 1e-14);
}

TEST(Quad, MassSumsToTheElementsMassAndLumpsAQuarterOnAParallelogram) {
  const QuadCorners parallelogram{{{0.0, 0.0}, {2.0, 0.0}, {2.5, 1.0}, {0.5, 1.0}}};
  const Matrix8 m = steel(parallelogram).consistent_mass();
  const double total = kDensity * kThickness * quad_area(parallelogram);  // area 2
  EXPECT_NEAR(quad_area(parallelogram), 2.0, 1e-15);
  double sum_x = 0.0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) sum_x += m(2 * a, 2 * b);
  EXPECT_NEAR(sum_x, total, 1e-14 * total);
  for (int a = 0; a < 8; ++a) EXPECT_NEAR(m.row(a).sum(), total / 4, 1e-14 * total);
  // Consistent mass of the bilinear element: (rho t A / 36) (4, 2, 1, 2) on a parallelogram.
  EXPECT_NEAR(m(0, 0), total * 4 / 36, 1e-14 * total);
  EXPECT_NEAR(m(0, 2), total * 2 / 36, 1e-14 * total);
  EXPECT_NEAR(m(0, 4), total * 1 / 36, 1e-14 * total);
}

TEST(Quad, LumpsTheRowSumsOrKeepsTheConsistentMassAndReportsNoEndForces) {
  const Matrix8 consistent = steel().consistent_mass();
  const model::ElementMass lumped = steel().mass();
  ASSERT_FALSE(lumped.is_consistent());
  EXPECT_EQ(lumped.lumped, Vector(consistent.rowwise().sum()));
  const model::ElementMass kept = steel(kDistorted, false, true).mass();
  ASSERT_TRUE(kept.is_consistent());
  EXPECT_EQ(kept.consistent, Matrix(consistent));
  EXPECT_TRUE(steel().end_force_names().empty());
  EXPECT_EQ(steel().end_forces(Vector::Ones(8)).size(), 0);
}

TEST(Quad, PlaneStrainIsStifferThanPlaneStressByTheClosedForm) {
  const Eigen::Matrix3d stress = steel(kDistorted, false).elasticity();
  const Eigen::Matrix3d strain = steel(kDistorted, true).elasticity();
  EXPECT_NEAR(stress(0, 0), kE / (1 - kNu * kNu), 1e-9);
  EXPECT_NEAR(strain(0, 0), kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu)), 1e-9);
  EXPECT_NEAR(stress(2, 2), strain(2, 2), 1e-9);  // the shear modulus G in both
  EXPECT_NEAR(stress(2, 2), kE / (2 * (1 + kNu)), 1e-9);
}

// A 2 x 2 patch of distorted quads on [0, 4] x [0, 3] (interior node moved off centre, edge
// midpoints moved along their edges), pulled by a uniform traction sigma on x = 4, held at
// x = 0 by rollers and at one corner in y.
std::string patch_model(double sigma, bool plane_strain) {
  const double x[3][3] = {{0.0, 0.0, 0.0}, {1.7, 2.3, 2.1}, {4.0, 4.0, 4.0}};
  const double y[3][3] = {{0.0, 1.3, 3.0}, {0.0, 1.8, 3.0}, {0.0, 1.6, 3.0}};
  std::string nodes, elements;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      nodes += fmt::format("{}{{\"id\": \"n{}{}\", \"x\": {}, \"y\": {}}}",
                           nodes.empty() ? "" : ",", i, j, x[i][j], y[i][j]);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      elements += fmt::format(
          "{}{{\"id\": \"e{}{}\", \"type\": \"quad\", \"nodes\": [\"n{}{}\", \"n{}{}\", \"n{}{}\", "
          "\"n{}{}\"], \"material\": \"m\", \"thickness\": {}, \"plane\": \"{}\"}}",
          elements.empty() ? "" : ",", i, j, i, j, i + 1, j, i + 1, j + 1, i, j + 1, kThickness,
          plane_strain ? "strain" : "stress");
  // Consistent loads of a uniform traction on x = 4: sigma t h / 2 on each end of each side.
  const double lower = 1.6, upper = 3.0 - 1.6;
  return fmt::format(R"({{
    "dimension": 2, "nodes": [{}],
    "materials": [{{"id": "m", "youngs_modulus": {}, "poisson_ratio": {}, "density": {}}}],
    "elements": [{}],
    "supports": [{{"node": "n00", "fix": ["x", "y"]}}, {{"node": "n01", "fix": ["x"]}},
                 {{"node": "n02", "fix": ["x"]}}],
    "loads": [{{"node": "n20", "x": {}}}, {{"node": "n21", "x": {}}}, {{"node": "n22", "x": {}}}],
    "analysis": {{"time_step": 1e-6, "duration": 1e-6}}
  }})",
                     nodes, kE, kNu, kDensity, elements, sigma * kThickness * lower / 2,
                     sigma * kThickness * (lower + upper) / 2, sigma * kThickness * upper / 2);
}

TEST(Quad, PassesThePatchTestOnADistortedMesh) {
  for (bool plane_strain : {false, true}) {
    const double sigma = 100.0;
    const builder::BuiltModel built =
        builder::build(io::parse_model(patch_model(sigma, plane_strain), "patch.json"));
    StructuralSystem system(built.model);
    const Vector u = static_equilibrium(system, 0.0, 1e-13).displacement;
    // Uniaxial stress: e_xx = sigma / E', e_yy = -nu' e_xx (E', nu' of plane strain or stress).
    const double e_eff = plane_strain ? kE / (1 - kNu * kNu) : kE;
    const double nu_eff = plane_strain ? kNu / (1 - kNu) : kNu;
    double worst = 0.0;
    for (const auto& [id, node] : built.node_index) {
      const auto& p = built.model.nodes[static_cast<std::size_t>(node)].position;
      const double exact[2] = {sigma / e_eff * p[0], -nu_eff * sigma / e_eff * p[1]};
      for (int d = 0; d < 2; ++d)
        if (const Index eq = system.dofs().own_equation(node, d); eq >= 0)
          worst = std::max(worst, std::abs(u[eq] - exact[d]) / (sigma / e_eff * 4.0));
    }
    std::cout << fmt::format(
        "patch test ({}): largest nodal error / largest displacement = {:.2e}\n",
        plane_strain ? "plane strain" : "plane stress", worst);
    EXPECT_LT(worst, 1e-12);
  }
}

TEST(Quad, ReproducesALinearFieldsConstantStrainAtEveryGaussPoint) {
  // u = 1e-3 (2 + 3x - y), v = 1e-3 (1 + 0.5x + 2y): strain (3e-3, 2e-3, -0.5e-3).
  Eigen::Matrix<double, 8, 1> u;
  for (int a = 0; a < 4; ++a) {
    const double x = kDistorted[a][0], y = kDistorted[a][1];
    u[2 * a] = 1e-3 * (2 + 3 * x - y);
    u[2 * a + 1] = 1e-3 * (1 + 0.5 * x + 2 * y);
  }
  const Eigen::Vector3d exact(3e-3, 2e-3, -0.5e-3);
  for (double xi : {-0.7, 0.1, 0.9})
    for (double eta : {-0.4, 0.6})
      EXPECT_LT((quad_strain(kDistorted, u, xi, eta) - exact).norm(), 1e-15);
}

TEST(Quad, AClockwiseOrInvertedQuadIsRefusedNamingIt) {
  const std::string text = R"({
    "dimension": 2,
    "nodes": [{"id": "a", "x": 0, "y": 0}, {"id": "b", "x": 1, "y": 0},
              {"id": "c", "x": 1, "y": 1}, {"id": "d", "x": 0, "y": 1}],
    "materials": [{"id": "m", "youngs_modulus": 1, "poisson_ratio": 0.2, "density": 1}],
    "elements": [{"id": "q", "type": "quad", "nodes": ["a", "d", "c", "b"], "material": "m",
                  "thickness": 1}],
    "analysis": {"time_step": 0.1, "duration": 1}
  })";
  try {
    builder::build(io::parse_model(text, "q.json"));
    FAIL() << "a clockwise quad was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("/elements/0/nodes"), std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find("counter-clockwise"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace pound::assembly
