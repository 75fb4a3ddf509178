#include "model/model.hpp"

#include <cmath>

namespace pound::model {

double Model::length(Index node_i, Index node_j) const {
  const Coordinates& a = nodes[static_cast<std::size_t>(node_i)].position;
  const Coordinates& b = nodes[static_cast<std::size_t>(node_j)].position;
  return std::hypot(b[0] - a[0], dimension == 2 ? b[1] - a[1] : 0.0);
}

double Model::element_length(const Truss& truss) const {
  return length(truss.node_i, truss.node_j);
}

DofMap::DofMap(const Model& model) : dofs_per_node_(model.dofs_per_node()) {
  equations_.assign(model.nodes.size() * static_cast<std::size_t>(dofs_per_node_), 0);
  // In a frame scene only nodes that a beam or a rotational link touches turn; the others
  // (truss joints, lumped masses, contact points) have no rotation to solve for.
  if (dofs_per_node_ == 3) {
    std::vector<bool> turns(model.nodes.size(), false);
    for (const Beam& beam : model.beams)
      turns[static_cast<std::size_t>(beam.node_i)] = turns[static_cast<std::size_t>(beam.node_j)] =
          true;
    for (const Link& link : model.links)
      if (link.rotational)
        turns[static_cast<std::size_t>(link.node_i)] =
            turns[static_cast<std::size_t>(link.node_j)] = true;
    for (std::size_t node = 0; node < turns.size(); ++node)
      if (!turns[node]) equations_[node * 3 + 2] = -1;
  }
  for (const Support& support : model.supports)
    for (int d = 0; d < dofs_per_node_; ++d)
      if (support.fixed[static_cast<std::size_t>(d)])
        equations_[static_cast<std::size_t>(support.node * dofs_per_node_ + d)] = -1;
  for (Index& equation : equations_)
    if (equation == 0) equation = size_++;
}

}  // namespace pound::model
