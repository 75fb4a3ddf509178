#include "model/model.hpp"

#include <algorithm>
#include <cmath>

namespace pound::model {

std::vector<Coordinates> contact_tangents(const Coordinates& n, int dimension) {
  // In the x-y plane, exactly the plane scene's tangent: a plane model written in 3-D slides
  // along the same row to the bit.
  if (dimension < 3 || n[2] == 0.0) {
    const Coordinates first{-n[1], n[0], 0.0};
    if (dimension < 3) return {first};
    return {first, cross(n, first)};
  }
  const double length = std::hypot(n[0], n[1], n[2]);
  const Coordinates unit{n[0] / length, n[1] / length, n[2] / length};
  const double horizontal = std::hypot(unit[0], unit[1]);
  Coordinates first;
  if (horizontal > 1e-9) {
    first = {-unit[1] / horizontal, unit[0] / horizontal, 0.0};
  } else {  // vertical: x, less its (round-off) component along n
    first = {1.0 - unit[0] * unit[0], -unit[0] * unit[1], -unit[0] * unit[2]};
    const double size = std::hypot(first[0], first[1], first[2]);
    for (double& component : first) component /= size;
  }
  Coordinates second = cross(unit, first);
  // A vertical contact (a block on a floor, a bearing) slides along x and y, whichever way n
  // points.
  if (horizontal <= 1e-9 && second[1] < 0.0)
    for (double& component : second) component = -component;
  return {first, second};
}

int Model::dofs_per_node() const {
  int count = dimension;
  for (const auto& element : elements)
    for (int direction : element->directions()) count = std::max(count, direction + 1);
  // A rotational link turns its nodes about an axis of the scene, a link with offsets its ends.
  if (std::ranges::any_of(links,
                          [](const Link& link) { return link.rotational || link.has_offsets(); }))
    count = direction_count(dimension);
  return count;
}

DofMap::DofMap(const Model& model)
    : dofs_per_node_(model.dofs_per_node()), dimension_(model.dimension) {
  equations_.assign(model.nodes.size() * static_cast<std::size_t>(dofs_per_node_), 0);
  // In a frame scene only nodes that an element or a rotational link turns have rotations;
  // the others (truss joints, lumped masses, contact points) have none to solve for.
  std::vector<bool> turns(model.nodes.size(), false);
  const auto is_rotation = [this](int d) { return direction(d, dimension_).rotation; };
  for (const auto& element : model.elements)
    if (std::ranges::any_of(element->directions(), is_rotation))
      for (Index node : element->nodes()) turns[static_cast<std::size_t>(node)] = true;
  for (const Link& link : model.links) {
    if (link.rotational)
      turns[static_cast<std::size_t>(link.node_i)] = turns[static_cast<std::size_t>(link.node_j)] =
          true;
    // An end whose point is offset turns with it.
    if (link.offsets[0] != Coordinates{}) turns[static_cast<std::size_t>(link.node_i)] = true;
    if (link.offsets[1] != Coordinates{}) turns[static_cast<std::size_t>(link.node_j)] = true;
  }
  const auto per_node = static_cast<std::size_t>(dofs_per_node_);
  for (std::size_t node = 0; node < turns.size(); ++node)
    for (int d = 0; d < dofs_per_node_; ++d)
      if (!turns[node] && is_rotation(d))
        equations_[node * per_node + static_cast<std::size_t>(d)] = -1;
  for (const Support& support : model.supports)
    for (int d = 0; d < dofs_per_node_; ++d)
      if (support.fixed[static_cast<std::size_t>(d)])
        equations_[static_cast<std::size_t>(support.node * dofs_per_node_ + d)] = -1;
  for (Index& equation : equations_)
    if (equation == 0) equation = size_++;
}

}  // namespace pound::model
