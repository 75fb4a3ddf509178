#include "integrators/transient_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/errors.hpp"
#include "core/interrupt.hpp"

namespace pound::integrators {

// One adaptive run: the step size it tries next and what the error estimate measures against.
class TransientAnalysis::AdaptiveRun {
 public:
  AdaptiveRun(TransientAnalysis& analysis, State& state, const StepObserver& observer);
  void run();

 private:
  // Steps on the grid base x 2^k keep the integrator's factorisations few.
  double on_grid(double dt) const;
  // The step tried next: dt_, or what is left of the run when that is at most a sliver more.
  double next_step() const;
  static constexpr double kSliver = 0.01;  // of a step
  // A step that cannot be shortened: the floor, or the floor with the run's last sliver.
  bool at_floor(double step) const;
  // The step failed: half of it next, unless it is at the floor already.
  void cut(double step, const StepResult& result);
  // A link closing well inside the accepted trial: redo the step to end where it closes. Returns
  // whether it did (the trial is then dropped).
  bool redo_to_contact(double step);
  double local_error(double step) const;
  // The error is too large: a shorter step next, at least halved.
  void reject(double step, double error);
  // The trial in next_ becomes the state.
  void accept(double step, const StepResult& result);

  TransientAnalysis& analysis_;
  const AdaptiveStepping& adaptive_;
  State& state_;
  const StepObserver& observer_;
  double base_, floor_, ceiling_;           // the nominal step and the bounds of dt
  double dt_;                               // the step tried next
  Vector mask_;                             // of the DOFs with mass
  double displacement_scale_;               // max |u| so far over them
  Vector start_rate_, start_acceleration_;  // of the link rows at the start of a step
};

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
  integrator_.initialize(system_, state, settings_.time_step);
  if (observer) {
    StepResult initial;
    initial.converged = true;
    observer(state, initial);
  }
  if (settings_.adaptive) {
    AdaptiveRun(*this, state, observer).run();
    return statistics_;
  }
  const double start = state.time;
  // Steps are counted, not accumulated, so the end time has no round-off drift.
  const double span = settings_.end_time - start;
  const long nominal_steps = static_cast<long>(fixed_step_count(span, settings_.time_step));
  // Every step is the nominal dt exactly (the last one may be shorter), with the time set to
  // the step's end: differences of targets vary in their last bits, and each distinct dt would
  // cost a factorisation of the implicit integrators.
  for (long k = 1; k <= nominal_steps; ++k) {
    const double target = (k == nominal_steps)
                              ? settings_.end_time
                              : start + static_cast<double>(k) * settings_.time_step;
    const double remaining = target - state.time;
    const double dt = std::abs(remaining - settings_.time_step) <= 1e-9 * settings_.time_step
                          ? settings_.time_step
                          : remaining;
    advance(state, dt, target, 0, observer);
  }
  return statistics_;
}

void TransientAnalysis::check_limits(const State& state, bool cutting) {
  throw_if_interrupted();  // Ctrl-C or SIGTERM: unwind, so no half-written result is left
  const TransientStatistics& stats = statistics_;
  if (settings_.max_steps > 0 && stats.steps >= settings_.max_steps)
    throw SolveError(state.time,
                     fmt::format("step limit of {} steps reached", settings_.max_steps));
  // The clock is read only when a limit is set, and then every 64 steps (a few ns per step) and
  // at every attempt of a cut step.
  if (settings_.time_limit > 0.0 && (stats.steps % 64 == 0 || cutting)) {
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - started_;
    if (elapsed.count() > settings_.time_limit)
      throw SolveError(state.time,
                       fmt::format("time limit of {:g} s reached after {} steps ({:.3g} s)",
                                   settings_.time_limit, stats.steps, elapsed.count()));
  }
}

void TransientAnalysis::accept(State& state, const StepResult& result) {
  TransientStatistics& stats = statistics_;
  system_.links().commit();
  swap(state, next_);
  ++stats.steps;
  stats.newton_iterations += result.iterations;
  stats.max_unbalanced_force = std::max(stats.max_unbalanced_force, result.unbalanced_force);
}

void TransientAnalysis::advance(State& state, double dt, double end, int depth,
                                const StepObserver& observer) {
  TransientStatistics& stats = statistics_;
  check_limits(state, depth > 0);
  const StepResult result = integrator_.advance(system_, state, dt, end, next_);
  if (result.converged) {
    accept(state, result);
    if (observer) observer(state, result);
    return;
  }
  system_.links().revert();
  if (depth >= settings_.max_step_cuts)
    throw SolveError(state.time, fmt::format("{} after cutting the step {} times to dt = {:.3e}",
                                             result.failure, depth, dt));
  ++stats.step_cuts;
  advance(state, 0.5 * dt, state.time + 0.5 * dt, depth + 1, observer);
  advance(state, 0.5 * dt, end, depth + 1, observer);
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

// The DOFs that carry mass (all of them when the mass is not lumped), as ones in a mask.
Vector mass_mask(const SecondOrderSystem& system) {
  Vector mask = Vector::Ones(system.size());
  if (const Vector* mass = system.lumped_mass())
    mask = (mass->array() > 0.0).select(Vector::Ones(mass->size()), 0.0);
  return mask;
}

}  // namespace

TransientAnalysis::AdaptiveRun::AdaptiveRun(TransientAnalysis& analysis, State& state,
                                            const StepObserver& observer)
    : analysis_(analysis),
      adaptive_(*analysis.settings_.adaptive),
      state_(state),
      observer_(observer),
      base_(analysis.settings_.time_step),
      floor_(adaptive_.shortest(base_)),
      ceiling_(adaptive_.longest(base_)),
      dt_(on_grid(base_)),
      mask_(mass_mask(analysis.system_)),
      displacement_scale_(masked_magnitude(state.displacement, mask_)) {}

void TransientAnalysis::AdaptiveRun::run() {
  TransientStatistics& stats = analysis_.statistics_;
  stats.smallest_step = INFINITY;
  const double end = analysis_.settings_.end_time;
  while (end - state_.time > 1e-12 * std::max(1.0, std::abs(end))) {
    analysis_.check_limits(state_);
    const double step = next_step();
    const StepResult result = analysis_.integrator_.advance(analysis_.system_, state_, step,
                                                            state_.time + step, analysis_.next_);
    if (!result.converged) {
      cut(step, result);
      continue;
    }
    if (redo_to_contact(step)) continue;
    const double error = local_error(step);
    if (error > 2.0 * adaptive_.tolerance && !at_floor(step)) {
      reject(step, error);
      continue;
    }
    accept(step, result);
    const double growth = error > 0.0 ? 0.9 * std::cbrt(adaptive_.tolerance / error) : 2.0;
    dt_ = on_grid(std::clamp(step * growth, 0.5 * step, 2.0 * step));
  }
  if (stats.steps == 0) stats.smallest_step = 0.0;
}

double TransientAnalysis::AdaptiveRun::on_grid(double dt) const {
  const double k = std::round(std::log2(dt / base_));
  double snapped = base_ * std::exp2(k);
  while (snapped > ceiling_ * (1.0 + 1e-12)) snapped *= 0.5;
  while (snapped < floor_ * (1.0 - 1e-12)) snapped *= 2.0;
  return snapped;
}

double TransientAnalysis::AdaptiveRun::next_step() const {
  const double end = analysis_.settings_.end_time;
  double step = std::min(dt_, end - state_.time);
  // A sliver left before the end is taken with this step.
  if (end - state_.time - step < kSliver * step) step = end - state_.time;
  return step;
}

bool TransientAnalysis::AdaptiveRun::at_floor(double step) const {
  // The last step may be the floor with a sliver: it cannot be cut or shortened either (it was
  // rejected and retried for ever, 4e-11 s above the floor, at the end of a run).
  return step <= floor_ * (1.0 + kSliver) * (1.0 + 1e-12);
}

void TransientAnalysis::AdaptiveRun::cut(double step, const StepResult& result) {
  analysis_.system_.links().revert();
  if (at_floor(step))
    throw SolveError(state_.time,
                     fmt::format("{} at the smallest step dt = {:.3e}", result.failure, step));
  ++analysis_.statistics_.step_cuts;
  dt_ = on_grid(std::max(floor_, 0.5 * step));
}

bool TransientAnalysis::AdaptiveRun::redo_to_contact(double step) {
  LinkSet& links = analysis_.system_.links();
  links.project(state_.velocity, start_rate_);
  links.project(state_.acceleration, start_acceleration_);
  const double theta =
      closing_fraction(state_, analysis_.next_, start_rate_, start_acceleration_, step);
  if (!(theta > 0.01 && theta < 0.99 && theta * step > floor_)) return false;
  links.revert();
  ++analysis_.statistics_.located_contacts;
  // Land just short of the contact, so the link is still open there and the next step
  // starts the contact at its beginning.
  const double to_contact_step = theta * (1.0 - 1e-9) * step;
  const StepResult to_contact = analysis_.integrator_.advance(
      analysis_.system_, state_, to_contact_step, state_.time + to_contact_step, analysis_.next_);
  if (to_contact.converged) {
    accept(to_contact_step, to_contact);
    dt_ = on_grid(std::max(floor_, 0.5 * dt_));  // the contact begins: look closer
    return true;
  }
  links.revert();
  dt_ = on_grid(std::max(floor_, 0.5 * step));
  return true;
}

double TransientAnalysis::AdaptiveRun::local_error(double step) const {
  // Local error estimate against the displacements seen so far, over the DOFs with mass
  // (a massless DOF's "acceleration" is whatever keeps it in equilibrium, and rotations are in
  // other units).
  const State& next = analysis_.next_;
  const double scale = std::max({displacement_scale_, masked_magnitude(next.displacement, mask_),
                                 masked_difference(next.displacement, state_.displacement, mask_),
                                 std::numeric_limits<double>::min()});
  return step * step / 12.0 * masked_difference(next.acceleration, state_.acceleration, mask_) /
         scale;
}

void TransientAnalysis::AdaptiveRun::reject(double step, double error) {
  analysis_.system_.links().revert();
  ++analysis_.statistics_.rejected_steps;
  // At least halved: rounding to the grid must not give the same step back.
  dt_ = std::min(on_grid(std::max(
                     floor_, step * std::max(0.25, 0.9 * std::cbrt(adaptive_.tolerance / error)))),
                 on_grid(std::max(floor_, 0.5 * step)));
}

void TransientAnalysis::AdaptiveRun::accept(double step, const StepResult& result) {
  TransientStatistics& stats = analysis_.statistics_;
  analysis_.accept(state_, result);
  stats.smallest_step = std::min(stats.smallest_step, step);
  stats.largest_step = std::max(stats.largest_step, step);
  displacement_scale_ = std::max(displacement_scale_, masked_magnitude(state_.displacement, mask_));
  if (observer_) observer_(state_, result);
}

}  // namespace pound::integrators
