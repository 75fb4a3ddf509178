#pragma once
// A built model's stiffness at one node along one direction, from one small elastic push (a
// pushover of one increment to 1e-5): what the hinge tests compare with the elastic model's.
#include <gtest/gtest.h>

#include <string>

#include "assembly/pushover.hpp"
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"

namespace pound::testing {

inline double push_stiffness(const builder::BuiltModel& model, const std::string& node,
                             int direction) {
  assembly::StructuralSystem system(model.model);
  assembly::PushoverControl control{
      .equation = system.dofs().own_equation(model.node_index.at(node), direction),
      .target = 1e-5,
      .increments = 1};
  control.pattern = Vector::Zero(system.size());
  control.pattern[control.equation] = 1.0;
  const auto result = assembly::pushover(system, Vector::Zero(system.size()), control);
  EXPECT_TRUE(result.stopped.empty()) << result.stopped;
  return result.curve.back().load_factor / result.curve.back().displacement;
}

}  // namespace pound::testing
