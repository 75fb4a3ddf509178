#include "integrators/transient_analysis.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "core/errors.hpp"

namespace pound {

TransientAnalysis::TransientAnalysis(SecondOrderSystem& system, Integrator& integrator,
                                     TransientSettings settings)
    : system_(system), integrator_(integrator), settings_(settings) {
  if (!(settings_.time_step > 0.0) || !std::isfinite(settings_.time_step))
    throw std::invalid_argument("time step must be positive and finite");
  if (!(settings_.time_limit >= 0.0)) throw std::invalid_argument("time limit must be >= 0");
}

TransientStatistics TransientAnalysis::run(State& state, const StepObserver& observer) {
  statistics_ = {};
  started_ = std::chrono::steady_clock::now();
  integrator_.initialize(system_, state);
  if (observer) {
    StepResult initial;
    initial.converged = true;
    observer(state, initial);
  }
  const double start = state.time;
  // Steps are counted, not accumulated, so the end time has no round-off drift.
  const double span = settings_.end_time - start;
  const long nominal_steps = static_cast<long>(std::ceil(span / settings_.time_step - 1e-9));
  for (long k = 1; k <= nominal_steps; ++k) {
    const double target = (k == nominal_steps)
                              ? settings_.end_time
                              : start + static_cast<double>(k) * settings_.time_step;
    advance(state, target - state.time, 0, observer);
  }
  return statistics_;
}

void TransientAnalysis::advance(State& state, double dt, int depth, const StepObserver& observer) {
  TransientStatistics& stats = statistics_;
  if (settings_.max_steps > 0 && stats.steps >= settings_.max_steps)
    throw SolveError(state.time,
                     fmt::format("step limit of {} steps reached", settings_.max_steps));
  // The clock is read only when a limit is set, and then every 64 steps (a few ns per step).
  if (settings_.time_limit > 0.0 && stats.steps % 64 == 0) {
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - started_;
    if (elapsed.count() > settings_.time_limit)
      throw SolveError(state.time,
                       fmt::format("time limit of {:g} s reached after {} steps ({:.3g} s)",
                                   settings_.time_limit, stats.steps, elapsed.count()));
  }
  const StepResult result = integrator_.advance(system_, state, dt, next_);
  if (result.converged) {
    system_.links().commit();
    std::swap(state, next_);
    ++stats.steps;
    stats.newton_iterations += result.iterations;
    stats.max_unbalanced_force = std::max(stats.max_unbalanced_force, result.unbalanced_force);
    if (observer) observer(state, result);
    return;
  }
  system_.links().revert();
  if (depth >= settings_.max_step_cuts)
    throw SolveError(state.time, fmt::format("{} after cutting the step {} times to dt = {:.3e}",
                                             result.failure, depth, dt));
  ++stats.step_cuts;
  const double end = state.time + dt;
  advance(state, 0.5 * dt, depth + 1, observer);
  advance(state, end - state.time, depth + 1, observer);
}

}  // namespace pound
