#include "results/energy_balance.hpp"

#include <algorithm>
#include <cmath>

namespace pound::results {

double EnergyTerms::largest_term() const {
  return std::max({std::abs(input), kinetic, strain, std::abs(damping), std::abs(links), initial});
}

double EnergyTerms::created_fraction() const {
  const double largest = largest_term();
  const double residual = kinetic + strain + damping + links - input - initial;
  return largest > 0.0 ? residual / largest : 0.0;
}

double EnergyTerms::link_created_fraction() const {
  const double largest = largest_term();
  return largest > 0.0 && links < 0.0 ? -links / largest : 0.0;
}

double EnergyTerms::balance_error() const { return std::abs(created_fraction()); }

void EnergyBalance::record(const integrators::State& state) {
  const Index n = system_.size();
  external_ = Vector::Zero(n);
  if (system_.has_external_force()) system_.external_force(state.time, external_);
  system_.multiply_mass(state.velocity, work_);
  terms_.kinetic = 0.5 * state.velocity.dot(work_);
  system_.multiply_stiffness(state.displacement, work_);
  terms_.strain = 0.5 * state.displacement.dot(work_);
  if (!started_) {
    terms_.initial = terms_.kinetic + terms_.strain;
    started_ = true;
  } else {
    const Vector step = state.displacement - previous_.displacement;
    terms_.input += 0.5 * step.dot(external_ + previous_external_);
    if (system_.has_damping()) {
      average_ = 0.5 * (state.velocity + previous_.velocity);
      system_.multiply_damping(average_, work_);
      terms_.damping += step.dot(work_);
    }
    if (state.link_force.size() > 0) {
      // Work of the link forces on the structure (B du): with moving supports the links also
      // deform by the supports' motion, whose work is not the structure's.
      system_.links().project(step, work_);
      terms_.links += 0.5 * (state.link_force + previous_.link_force).dot(work_);
    }
  }
  worst_ = std::max(worst_, terms_.balance_error());
  previous_external_.swap(external_);
  previous_.displacement = state.displacement;
  previous_.velocity = state.velocity;
  previous_.link_force = state.link_force;
  previous_.link_penetration = state.link_penetration;
}

}  // namespace pound::results
