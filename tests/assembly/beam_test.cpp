// The 2-D beam-column (assembly/beam): stiffness and consistent mass against their closed
// forms, rotated into global axes, rigid-body motions without force, mass totals, and the end
// forces against the statics of a cantilever.
#include "assembly/beam.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <iostream>
#include <numbers>

#include "assembly/static_equilibrium.hpp"
#include "assembly/structural_system.hpp"
#include "support/elements.hpp"

namespace pound::assembly {
namespace {

constexpr double kE = 2.0e11, kArea = 0.01, kInertia = 1.0e-4, kDensity = 7850.0,
                 kExtraMass = 120.0;

Beam beam(const model::Coordinates& a, const model::Coordinates& b, bool consistent_mass = false,
          Index node_i = 0, Index node_j = 1) {
  return Beam("b", {{{node_i, a}, {node_j, b}}},
              {.youngs_modulus = kE,
               .area = kArea,
               .inertia = kInertia,
               .density = kDensity,
               .extra_mass = kExtraMass},
              consistent_mass, std::nullopt);
}

// Local -> global for one beam of direction (c, s): u' = T u (theta unchanged).
Matrix rotation(double c, double s) {
  Matrix t = Matrix::Zero(6, 6);
  for (int o : {0, 3}) {
    t.block(o, o, 3, 3) << c, s, 0, -s, c, 0, 0, 0, 1;
  }
  return t;
}

double relative_difference(const Matrix& actual, const Matrix& expected) {
  return (actual - expected).norm() / expected.norm();
}

// Length 5 at 30 degrees from node (1, 2).
constexpr double kLength = 5.0;
const double kCos = std::cos(std::numbers::pi / 6), kSin = std::sin(std::numbers::pi / 6);
const model::Coordinates kStart{1.0, 2.0};
const double kRise = kLength * kSin, kRun = kLength * kCos;
const model::Coordinates kEnd{kStart[0] + kRun, kStart[1] + kRise};

TEST(Beam, HorizontalStiffnessIsTheEulerBernoulliOne) {
  const Beam horizontal = beam({0.0, 0.0}, {kLength, 0.0});
  const double ea = kE * kArea / kLength, ei = kE * kInertia, l = kLength;
  Matrix expected(6, 6);
  expected << ea, 0, 0, -ea, 0, 0,                                                                //
      0, 12 * ei / (l * l * l), 6 * ei / (l * l), 0, -12 * ei / (l * l * l), 6 * ei / (l * l),    //
      0, 6 * ei / (l * l), 4 * ei / l, 0, -6 * ei / (l * l), 2 * ei / l,                          //
      -ea, 0, 0, ea, 0, 0,                                                                        //
      0, -12 * ei / (l * l * l), -6 * ei / (l * l), 0, 12 * ei / (l * l * l), -6 * ei / (l * l),  //
      0, 6 * ei / (l * l), 2 * ei / l, 0, -6 * ei / (l * l), 4 * ei / l;
  EXPECT_LE(relative_difference(horizontal.stiffness(), expected), 1e-15);
  const std::span<const int> directions = horizontal.directions();
  EXPECT_EQ(std::vector<int>(directions.begin(), directions.end()), (std::vector<int>{0, 1, 2}));
}

TEST(Beam, InclinedStiffnessIsTheHorizontalOneInRotatedAxes) {
  const Matrix t = rotation(kCos, kSin);
  const Matrix expected = t.transpose() * beam({0.0, 0.0}, {kLength, 0.0}).stiffness() * t;
  const Matrix k = beam(kStart, kEnd).stiffness();
  const double error = relative_difference(k, expected);
  std::cout << "inclined K relative error " << error << "\n";
  EXPECT_LE(error, 1e-14);
  EXPECT_LE((k - k.transpose()).norm(), 1e-15 * k.norm());
}

TEST(Beam, HasExactlyThreeRigidBodyModesWhichCarryNoForce) {
  const Beam inclined = beam(kStart, kEnd);
  const Matrix k = inclined.stiffness();
  const Vector eigenvalues = Eigen::SelfAdjointEigenSolver<Matrix>(k).eigenvalues();
  int zero = 0;
  for (Index i = 0; i < 6; ++i) zero += std::abs(eigenvalues[i]) < 1e-12 * eigenvalues.maxCoeff();
  EXPECT_EQ(zero, 3);
  // Translations and a rotation about the origin (u = -theta y, v = theta x, theta).
  const Vector modes[] = {Vector{{1.0, 0.0, 0.0, 1.0, 0.0, 0.0}},
                          Vector{{0.0, 1.0, 0.0, 0.0, 1.0, 0.0}},
                          Vector{{-kStart[1], kStart[0], 1.0, -kEnd[1], kEnd[0], 1.0}}};
  for (const Vector& u : modes) {
    EXPECT_LE((k * u).norm(), 1e-14 * k.norm() * u.norm());
    EXPECT_LE(inclined.end_forces(u).norm(), 1e-14 * k.norm() * u.norm());
  }
}

TEST(Beam, LumpedMassIsHalfTheElementsAtEachEndWithoutRotaryInertia) {
  const model::ElementMass mass = beam(kStart, kEnd).mass();
  ASSERT_FALSE(mass.is_consistent());
  const double half = 0.5 * (kDensity * kArea + kExtraMass) * kLength;
  EXPECT_EQ(mass.lumped, (Vector{{half, half, 0.0, half, half, 0.0}}));
}

TEST(Beam, ConsistentMassIsTheHermitianOneAndSumsToTheElementsMass) {
  const double m = (kDensity * kArea + kExtraMass) * kLength, l = kLength;
  Matrix expected = Matrix::Zero(6, 6);
  expected(0, 0) = expected(3, 3) = 140;
  expected(0, 3) = expected(3, 0) = 70;
  const int transverse[4] = {1, 2, 4, 5};
  const double hermitian[4][4] = {{156, 22 * l, 54, -13 * l},
                                  {22 * l, 4 * l * l, 13 * l, -3 * l * l},
                                  {54, 13 * l, 156, -22 * l},
                                  {-13 * l, -3 * l * l, -22 * l, 4 * l * l}};
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) expected(transverse[a], transverse[b]) = hermitian[a][b];
  expected *= m / 420;
  const model::ElementMass horizontal = beam({0.0, 0.0}, {kLength, 0.0}, true).mass();
  ASSERT_TRUE(horizontal.is_consistent());
  EXPECT_LE(relative_difference(horizontal.consistent, expected), 1e-15);

  // Inclined: a unit translation in x or y carries the whole mass m (iota^T M iota = m), and no
  // inertia couples the two directions.
  const Matrix inclined = beam(kStart, kEnd, true).mass().consistent;
  const Vector x{{1.0, 0.0, 0.0, 1.0, 0.0, 0.0}}, y{{0.0, 1.0, 0.0, 0.0, 1.0, 0.0}};
  EXPECT_NEAR(x.dot(inclined * x), m, 1e-14 * m);
  EXPECT_NEAR(y.dot(inclined * y), m, 1e-14 * m);
  EXPECT_NEAR(x.dot(inclined * y), 0.0, 1e-14 * m);
}

TEST(Beam, EndForcesAreTheNodalForcesInLocalAxes) {
  const Beam inclined = beam(kStart, kEnd);
  const Vector u{{0.001, -0.002, 0.0003, 0.0025, 0.0011, -0.0004}};
  const Vector forces = inclined.end_forces(u);
  // T^T f' = K u, and u^T K u = (T u)^T f' (the same work in either axes).
  const Matrix t = rotation(kCos, kSin);
  const Vector global = inclined.stiffness() * u;
  EXPECT_LE((t.transpose() * forces - global).norm(), 1e-14 * global.norm());
  EXPECT_NEAR((t * u).dot(forces), u.dot(global), 1e-14 * std::abs(u.dot(global)));
  std::vector<std::string_view> names;
  std::vector<Dimension> dimensions;
  for (const model::EndForce& force : inclined.end_force_names()) {
    names.push_back(force.name);
    dimensions.push_back(force.dimension);
  }
  EXPECT_EQ(names, (std::vector<std::string_view>{"N_i", "V_i", "M_i", "N_j", "V_j", "M_j"}));
  const Dimension F = Dimension::force, M = Dimension::moment;
  EXPECT_EQ(dimensions, (std::vector<Dimension>{F, F, M, F, F, M}));
}

// A cantilever of 4 beams at 30 degrees, fixed at its base, under a tip load P across its axis
// and a tip load Q along it. Each element, cut at x' from the base: N = Q (tension), shear P,
// moment P (L - x'); as forces the nodes apply: N_i = -Q, V_i = -P, M_i = -P (L - x'_i),
// N_j = Q, V_j = P, M_j = P (L - x'_j). Euler-Bernoulli elements are exact here.
TEST(Beam, EndForcesOfACantileverBalanceTheTipLoad) {
  constexpr int kElements = 4;
  constexpr double kShear = 3000.0, kAxialLoad = 5000.0;
  model::Model m;
  m.dimension = 2;
  for (int i = 0; i <= kElements; ++i) {
    const double along = kLength * i / kElements;
    m.nodes.push_back(
        {fmt::format("n{}", i), {kStart[0] + along * kCos, kStart[1] + along * kSin}});
  }
  for (Index e = 0; e < kElements; ++e)
    m.elements.push_back(std::make_shared<const Beam>(
        beam(m.nodes[static_cast<std::size_t>(e)].position,
             m.nodes[static_cast<std::size_t>(e + 1)].position, false, e, e + 1)));
  m.supports = {{.node = 0, .fixed = {true, true, true}}};
  m.loads = {{.node = kElements,
              .force = {kAxialLoad * kCos - kShear * kSin, kAxialLoad * kSin + kShear * kCos}}};
  StructuralSystem system(m);
  const Vector u = static_equilibrium(system, 0.0).displacement;
  for (Index e = 0; e < kElements; ++e) {
    const model::Element& element = *m.elements[static_cast<std::size_t>(e)];
    const Vector f = element.end_forces(testing::element_displacements(system.dofs(), element, u));
    const double x_i = kLength * static_cast<double>(e) / kElements,
                 x_j = kLength * static_cast<double>(e + 1) / kElements;
    const Vector exact{{-kAxialLoad, -kShear, -kShear * (kLength - x_i), kAxialLoad, kShear,
                        kShear * (kLength - x_j)}};
    const double error = (f - exact).cwiseAbs().maxCoeff() / (kShear * kLength);
    std::cout << "element " << e << ": (N, V, M)_i = (" << f[0] << ", " << f[1] << ", " << f[2]
              << "), largest error / (P L) " << error << "\n";
    EXPECT_LE(error, 1e-12);
  }
  // At the base: shear P and moment P L.
  const Vector base =
      m.elements[0]->end_forces(testing::element_displacements(system.dofs(), *m.elements[0], u));
  EXPECT_NEAR(-base[1], kShear, 1e-12 * kShear);
  EXPECT_NEAR(-base[2], kShear * kLength, 1e-12 * kShear * kLength);
}

}  // namespace
}  // namespace pound::assembly
