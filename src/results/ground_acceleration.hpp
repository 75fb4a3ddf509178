#pragma once
// The ground's acceleration (assembly::StructuralSystem's), which recorders and monitors add to
// the relative accelerations the equations of motion carry, for absolute ones.
#include <functional>

#include "core/types.hpp"

namespace pound::results {

struct GroundAcceleration {
  std::function<void(double time, Vector& free_dofs)> frame;  // added to a at the free DOFs
  std::function<double(Index node, int direction, double time)> support;  // of a fixed DOF

  // The absolute acceleration along `direction` of `node`, whose equation there is `equation`
  // (-1 where fixed), given this step's frame acceleration.
  double absolute(const Vector& acceleration, const Vector& frame_now, Index equation, Index node,
                  int direction, double time) const {
    return equation >= 0 ? acceleration[equation] + frame_now[equation]
                         : support(node, direction, time);
  }
};

}  // namespace pound::results
