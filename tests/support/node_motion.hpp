#pragma once
// Runs a built model's transient analysis and keeps the displacements of some nodes along some
// directions at every step: what the tests of 3-D scenes compare with their plane counterparts,
// their mirror images and their summaries.
#include <string>
#include <vector>

#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "integrators/transient_analysis.hpp"

namespace pound::testing {

struct NodeMotion {
  std::vector<double> time;
  std::vector<std::vector<double>> values;  // per step, per (node, direction) asked, node-major
};

inline NodeMotion run_node_motion(const builder::BuiltModel& built,
                                  const std::vector<std::string>& nodes,
                                  const std::vector<int>& directions) {
  assembly::StructuralSystem system(built.model);
  auto integrator = builder::make_integrator(built.analysis);
  integrators::TransientAnalysis analysis(system, *integrator,
                                          builder::make_transient_settings(built.analysis));
  std::vector<std::vector<model::DofTerm>> readings;  // a tied DOF through its master's
  for (const std::string& node : nodes)
    for (const int direction : directions) {
      const auto terms = system.dofs().terms(built.node_index.at(node), direction);
      readings.emplace_back(terms.begin(), terms.end());
    }
  NodeMotion motion;
  integrators::State state;
  state.displacement = Vector::Zero(system.size());
  state.velocity = Vector::Zero(system.size());
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    motion.time.push_back(s.time);
    std::vector<double> row;
    for (const auto& reading : readings) row.push_back(model::value_of(reading, s.displacement));
    motion.values.push_back(row);
  });
  return motion;
}

}  // namespace pound::testing
