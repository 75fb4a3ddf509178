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

std::array<bool, 6> tied_directions(const Constraint& constraint, int dimension) {
  std::array<bool, 6> tied{};
  for (int d = 0; d < direction_count(dimension); ++d) {
    const Direction along = direction(d, dimension);
    const auto at = static_cast<std::size_t>(d);
    switch (constraint.kind) {
      case ConstraintKind::equal_dofs:
        tied[at] = constraint.tied[at];
        break;
      case ConstraintKind::rigid_beam:
        tied[at] = along.axis < dimension || along.rotation;
        break;
      case ConstraintKind::rigid_bar:
        tied[at] = !along.rotation && along.axis < dimension;
        break;
      case ConstraintKind::rigid_diaphragm:
        tied[at] = along.rotation == (along.axis == constraint.normal);
        break;
    }
  }
  // A plane scene's rotation is about z; a 1-D scene has none.
  if (dimension == 1) tied[2] = false;
  return tied;
}

std::vector<std::pair<int, double>> tie_terms(const Constraint& constraint, int d,
                                              const Coordinates& r, int dimension) {
  const std::array<bool, 6> tied = tied_directions(constraint, dimension);
  if (!tied[static_cast<std::size_t>(d)]) return {};
  std::vector<std::pair<int, double>> terms{{d, 1.0}};
  const Direction along = direction(d, dimension);
  if (along.rotation || constraint.kind == ConstraintKind::equal_dofs ||
      constraint.kind == ConstraintKind::rigid_bar)
    return terms;
  // u_s = u_m + sum over the tied rotations theta_j (e_j x r).
  for (int j = 0; j < direction_count(dimension); ++j) {
    const Direction rotation = direction(j, dimension);
    if (!rotation.rotation || !tied[static_cast<std::size_t>(j)]) continue;
    Coordinates axis{};
    axis[static_cast<std::size_t>(rotation.axis)] = 1.0;
    const double weight = cross(axis, r)[static_cast<std::size_t>(along.axis)];
    if (weight != 0.0) terms.emplace_back(j, weight);
  }
  return terms;
}

int Model::dofs_per_node() const {
  int count = dimension;
  for (const auto& element : elements)
    for (int direction : element->directions()) count = std::max(count, direction + 1);
  // A rotational link turns its nodes about an axis of the scene, a link with offsets its ends.
  if (std::ranges::any_of(links,
                          [](const Link& link) { return link.rotational || link.has_offsets(); }))
    count = direction_count(dimension);
  // A master turns its slaves' points about it.
  for (const Constraint& constraint : constraints) {
    const std::array<bool, 6> tied = tied_directions(constraint, dimension);
    for (int d = 0; d < direction_count(dimension); ++d)
      if (tied[static_cast<std::size_t>(d)]) count = std::max(count, d + 1);
  }
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
  // A master's tied rotations turn the points of its slaves.
  for (const Constraint& constraint : model.constraints) {
    const std::array<bool, 6> tied = tied_directions(constraint, dimension_);
    for (int d = 0; d < dofs_per_node_; ++d)
      if (tied[static_cast<std::size_t>(d)] && is_rotation(d))
        turns[static_cast<std::size_t>(constraint.master)] = true;
  }
  const auto per_node = static_cast<std::size_t>(dofs_per_node_);
  for (std::size_t node = 0; node < turns.size(); ++node)
    for (int d = 0; d < dofs_per_node_; ++d)
      if (!turns[node] && is_rotation(d))
        equations_[node * per_node + static_cast<std::size_t>(d)] = -1;
  for (const Support& support : model.supports)
    for (int d = 0; d < dofs_per_node_; ++d)
      if (support.fixed[static_cast<std::size_t>(d)]) equations_[place(support.node, d)] = -1;
  // Tied slave DOFs (those that exist) have no equation of their own; the builder has refused
  // supports on them and chains of ties.
  for (const Constraint& constraint : model.constraints) {
    const std::array<bool, 6> tied = tied_directions(constraint, dimension_);
    for (Index slave : constraint.slaves)
      for (int d = 0; d < dofs_per_node_; ++d)
        if (tied[static_cast<std::size_t>(d)] && equations_[place(slave, d)] == 0)
          equations_[place(slave, d)] = -2;
  }
  for (Index& equation : equations_)
    if (equation == 0) equation = size_++;
  build_terms(model);
}

void DofMap::build_terms(const Model& model) {
  std::vector<std::vector<DofTerm>> tied(equations_.size());
  for (const Constraint& constraint : model.constraints) {
    const Coordinates& master = model.nodes[static_cast<std::size_t>(constraint.master)].position;
    for (Index slave : constraint.slaves) {
      const Coordinates& at = model.nodes[static_cast<std::size_t>(slave)].position;
      const Coordinates r{at[0] - master[0], at[1] - master[1], at[2] - master[2]};
      for (int d = 0; d < dofs_per_node_; ++d) {
        if (equations_[place(slave, d)] != -2) continue;
        std::vector<DofTerm>& terms = tied[place(slave, d)];
        for (const auto& [master_direction, weight] : tie_terms(constraint, d, r, dimension_))
          if (master_direction < dofs_per_node_)
            if (const Index equation = equations_[place(constraint.master, master_direction)];
                equation >= 0)
              terms.push_back({equation, weight});
      }
    }
  }
  first_term_.reserve(equations_.size() + 1);
  for (std::size_t at = 0; at < equations_.size(); ++at) {
    first_term_.push_back(terms_.size());
    if (equations_[at] >= 0) terms_.push_back({equations_[at], 1.0});
    for (const DofTerm& term : tied[at]) terms_.push_back(term);
    has_ties_ = has_ties_ || equations_[at] == -2;
  }
  first_term_.push_back(terms_.size());
}

}  // namespace pound::model
