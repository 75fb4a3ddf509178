#include "results/energy_balance.hpp"

#include <algorithm>
#include <cmath>

namespace pound::results {

double EnergyTerms::largest_term() const {
  return std::max(
      {std::abs(input), kinetic, strain, std::abs(damping), std::abs(links), initial, round_off});
}

double EnergyTerms::residual() const {
  return kinetic + strain + damping + links - input - initial;
}

double EnergyTerms::created_fraction() const {
  const double largest = largest_term();
  return largest > 0.0 ? residual() / largest : 0.0;
}

double EnergyTerms::link_created_fraction() const {
  const double largest = largest_term();
  return largest > 0.0 && links < 0.0 ? -links / largest : 0.0;
}

double EnergyTerms::balance_error() const {
  const double largest = largest_term();
  return largest > 0.0 ? std::abs(residual() + algorithmic) / largest : 0.0;
}

double EnergyBalance::step_load_energy(double dt) {
  const Vector* mass = system_.lumped_mass();
  if (!mass || external_.size() != mass->size()) return 0.0;
  if (inverse_mass_.size() != mass->size())  // once: no division per step
    inverse_mass_ = mass->unaryExpr([](double m) { return m > 0.0 ? 1.0 / m : 0.0; });
  return 0.5 * dt * dt * external_.cwiseAbs2().dot(inverse_mass_);
}

double EnergyBalance::mass_norm(const Vector& acceleration) {
  system_.multiply_mass(acceleration, work_);
  return acceleration.dot(work_);
}

void EnergyBalance::set_step_forces(const std::vector<char>& by_row) {
  step_force_weight_ = Vector::Zero(static_cast<Index>(by_row.size()));
  bool any = false;
  for (std::size_t r = 0; r < by_row.size(); ++r) {
    step_force_weight_[static_cast<Index>(r)] = by_row[r] ? 1.0 : 0.0;
    any = any || by_row[r];
  }
  if (!any) step_force_weight_.resize(0);
}

void EnergyBalance::record(const integrators::State& state) {
  const Index n = system_.size();
  if (system_.has_external_force())
    system_.external_force(state.time, external_);
  else
    external_.setZero(n);
  system_.multiply_mass(state.velocity, work_);
  terms_.kinetic = 0.5 * state.velocity.dot(work_);
  system_.multiply_stiffness(state.displacement, stiffness_force_);
  terms_.strain = 0.5 * state.displacement.dot(stiffness_force_);
  const bool algorithmic = acceleration_energy_ != 0.0 && state.acceleration.size() == n;
  if (!started_) {
    terms_.initial = terms_.kinetic + terms_.strain;
    if (algorithmic) initial_acceleration_norm_ = mass_norm(state.acceleration);
    started_ = true;
  } else {
    if (algorithmic) {
      const double dt = state.time - previous_.time;
      terms_.algorithmic = acceleration_energy_ * dt * dt *
                           (mass_norm(state.acceleration) - initial_acceleration_norm_);
    }
    // Sampled: a floor needs no exact maximum, and on the smallest models (two DOFs) taking it
    // every step cost 8 % of the solve.
    if (recorded_steps_++ % kRoundOffStride == 0)
      terms_.round_off =
          std::max(terms_.round_off, 1e-9 * step_load_energy(state.time - previous_.time));
    step_ = state.displacement - previous_.displacement;
    const Vector& step = step_;
    terms_.input += 0.5 * step.dot(external_ + previous_external_);
    if (system_.has_damping()) {
      average_ = 0.5 * (state.velocity + previous_.velocity);
      if (const auto rayleigh = system_.rayleigh()) {
        system_.multiply_mass(average_, work_);
        terms_.damping += rayleigh->mass_coefficient * step.dot(work_) +
                          rayleigh->stiffness_coefficient *
                              average_.dot(stiffness_force_ - previous_stiffness_force_);
      } else {
        system_.multiply_damping(average_, work_);
        terms_.damping += step.dot(work_);
      }
    }
    if (state.link_force.size() > 0) {
      // Work of the link forces on the structure (B du): with moving supports the links also
      // deform by the supports' motion, whose work is not the structure's.
      system_.links().project(step, link_step_);
      average_force_ = 0.5 * (state.link_force + previous_.link_force);
      if (step_force_weight_.size() > 0)
        average_force_ +=
            0.5 * step_force_weight_.cwiseProduct(state.link_force - previous_.link_force);
      terms_.links += average_force_.dot(link_step_);
    }
  }
  worst_ = std::max(worst_, terms_.balance_error());
  previous_external_.swap(external_);
  previous_stiffness_force_.swap(stiffness_force_);
  previous_.time = state.time;
  previous_.displacement = state.displacement;
  previous_.velocity = state.velocity;
  previous_.link_force = state.link_force;
  previous_.link_penetration = state.link_penetration;
}

}  // namespace pound::results
