#pragma once
// A DOF as a combination of equations (model::DofMap::terms), and reading one from a vector.
#include <span>

#include "core/types.hpp"

namespace pound::model {

// One equation's share of a DOF's value (u_dof = sum of coefficient x u[equation]).
struct DofTerm {
  Index equation;
  double coefficient;
};

// The DOF's value in `v`: 0 where it has no terms (fixed), v[equation] exactly where it is free.
inline double value_of(std::span<const DofTerm> terms, const Vector& v) {
  if (terms.empty()) return 0.0;
  double value = terms[0].coefficient * v[terms[0].equation];
  for (std::size_t k = 1; k < terms.size(); ++k)
    value += terms[k].coefficient * v[terms[k].equation];
  return value;
}

}  // namespace pound::model
