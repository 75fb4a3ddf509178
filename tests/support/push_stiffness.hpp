#pragma once
// A built model's stiffness at one node along one direction, from one small elastic push (a
// pushover of one increment to 1e-5): what the hinge tests compare with the elastic model's.
#include <gtest/gtest.h>

#include <string>

#include "assembly/pushover.hpp"
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"

namespace pound::testing {

// A push of `node` along `direction` by a load there alone, from rest to `target` in `increments`.
inline assembly::PushoverResult push(const builder::BuiltModel& model, const std::string& node,
                                     int direction, double target, int increments) {
  assembly::StructuralSystem system(model.model);
  assembly::PushoverControl control{
      .equation = system.dofs().own_equation(model.node_index.at(node), direction),
      .target = target,
      .increments = increments};
  control.pattern = Vector::Zero(system.size());
  control.pattern[control.equation] = 1.0;
  auto result = assembly::pushover(system, Vector::Zero(system.size()), control);
  EXPECT_TRUE(result.stopped.empty()) << result.stopped;
  return result;
}

inline double push_stiffness(const builder::BuiltModel& model, const std::string& node,
                             int direction) {
  const auto result = push(model, node, direction, 1e-5, 1);
  return result.curve.back().load_factor / result.curve.back().displacement;
}

}  // namespace pound::testing
