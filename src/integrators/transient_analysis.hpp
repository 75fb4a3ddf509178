#pragma once
// Drives an integrator from t0 to t_end with a nominal step, cutting a step that does not
// converge in halves down to a floor, and stopping with a SolveError (time and reason) when even
// the floor fails. An unconverged step is never accepted.
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>

#include "integrators/integrator.hpp"

namespace pound::integrators {

// Adaptive time stepping for the implicit integrators. Each step's local error is estimated
// from the change of acceleration, e = dt^2/12 |a_{n+1} - a_n| (the trapezoidal rule's, as in
// Zienkiewicz & Xie 1991), against the largest displacement so far; a step with e over
// 2 x tolerance is redone shorter, and the next step is chosen so e comes near the tolerance.
// Steps are the nominal dt times a power of 2, so only a few factorisations are ever made. A
// link that closes inside a step has its contact instant located by interpolating its
// penetration: the step is redone to end there, so every contact starts on a step boundary
// whatever the step size was (Kawashima's onset error of up to one step disappears).
struct AdaptiveStepping {
  double tolerance = 1e-5;     // e / max |u|
  double min_time_step = 0.0;  // floor; a step that fails there stops the run
  double max_time_step = 0.0;  // ceiling (e.g. the record's sample interval x a few)

  // The shortest and longest step a run with this nominal step takes. Steps are nominal x 2^k,
  // so these are the grid's steps nearest inside min_time_step and max_time_step (0 above:
  // nominal / 256 and 16 x nominal): a bound between two grid steps is never reached, and a run
  // that cut or rejected steps until it got there would never stop. None inside both bounds
  // (a grid step between them): the shortest comes out above the longest.
  // (The powers from differences of logarithms and ldexp: a bound of 1e308 over a step of 0.002
  // overflows as a quotient, not as the step 0.002 x 2^1032 it gives.)
  double shortest(double nominal) const {
    const double floor = min_time_step > 0.0 ? min_time_step : nominal / 256.0;
    return std::ldexp(nominal,
                      static_cast<int>(std::ceil(std::log2(floor) - std::log2(nominal) - 1e-9)));
  }
  double longest(double nominal) const {
    const double ceiling = max_time_step > 0.0 ? max_time_step : 16.0 * nominal;
    return std::ldexp(nominal,
                      static_cast<int>(std::floor(std::log2(ceiling) - std::log2(nominal) + 1e-9)));
  }
};

// The steps of a fixed-step run over `span`: the nominal step's count, the last one perhaps
// shorter, and none added for a quotient a few ulps above a whole number (0.004 / 1e-6 is
// 4000.0000000000005: 4000 steps).
inline double fixed_step_count(double span, double time_step) {
  return std::ceil(span / time_step - 1e-9);
}

struct TransientSettings {
  double time_step = 0.0;  // nominal dt (with adaptive stepping: the first, and the grid)
  double end_time = 0.0;
  int max_step_cuts = 10;   // floor: dt / 2^max_step_cuts
  long max_steps = 0;       // 0: no limit; otherwise refuse to run more accepted steps
  double time_limit = 0.0;  // wall-clock seconds; 0: no limit. The machine's, not the model's.
  std::optional<AdaptiveStepping> adaptive;
};

struct TransientStatistics {
  long steps = 0;              // accepted steps (including cut ones)
  long newton_iterations = 0;  // linearised corrections over all accepted steps
  long step_cuts = 0;          // times a step was halved
  double max_unbalanced_force = 0.0;
  // Adaptive stepping only:
  long rejected_steps = 0;    // redone shorter because of their error estimate
  long located_contacts = 0;  // steps redone to end where a link closes
  double smallest_step = 0.0, largest_step = 0.0;
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
  class AdaptiveRun;
  // One step of dt ending at `end` (the time the accepted state gets), halved on failure.
  void advance(State& state, double dt, double end, int depth, const StepObserver& observer);
  // The trial in next_ becomes the state, and counts.
  void accept(State& state, const StepResult& result);
  // `cutting`: inside a cut step, whose attempts may each take long (the clock is then read at
  // every attempt, not every 64 steps).
  void check_limits(const State& state, bool cutting = false);

  SecondOrderSystem& system_;
  Integrator& integrator_;
  TransientSettings settings_;
  TransientStatistics statistics_;
  std::chrono::steady_clock::time_point started_;
  State next_;
};

}  // namespace pound::integrators
