#pragma once
// Drives an integrator from t0 to t_end with a nominal step, cutting a step that does not
// converge in halves down to a floor, and stopping with a SolveError (time and reason) when even
// the floor fails. An unconverged step is never accepted.
#include <chrono>
#include <functional>

#include "integrators/integrator.hpp"

namespace pound {

struct TransientSettings {
  double time_step = 0.0;  // nominal dt
  double end_time = 0.0;
  int max_step_cuts = 10;   // floor: dt / 2^max_step_cuts
  long max_steps = 0;       // 0: no limit; otherwise refuse to run more accepted steps
  double time_limit = 0.0;  // wall-clock seconds; 0: no limit. The machine's, not the model's.
};

struct TransientStatistics {
  long steps = 0;              // accepted steps (including cut ones)
  long newton_iterations = 0;  // linearised corrections over all accepted steps
  long step_cuts = 0;          // times a step was halved
  double max_unbalanced_force = 0.0;
};

// Called after every accepted step (and once for the initial state, with result.iterations = 0).
using StepObserver = std::function<void(const State&, const StepResult&)>;

class TransientAnalysis {
 public:
  TransientAnalysis(SecondOrderSystem& system, Integrator& integrator, TransientSettings settings);

  // Runs from `state` (u, v, time set; completed by the integrator) to end_time.
  TransientStatistics run(State& state, const StepObserver& observer = {});
  // The statistics so far: after a SolveError, those up to the failure.
  const TransientStatistics& statistics() const { return statistics_; }

 private:
  void advance(State& state, double dt, int depth, const StepObserver& observer);

  SecondOrderSystem& system_;
  Integrator& integrator_;
  TransientSettings settings_;
  TransientStatistics statistics_;
  std::chrono::steady_clock::time_point started_;
  State next_;
};

}  // namespace pound
