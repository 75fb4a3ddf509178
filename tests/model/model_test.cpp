// DOFs per node and their numbering follow what the scene's elements need.
#include "model/model.hpp"

#include <gtest/gtest.h>

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
  for (Index node : {0, 3}) EXPECT_EQ(dofs.equation(node, 2), -1) << node;
  for (Index node : {1, 2}) EXPECT_GE(dofs.equation(node, 2), 0) << node;
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

}  // namespace
}  // namespace pound::model
