// The truss (assembly/truss): stiffness against E A / L in 1-D and in the plane, rigid-body
// motions without force, the lumped mass, and the axial force against the elongation and
// against the statics of a two-bar truss.
#include "assembly/truss.hpp"

#include <gtest/gtest.h>

#include <iostream>
#include <vector>

#include "assembly/static_equilibrium.hpp"
#include "assembly/structural_system.hpp"
#include "support/elements.hpp"

namespace pound::assembly {
namespace {

constexpr double kE = 200.0, kArea = 3.0, kDensity = 0.5;

Truss bar(const model::Coordinates& a, const model::Coordinates& b, int dimension, Index node_i = 0,
          Index node_j = 1) {
  return Truss("t", {{{node_i, a}, {node_j, b}}}, dimension,
               {.youngs_modulus = kE, .area = kArea, .density = kDensity}, std::nullopt);
}

// A 3-4-5 bar: L = 5, c = (0.6, 0.8), E A / L = 120.
const Truss kInclined = bar({1.0, 2.0}, {4.0, 6.0}, 2);
constexpr double kAxial = 120.0, kCos = 0.6, kSin = 0.8;

TEST(Truss, OneDimensionalStiffnessIsEaOverLAlongX) {
  // y ignored: L = 2.5, E A / L = 240.
  const Truss truss = bar({1.0, 7.0}, {3.5, -2.0}, 1, 4, 2);
  ASSERT_EQ(truss.directions().size(), 1u);
  EXPECT_EQ(truss.directions()[0], 0);
  const std::vector<model::ElementDof> dofs = truss.dofs();
  ASSERT_EQ(dofs.size(), 2u);
  EXPECT_EQ(dofs[0].node, 4);
  EXPECT_EQ(dofs[1].node, 2);
  Matrix expected(2, 2);
  expected << 240.0, -240.0, -240.0, 240.0;
  EXPECT_LE((truss.stiffness() - expected).norm(), 1e-14 * expected.norm());
}

TEST(Truss, PlaneStiffnessIsEaOverLInTheBarsDirection) {
  ASSERT_EQ(kInclined.directions().size(), 2u);
  Matrix cc(2, 2);
  cc << kCos * kCos, kCos * kSin, kCos * kSin, kSin * kSin;
  Matrix expected(4, 4);
  expected << cc, -cc, -cc, cc;
  expected *= kAxial;
  const Matrix k = kInclined.stiffness();
  EXPECT_LE((k - expected).norm(), 1e-14 * expected.norm());
  EXPECT_LE((k - k.transpose()).norm(), 1e-15 * k.norm());
}

TEST(Truss, RigidBodyMotionsCarryNoForce) {
  const double a[2] = {1.0, 2.0}, b[2] = {4.0, 6.0};
  const Vector translation_x{{1.0, 0.0, 1.0, 0.0}}, translation_y{{0.0, 1.0, 0.0, 1.0}};
  const Vector rotation{{-a[1], a[0], -b[1], b[0]}};  // u = -theta y, v = theta x
  const Matrix k = kInclined.stiffness();
  for (const Vector& u : {translation_x, translation_y, rotation}) {
    EXPECT_LE((k * u).norm(), 1e-14 * k.norm() * u.norm());
    EXPECT_LE(std::abs(kInclined.end_forces(u)[0]), 1e-14 * kAxial * u.norm());
  }
}

TEST(Truss, LumpedMassIsHalfOfRhoALAtEachEndInEachDirection) {
  const model::ElementMass mass = kInclined.mass();
  ASSERT_FALSE(mass.is_consistent());
  EXPECT_EQ(mass.lumped, Vector::Constant(4, 0.5 * kDensity * kArea * 5.0));
  EXPECT_EQ(mass.lumped[0] + mass.lumped[2], kDensity * kArea * 5.0);  // rho A L along x
}

TEST(Truss, AxialForceIsEaOverLTimesTheElongation) {
  ASSERT_EQ(kInclined.end_force_names().size(), 1u);
  EXPECT_EQ(kInclined.end_force_names()[0].name, "N");
  EXPECT_EQ(kInclined.end_force_names()[0].dimension, Dimension::force);
  // Node j moves 0.01 along the bar and 0.3 across it; node i stays (across: no first-order
  // elongation, so no force).
  const double along = 0.01, across = 0.3;
  const Vector u{{0.0, 0.0, along * kCos - across * kSin, along * kSin + across * kCos}};
  EXPECT_NEAR(kInclined.end_forces(u)[0], kAxial * along, 1e-14 * kAxial);
  EXPECT_NEAR(kInclined.end_forces(-u)[0], -kAxial * along, 1e-14 * kAxial);  // compression
  const Truss rod = bar({0.0, 0.0}, {2.5, 0.0}, 1);
  EXPECT_NEAR(rod.end_forces(Vector{{0.002, -0.003}})[0], 240.0 * -0.005, 1e-15);
}

// Two bars from supports at (-3, 0) and (3, 0) to an apex at (0, 4) loaded by P downwards:
// each bar carries N = -P / (2 sin alpha) = -0.625 P (compression), sin alpha = 4 / 5.
TEST(Truss, AxialForcesBalanceTheLoadOnATwoBarTruss) {
  constexpr double kLoad = 1000.0;
  model::Model m;
  m.dimension = 2;
  m.nodes = {{"left", {-3.0, 0.0}}, {"right", {3.0, 0.0}}, {"apex", {0.0, 4.0}}};
  m.elements = {
      std::make_shared<const Truss>(bar(m.nodes[0].position, m.nodes[2].position, 2, 0, 2)),
      std::make_shared<const Truss>(bar(m.nodes[1].position, m.nodes[2].position, 2, 1, 2))};
  m.supports = {{.node = 0, .fixed = {true, true}}, {.node = 1, .fixed = {true, true}}};
  m.loads = {{.node = 2, .force = {0.0, -kLoad}}};
  StructuralSystem system(m);
  const Vector u = static_equilibrium(system, 0.0).displacement;
  for (const auto& element : m.elements) {
    const double n =
        element->end_forces(testing::element_displacements(system.dofs(), *element, u))[0];
    std::cout << "N = " << n << " (exact " << -0.625 * kLoad << ")\n";
    EXPECT_NEAR(n, -0.625 * kLoad, 1e-12 * kLoad);
  }
}

}  // namespace
}  // namespace pound::assembly
