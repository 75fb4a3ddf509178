#pragma once
// How the results tests name a DOF by hand: an equation of its own (coefficient 1), or -1 for a
// fixed DOF (no terms), as model::DofMap::terms gives them.
#include "results/ground_acceleration.hpp"

namespace pound::testing {

inline results::DofReading dof(Index equation) {
  if (equation < 0) return {};
  return {{equation, 1.0}};
}

}  // namespace pound::testing
