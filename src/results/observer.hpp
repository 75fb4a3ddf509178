#pragma once
// Something that watches a run: told every accepted step (and the initial state) in order.
// Recorders, link summaries, monitors, the energy balance and verifications against exact
// solutions are observers; a run does not know which it has.
#include "integrators/integrator.hpp"

namespace pound::results {

class Observer {
 public:
  virtual ~Observer() = default;
  virtual void record(const integrators::State& state) = 0;
};

}  // namespace pound::results
