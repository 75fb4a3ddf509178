#include "integrators/transient_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/errors.hpp"

namespace pound::integrators {

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
  if (settings_.adaptive) {
    run_adaptive(state, observer);
    return statistics_;
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

void TransientAnalysis::check_limits(const State& state) {
  const TransientStatistics& stats = statistics_;
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
}

void TransientAnalysis::advance(State& state, double dt, int depth, const StepObserver& observer) {
  TransientStatistics& stats = statistics_;
  check_limits(state);
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

namespace {

double masked_magnitude(const Vector& x, const Vector& mask) {
  return x.size() ? x.cwiseAbs().cwiseProduct(mask).maxCoeff() : 0.0;
}

// max |a - b| over the masked DOFs, without a temporary inside the time loop.
double masked_difference(const Vector& a, const Vector& b, const Vector& mask) {
  return a.size() ? (a - b).cwiseAbs().cwiseProduct(mask).maxCoeff() : 0.0;
}

// The contact instant inside a step, as a fraction of it, over the link rows that were open (no
// force) and close in the trial. Before the contact the row moves freely, so its penetration is
// extrapolated from the start of the step, delta_n + rate_n tau + accel_n tau^2 / 2 = 0 (the
// trial's end value already feels the contact force and would put the instant too late); where
// that has no root in the step, the trial's values are interpolated linearly.
double closing_fraction(const State& from, const State& to, const Vector& rate,
                        const Vector& acceleration, double step) {
  double theta = 1.0;
  for (Index r = 0; r < to.link_penetration.size(); ++r) {
    const double before = from.link_penetration[r], after = to.link_penetration[r];
    if (!(from.link_force[r] == 0.0 && before <= 0.0 && after > 0.0 && to.link_force[r] != 0.0))
      continue;
    double fraction = -before / (after - before);  // linear, when the extrapolation fails
    const double a = 0.5 * acceleration[r] * step * step, b = rate[r] * step, c = before;
    // Smallest root in (0, 1] of a x^2 + b x + c, in the form that does not cancel.
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant >= 0.0 && (a != 0.0 || b != 0.0)) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
      double earliest = INFINITY;
      for (const double root : {q != 0.0 ? c / q : -1.0, a != 0.0 ? q / a : -1.0})
        if (root > 0.0 && root <= 1.0) earliest = std::min(earliest, root);
      if (std::isfinite(earliest)) fraction = earliest;
    }
    theta = std::min(theta, fraction);
  }
  return theta;
}

}  // namespace

void TransientAnalysis::run_adaptive(State& state, const StepObserver& observer) {
  const AdaptiveStepping& adaptive = *settings_.adaptive;
  TransientStatistics& stats = statistics_;
  const double base = settings_.time_step;
  const double floor = adaptive.min_time_step > 0.0 ? adaptive.min_time_step : base / 256.0;
  const double ceiling = adaptive.max_time_step > 0.0 ? adaptive.max_time_step : 16.0 * base;
  // Steps on the grid base x 2^k keep the integrator's factorisations few.
  auto on_grid = [&](double dt) {
    const double k = std::round(std::log2(dt / base));
    double snapped = base * std::exp2(k);
    while (snapped > ceiling * (1.0 + 1e-12)) snapped *= 0.5;
    while (snapped < floor * (1.0 - 1e-12)) snapped *= 2.0;
    return snapped;
  };
  double dt = on_grid(base);
  // The DOFs that carry mass (all of them when the mass is not lumped).
  Vector mask = Vector::Ones(system_.size());
  if (const Vector* mass = system_.lumped_mass())
    mask = (mass->array() > 0.0).select(Vector::Ones(mass->size()), 0.0);
  double displacement_scale = masked_magnitude(state.displacement, mask);
  Vector start_rate, start_acceleration;  // of the link rows at the start of a step
  stats.smallest_step = INFINITY;
  // The trial in next_ becomes the state.
  auto accept = [&](double step, const StepResult& result) {
    system_.links().commit();
    std::swap(state, next_);
    ++stats.steps;
    stats.newton_iterations += result.iterations;
    stats.max_unbalanced_force = std::max(stats.max_unbalanced_force, result.unbalanced_force);
    stats.smallest_step = std::min(stats.smallest_step, step);
    stats.largest_step = std::max(stats.largest_step, step);
    displacement_scale = std::max(displacement_scale, masked_magnitude(state.displacement, mask));
    if (observer) observer(state, result);
  };
  const double end = settings_.end_time;
  while (end - state.time > 1e-12 * std::max(1.0, std::abs(end))) {
    check_limits(state);
    double step = std::min(dt, end - state.time);
    // A sliver left before the end is taken with this step.
    if (end - state.time - step < 0.01 * step) step = end - state.time;
    const StepResult result = integrator_.advance(system_, state, step, next_);
    if (!result.converged) {
      system_.links().revert();
      if (step <= floor * (1.0 + 1e-12))
        throw SolveError(state.time,
                         fmt::format("{} at the smallest step dt = {:.3e}", result.failure, step));
      ++stats.step_cuts;
      dt = on_grid(std::max(floor, 0.5 * step));
      continue;
    }
    // A link closing well inside the step: redo the step to end where it closes.
    system_.links().project(state.velocity, start_rate);
    system_.links().project(state.acceleration, start_acceleration);
    const double theta = closing_fraction(state, next_, start_rate, start_acceleration, step);
    if (theta > 0.01 && theta < 0.99 && theta * step > floor) {
      system_.links().revert();
      ++stats.located_contacts;
      // Land just short of the contact, so the link is still open there and the next step
      // starts the contact at its beginning.
      const double to_contact_step = theta * (1.0 - 1e-9) * step;
      const StepResult to_contact = integrator_.advance(system_, state, to_contact_step, next_);
      if (to_contact.converged) {
        accept(to_contact_step, to_contact);
        dt = on_grid(std::max(floor, 0.5 * dt));  // the contact begins: look closer
        continue;
      }
      system_.links().revert();
      dt = on_grid(std::max(floor, 0.5 * step));
      continue;
    }
    // Local error estimate against the displacements seen so far, over the DOFs with mass
    // (a massless DOF's "acceleration" is whatever keeps it in equilibrium, and rotations are in
    // other units).
    const double scale = std::max({displacement_scale, masked_magnitude(next_.displacement, mask),
                                   masked_difference(next_.displacement, state.displacement, mask),
                                   std::numeric_limits<double>::min()});
    const double error = step * step / 12.0 *
                         masked_difference(next_.acceleration, state.acceleration, mask) / scale;
    if (error > 2.0 * adaptive.tolerance && step > floor * (1.0 + 1e-12)) {
      system_.links().revert();
      ++stats.rejected_steps;
      // At least halved: rounding to the grid must not give the same step back.
      dt = std::min(on_grid(std::max(
                        floor, step * std::max(0.25, 0.9 * std::cbrt(adaptive.tolerance / error)))),
                    on_grid(std::max(floor, 0.5 * step)));
      continue;
    }
    accept(step, result);
    const double growth = error > 0.0 ? 0.9 * std::cbrt(adaptive.tolerance / error) : 2.0;
    dt = on_grid(std::clamp(step * growth, 0.5 * step, 2.0 * step));
  }
  if (stats.steps == 0) stats.smallest_step = 0.0;
}

}  // namespace pound::integrators
