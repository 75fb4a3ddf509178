// DOFs per node and their numbering follow what the scene's elements need.
#include "model/model.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "assembly/beam.hpp"
#include "assembly/quad.hpp"
#include "assembly/truss.hpp"

namespace pound::model {
namespace {

// Nodes on a unit square, counter-clockwise, in a scene of `dimension`.
Model square(int dimension) {
  Model m;
  m.dimension = dimension;
  m.nodes = {{"a", {0.0, 0.0}}, {"b", {1.0, 0.0}}, {"c", {1.0, 1.0}}, {"d", {0.0, 1.0}}};
  return m;
}

ElementNode at(const Model& m, Index node) {
  return {node, m.nodes[static_cast<std::size_t>(node)].position};
}

std::shared_ptr<const Element> truss(const Model& m, Index i, Index j) {
  return std::make_shared<const assembly::Truss>(
      "t", std::array{at(m, i), at(m, j)}, m.dimension,
      assembly::Truss::Section{.youngs_modulus = 1.0, .area = 1.0, .density = 1.0}, std::nullopt);
}

std::shared_ptr<const Element> beam(const Model& m, Index i, Index j) {
  return std::make_shared<const assembly::Beam>(
      "b", std::array{at(m, i), at(m, j)},
      assembly::Beam::Section{.youngs_modulus = 1.0, .area = 1.0, .inertia = 1.0, .density = 1.0},
      false, std::nullopt);
}

std::shared_ptr<const Element> quad(const Model& m) {
  return std::make_shared<const assembly::Quad>(
      "q", std::array{at(m, 0), at(m, 1), at(m, 2), at(m, 3)},
      assembly::Quad::Material{
          .youngs_modulus = 1.0, .poisson_ratio = 0.2, .thickness = 1.0, .density = 1.0},
      false, std::nullopt);
}

TEST(Model, DofsPerNodeAreTheMostAnElementNeedsAndNothingIsPadded) {
  Model axial = square(1);
  axial.elements = {truss(axial, 0, 1)};
  EXPECT_EQ(axial.dofs_per_node(), 1);
  EXPECT_EQ(square(2).dofs_per_node(), 2);  // masses and links alone: the plane's translations
  Model plane_truss = square(2);
  plane_truss.elements = {truss(plane_truss, 0, 2)};
  EXPECT_EQ(plane_truss.dofs_per_node(), 2);
  Model continuum = square(2);
  continuum.elements = {quad(continuum)};
  EXPECT_EQ(continuum.dofs_per_node(), 2);
  Model frame = square(2);
  frame.elements = {truss(frame, 0, 2), beam(frame, 1, 2)};
  EXPECT_EQ(frame.dofs_per_node(), 3);
}

// In a frame scene only the nodes of elements that need a rotation turn.
TEST(Model, OnlyNodesOfRotatingElementsHaveARotation) {
  Model frame = square(2);
  frame.elements = {truss(frame, 0, 2), beam(frame, 1, 2)};
  const DofMap dofs(frame);
  EXPECT_EQ(dofs.size(), 4 * 2 + 2);
  for (Index node : {0, 3}) EXPECT_EQ(dofs.own_equation(node, 2), -1) << node;
  for (Index node : {1, 2}) EXPECT_GE(dofs.own_equation(node, 2), 0) << node;
}

}  // namespace
}  // namespace pound::model

namespace pound::model {
namespace {

double dot3(const Coordinates& a, const Coordinates& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The contact plane of a link: t_1, t_2 and n orthonormal for any n, the plane scene's tangent
// to the bit for an n in the x-y plane, x and y for a vertical n of either sign.
TEST(ContactTangents, AreOrthonormalAndMatchThePlaneScenesTangent) {
  EXPECT_EQ(contact_tangents({0.6, 0.8, 0.0}, 2), (std::vector<Coordinates>{{-0.8, 0.6, 0.0}}));
  const std::vector<Coordinates> horizontal = contact_tangents({0.6, 0.8, 0.0}, 3);
  EXPECT_EQ(horizontal[0], (Coordinates{-0.8, 0.6, 0.0}));
  EXPECT_NEAR(horizontal[1][2], 1.0, 1e-15);
  for (const Coordinates& down : {Coordinates{0, 0, -1}, Coordinates{0, 0, 1}}) {
    const std::vector<Coordinates> vertical = contact_tangents(down, 3);
    EXPECT_EQ(vertical[0], (Coordinates{1, 0, 0}));
    EXPECT_EQ(vertical[1], (Coordinates{0, 1, 0}));
  }
  double worst = 0.0;
  for (const Coordinates& raw :
       {Coordinates{1, 2, 2}, Coordinates{-0.3, 0.1, 5}, Coordinates{1e-12, 0, 1},
        Coordinates{0, -1, -1}, Coordinates{3, -4, 0.5}}) {
    const double length = std::sqrt(dot3(raw, raw));
    const Coordinates n{raw[0] / length, raw[1] / length, raw[2] / length};
    const std::vector<Coordinates> t = contact_tangents(n, 3);
    ASSERT_EQ(t.size(), 2u);
    for (const auto& [a, b, expected] : {std::tuple{t[0], t[0], 1.0},
                                         {t[1], t[1], 1.0},
                                         {t[0], t[1], 0.0},
                                         {t[0], n, 0.0},
                                         {t[1], n, 0.0}})
      worst = std::max(worst, std::abs(dot3(a, b) - expected));
    EXPECT_LT(std::abs(t[0][2]), 1e-11);  // t_1 horizontal (but for n's own round-off)
  }
  std::printf("  contact planes: largest departure from orthonormal %.1e\n", worst);
  EXPECT_LT(worst, 1e-15);
}

// A rigid beam's tie is the linearised rigid motion: rotating the point r by a small angle t
// about each axis moves it by (R(t) r - r) / t -> e x r, which is what tie_terms weights the
// master's rotation by (checked by a central difference of the exact rotation, step 1e-6).
TEST(Constraints, ARigidTieIsTheLinearisedRigidRotation) {
  const Coordinates r{1.3, -0.7, 2.1};
  const Constraint beam{.kind = ConstraintKind::rigid_beam};
  double worst = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Vector3d unit = Eigen::Vector3d::Zero();
    unit[axis] = 1.0;
    const Eigen::Vector3d point(r[0], r[1], r[2]);
    const double step = 1e-6;
    const Eigen::Vector3d rate =
        (Eigen::AngleAxisd(step, unit) * point - Eigen::AngleAxisd(-step, unit) * point) /
        (2.0 * step);
    for (int d = 0; d < 3; ++d) {
      double weight = 0.0;
      for (const auto& [master, w] : tie_terms(beam, d, r, 3))
        if (master == 3 + axis) weight = w;
      worst = std::max(worst, std::abs(weight - rate[d]));
    }
  }
  std::printf("  rigid-beam weights against the rotation's central difference: %.1e\n", worst);
  EXPECT_LT(worst, 1e-9);
  // The slave's own rotation is the master's; a diaphragm keeps the out-of-plane ones free.
  EXPECT_EQ(tie_terms(beam, 4, r, 3), (std::vector<std::pair<int, double>>{{4, 1.0}}));
  const Constraint floor{.kind = ConstraintKind::rigid_diaphragm};
  EXPECT_EQ(tie_terms(floor, 0, r, 3), (std::vector<std::pair<int, double>>{{0, 1.0}, {5, -r[1]}}));
  EXPECT_EQ(tie_terms(floor, 1, r, 3), (std::vector<std::pair<int, double>>{{1, 1.0}, {5, r[0]}}));
  for (int d : {2, 3, 4}) EXPECT_TRUE(tie_terms(floor, d, r, 3).empty()) << d;
  // In a plane the rotation is about z: u_x gains -theta r_y, u_y +theta r_x.
  EXPECT_EQ(tie_terms(beam, 0, r, 2), (std::vector<std::pair<int, double>>{{0, 1.0}, {2, -r[1]}}));
  const Constraint bar{.kind = ConstraintKind::rigid_bar};
  EXPECT_EQ(tie_terms(bar, 0, r, 3), (std::vector<std::pair<int, double>>{{0, 1.0}}));
  EXPECT_TRUE(tie_terms(bar, 5, r, 3).empty());
}

// A tied DOF has no equation of its own and reads as its master's terms; free DOFs keep their
// numbering in node order, fixed ones read as nothing.
TEST(Constraints, ATiedDofIsItsMastersTerms) {
  Model m;
  m.dimension = 3;
  m.nodes = {{"master", {0.0, 0.0, 3.0}}, {"corner", {2.0, 1.0, 3.0}}, {"other", {5.0, 0.0, 3.0}}};
  m.supports = {{0, {false, false, true, true, true, false}}};
  m.constraints = {{.kind = ConstraintKind::rigid_diaphragm, .master = 0, .slaves = {1}}};
  const DofMap dofs(m);
  EXPECT_EQ(dofs.dofs_per_node(), 6);
  EXPECT_TRUE(dofs.has_ties());
  // master: x, y, rz (it turns for its slaves); corner: z of its own; other: x, y, z.
  EXPECT_EQ(dofs.size(), 7);
  const Index x = dofs.own_equation(0, 0), turn = dofs.own_equation(0, 5);
  EXPECT_EQ(dofs.own_equation(1, 0), -1);
  EXPECT_TRUE(dofs.tied(1, 0));
  EXPECT_FALSE(dofs.tied(1, 2));
  const std::span<const DofTerm> corner_x = dofs.terms(1, 0);
  ASSERT_EQ(corner_x.size(), 2u);
  EXPECT_EQ(corner_x[0].equation, x);
  EXPECT_EQ(corner_x[0].coefficient, 1.0);
  EXPECT_EQ(corner_x[1].equation, turn);
  EXPECT_EQ(corner_x[1].coefficient, -1.0);  // -theta r_y
  EXPECT_TRUE(dofs.terms(0, 2).empty());     // the master's held z
  EXPECT_EQ(dofs.terms(2, 1).size(), 1u);
  // Rigid motion: the master moving by (0.1, 0.2) and turning by 0.01 carries the corner to
  // (0.1 - 0.01 x 1, 0.2 + 0.01 x 2).
  Vector u = Vector::Zero(dofs.size());
  u[x] = 0.1;
  u[dofs.own_equation(0, 1)] = 0.2;
  u[turn] = 0.01;
  EXPECT_DOUBLE_EQ(value_of(dofs.terms(1, 0), u), 0.09);
  EXPECT_DOUBLE_EQ(value_of(dofs.terms(1, 1), u), 0.22);
  // Nothing turns the corner itself (no element): it has no rotation to tie.
  EXPECT_TRUE(dofs.terms(1, 5).empty());
}

}  // namespace
}  // namespace pound::model
