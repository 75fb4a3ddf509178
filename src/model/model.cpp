#include "model/model.hpp"

#include <cmath>

namespace pound::model {

double Model::element_length(const Truss& truss) const {
  const Coordinates& a = nodes[static_cast<std::size_t>(truss.node_i)].position;
  const Coordinates& b = nodes[static_cast<std::size_t>(truss.node_j)].position;
  return std::hypot(b[0] - a[0], dimension == 2 ? b[1] - a[1] : 0.0);
}

DofMap::DofMap(const Model& model) : dofs_per_node_(model.dofs_per_node()) {
  equations_.assign(model.nodes.size() * static_cast<std::size_t>(dofs_per_node_), 0);
  for (const Support& support : model.supports)
    for (int d = 0; d < dofs_per_node_; ++d)
      if (support.fixed[static_cast<std::size_t>(d)])
        equations_[static_cast<std::size_t>(support.node * dofs_per_node_ + d)] = -1;
  for (Index& equation : equations_)
    if (equation == 0) equation = size_++;
}

}  // namespace pound::model
