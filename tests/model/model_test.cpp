// DOFs per node and their numbering follow what the scene's elements need.
#include "model/model.hpp"

#include <gtest/gtest.h>

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
