#pragma once
// Elements seen from the tests: how many of a model's are of one kind (assembly::Truss, Beam,
// Quad), and an element's displacements out of a system's solution.
#include <algorithm>
#include <cstddef>

#include "model/model.hpp"

namespace pound::testing {

template <typename Kind>
std::size_t element_count(const model::Model& model) {
  return static_cast<std::size_t>(std::ranges::count_if(model.elements, [](const auto& element) {
    return dynamic_cast<const Kind*>(element.get()) != nullptr;
  }));
}

// u over the element's DOFs (zero where fixed) from the displacements u of the free DOFs.
inline Vector element_displacements(const model::DofMap& dofs, const model::Element& element,
                                    const Vector& u) {
  const std::vector<model::ElementDof> element_dofs = element.dofs();
  Vector local = Vector::Zero(static_cast<Index>(element_dofs.size()));
  for (std::size_t k = 0; k < element_dofs.size(); ++k)
    if (const Index row = dofs.own_equation(element_dofs[k].node, element_dofs[k].direction);
        row >= 0)
      local[static_cast<Index>(k)] = u[row];
  return local;
}

}  // namespace pound::testing
