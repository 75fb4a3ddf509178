#include "results/energy_balance.hpp"

#include <algorithm>
#include <cmath>

#include "core/packets.hpp"

namespace pound::results {

double EnergyTerms::largest_term() const {
  return std::max({std::abs(input), kinetic, strain, std::abs(damping), std::abs(links), initial,
                   round_off, peak});
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

namespace {

// The sums of one step's energy terms over the DOFs, in one pass (lumped mass): four at a time in
// packets, the rest one by one, each sum then added across its packet.
struct StepSums {
  double kinetic = 0.0;            // sum m v^2
  double strain = 0.0;             // sum u K u
  double input = 0.0;              // sum du (f + f_n)
  double mass_damping = 0.0;       // sum a0 du m (v + v_n)
  double stiffness_damping = 0.0;  // sum a1 (v + v_n) (K u - K u_n)
  double damping = 0.0;            // sum du (C v_avg), when C is assembled
};

struct StepVectors {
  const double* mass;
  const double* u;
  const double* v;
  const double* stiffness_force;
  const double* external;
  const double* previous_u;
  const double* previous_v;
  const double* previous_stiffness_force;
  const double* previous_external;
  const double* damping_force;          // C v_avg, or nullptr
  const double* mass_coefficient;       // a0 of Rayleigh damping by DOF, or nullptr
  const double* stiffness_coefficient;  // its a1
  double* step;                         // du, written
};

double sum_of(Packet4 packet) { return (packet[0] + packet[1]) + (packet[2] + packet[3]); }

StepSums step_sums(Index n, const StepVectors& x) {
  Packet4 kinetic{}, strain{}, input{}, mass_damping{}, stiffness_damping{}, damping{};
  const Index packed = n / 4 * 4;
  for (Index i = 0; i < packed; i += 4) {
    const Packet4 v = load_packet(x.v + i), u = load_packet(x.u + i);
    const Packet4 mass = load_packet(x.mass + i), stiffness = load_packet(x.stiffness_force + i);
    const Packet4 step = u - load_packet(x.previous_u + i);
    const Packet4 velocities = v + load_packet(x.previous_v + i);
    store_packet(step, x.step + i);
    kinetic = multiply_add(mass * v, v, kinetic);
    strain = multiply_add(u, stiffness, strain);
    input = multiply_add(step, load_packet(x.external + i) + load_packet(x.previous_external + i),
                         input);
    if (x.mass_coefficient) {
      mass_damping =
          multiply_add(load_packet(x.mass_coefficient + i) * step * mass, velocities, mass_damping);
      stiffness_damping =
          multiply_add(load_packet(x.stiffness_coefficient + i) * velocities,
                       stiffness - load_packet(x.previous_stiffness_force + i), stiffness_damping);
    }
    if (x.damping_force) damping = multiply_add(step, load_packet(x.damping_force + i), damping);
  }
  StepSums sums{sum_of(kinetic),           sum_of(strain), sum_of(input), sum_of(mass_damping),
                sum_of(stiffness_damping), sum_of(damping)};
  for (Index i = packed; i < n; ++i) {
    const double step = x.u[i] - x.previous_u[i], velocities = x.v[i] + x.previous_v[i];
    x.step[i] = step;
    sums.kinetic = multiply_add(x.mass[i] * x.v[i], x.v[i], sums.kinetic);
    sums.strain = multiply_add(x.u[i], x.stiffness_force[i], sums.strain);
    sums.input = multiply_add(step, x.external[i] + x.previous_external[i], sums.input);
    if (x.mass_coefficient) {
      sums.mass_damping =
          multiply_add(x.mass_coefficient[i] * step * x.mass[i], velocities, sums.mass_damping);
      sums.stiffness_damping = multiply_add(x.stiffness_coefficient[i] * velocities,
                                            x.stiffness_force[i] - x.previous_stiffness_force[i],
                                            sums.stiffness_damping);
    }
    if (x.damping_force) sums.damping = multiply_add(step, x.damping_force[i], sums.damping);
  }
  return sums;
}

}  // namespace

void EnergyBalance::record(const integrators::State& state) {
  const Index n = system_.size();
  if (system_.has_external_force())
    system_.external_force(state.time, external_);
  else
    external_.setZero(n);
  system_.multiply_stiffness(state.displacement, stiffness_force_);
  has_extra_link_work_ = false;
  const Vector* mass = system_.lumped_mass();
  const bool algorithmic = acceleration_energy_ != 0.0 && state.acceleration.size() == n;
  if (started_ && mass && !algorithmic)
    record_step_lumped(state, *mass);
  else
    record_general(state, algorithmic);
  terms_.peak = terms_.largest_term();
  worst_residual_ = std::max(worst_residual_, std::abs(terms_.residual() + terms_.algorithmic));
  previous_external_.swap(external_);
  previous_stiffness_force_.swap(stiffness_force_);
  previous_.time = state.time;
  previous_.displacement = state.displacement;
  previous_.velocity = state.velocity;
  previous_.link_force = state.link_force;
  if (link_motion_) previous_.link_penetration = state.link_penetration;
  if (predicted_damping_) {
    // The first step's damping took v_0 itself (the start's acceleration is from C v_0).
    if (previous_damping_velocity_.size() == 0) damping_velocity_ = state.velocity;
    previous_damping_velocity_.swap(damping_velocity_);
    previous_acceleration_ = state.acceleration;
  }
}

void EnergyBalance::record_step_lumped(const integrators::State& state, const Vector& mass) {
  sample_round_off(state.time - previous_.time);
  const Index n = system_.size();
  const bool damped = system_.has_damping();
  const integrators::SecondOrderSystem::Rayleigh* rayleigh = damped ? system_.rayleigh() : nullptr;
  if (damped && !rayleigh) {
    average_ = 0.5 * (state.velocity + previous_.velocity);
    system_.multiply_damping(average_, work_);
  }
  step_.resize(n);
  const StepSums sums =
      step_sums(n, {mass.data(), state.displacement.data(), state.velocity.data(),
                    stiffness_force_.data(), external_.data(), previous_.displacement.data(),
                    previous_.velocity.data(), previous_stiffness_force_.data(),
                    previous_external_.data(), damped && !rayleigh ? work_.data() : nullptr,
                    rayleigh ? rayleigh->mass_coefficient.data() : nullptr,
                    rayleigh ? rayleigh->stiffness_coefficient.data() : nullptr, step_.data()});
  terms_.kinetic = 0.5 * sums.kinetic;
  terms_.strain = 0.5 * sums.strain;
  terms_.input += 0.5 * sums.input;
  if (rayleigh)
    terms_.damping += 0.5 * (sums.mass_damping + sums.stiffness_damping);
  else if (damped)
    terms_.damping += sums.damping;
  add_link_work(state);
}

void EnergyBalance::sample_round_off(double dt) {
  // Sampled: a floor needs no exact maximum, and on the smallest models (two DOFs) taking it
  // every step cost 8 % of the solve.
  if (recorded_steps_++ % kRoundOffStride == 0)
    terms_.round_off = std::max(terms_.round_off, 1e-9 * step_load_energy(dt));
}

void EnergyBalance::add_link_work(const integrators::State& state) {
  if (state.link_force.size() == 0) return;
  // Work of the link forces on the structure (B du). With moving supports (or belts) the links
  // also deform by the supports' motion: the links then take their whole work F d(delta), and
  // what the supports did through them (F (d(delta) - B du)) is input, so that the links' term
  // holds what yielding links dissipate and a link driven by supports alone balances. Each row
  // by the trapezoidal rule, or an impulse's by add_impulse_work.
  system_.links().project(step_, link_step_);
  const bool moving = link_motion_ && previous_.link_penetration.size() == link_step_.size();
  double work = 0.0, whole = 0.0;
  if (step_force_weight_.size() > 0) {
    add_impulse_work(state, moving, work, whole);
  } else {
    for (Index r = 0; r < link_step_.size(); ++r) {
      const double average = 0.5 * (state.link_force[r] + previous_.link_force[r]);
      work = multiply_add(average, link_step_[r], work);
      if (moving)
        whole =
            multiply_add(average, state.link_penetration[r] - previous_.link_penetration[r], whole);
    }
  }
  if (!moving) {
    terms_.links += work;
    return;
  }
  terms_.links += whole;
  terms_.input += whole - work;
}

void EnergyBalance::record_general(const integrators::State& state, bool algorithmic) {
  system_.multiply_mass(state.velocity, work_);
  terms_.kinetic = 0.5 * state.velocity.dot(work_);
  terms_.strain = 0.5 * state.displacement.dot(stiffness_force_);
  if (!started_) {
    terms_.initial = terms_.kinetic + terms_.strain;
    if (algorithmic) initial_acceleration_norm_ = mass_norm(state.acceleration);
    started_ = true;
    return;
  }
  const bool first_step = recorded_steps_ == 0;
  if (algorithmic) {
    // c dt^2 a^T M a of the state less the start's: the start's is fixed at the first step's dt
    // (a run's last step, shorter to end at its duration, took it at its own and scaled it: a
    // launched mass damped at 0.32 in its highest mode read 4 % of balance error at its end).
    const double dt = state.time - previous_.time;
    if (first_step)
      initial_algorithmic_ = -acceleration_energy_ * dt * dt * initial_acceleration_norm_;
    terms_.algorithmic = acceleration_energy_ * dt * dt * mass_norm(state.acceleration) +
                         initial_algorithmic_ + start_algorithmic_;
  }
  sample_round_off(state.time - previous_.time);
  step_ = state.displacement - previous_.displacement;
  terms_.input += 0.5 * step_.dot(external_ + previous_external_);
  if (system_.has_damping()) {
    if (predicted_damping_) {  // C v*, v* = v_n + dt a_n, at each end of the step
      damping_velocity_ =
          previous_.velocity + (state.time - previous_.time) * previous_acceleration_;
      average_ = 0.5 * (damping_velocity_ + previous_damping_velocity_);
    } else {
      average_ = 0.5 * (state.velocity + previous_.velocity);
    }
    if (const auto* rayleigh = system_.rayleigh()) {
      // du^T diag(a0) M v_avg + v_avg^T diag(a1) (K u - K u_n): C = diag(a0) M + diag(a1) K is
      // symmetric, as M and K couple no DOFs of different coefficients.
      system_.multiply_mass(average_, work_);
      terms_.damping += step_.cwiseProduct(rayleigh->mass_coefficient).dot(work_) +
                        average_.cwiseProduct(rayleigh->stiffness_coefficient)
                            .dot(stiffness_force_ - previous_stiffness_force_);
    } else {
      system_.multiply_damping(average_, work_);
      terms_.damping += step_.dot(work_);
    }
  }
  add_link_work(state);
  if (algorithmic && first_step && state.link_force.size() > 0) {
    const double gained = add_start_link_work(state.time - previous_.time);
    terms_.links += gained;
    start_algorithmic_ = -gained;
    terms_.algorithmic += start_algorithmic_;
  }
}

// With step forces (an implicit integrator's hard contacts): an impulse F_{n+1} dt that turned
// the row's rate from w_n to w_{n+1} did the impulse times their mean, what the velocities' change
// takes. F_{n+1} d(delta) is that only where d(delta) = dt (w_n + w_{n+1}) / 2, under the
// trapezoidal rule: under HHT a perfectly elastic impact of two masses (81 J) read -1.8 J,
// "created by a penalty contact". The other rows by the trapezoidal rule.
void EnergyBalance::add_impulse_work(const integrators::State& state, bool moving, double& work,
                                     double& whole) {
  link_rates(state);
  extra_link_work_.setZero(link_step_.size());
  has_extra_link_work_ = true;
  const double dt = state.time - previous_.time;
  for (Index r = 0; r < link_step_.size(); ++r) {
    const double now = state.link_force[r], before = previous_.link_force[r];
    const double deformed =
        moving ? state.link_penetration[r] - previous_.link_penetration[r] : link_step_[r];
    if (step_force_weight_[r] == 0.0) {
      const double average = 0.5 * (now + before);
      work = multiply_add(average, link_step_[r], work);
      whole = multiply_add(average, deformed, whole);
      continue;
    }
    const double impulse = now * dt;
    work = multiply_add(impulse, 0.5 * (rate_before_[r] + rate_after_[r]), work);
    const double taken = impulse * 0.5 * (whole_rate_before_[r] + whole_rate_after_[r]);
    whole += taken;
    extra_link_work_[r] = taken - now * deformed;  // beyond LinkSummaries' rectangle rule
  }
}

// Central difference applies a force of the start's state over the first half step only (v_1/2 =
// v_0 + dt/2 a_0), at the velocities from v_0 to v_1/2: its work there is F_0 (dt delta_dot_0 +
// d(delta)) / 4, where the trapezoidal rule counts F_0 d(delta) / 2 (d(delta) = dt delta_dot_1/2).
// The two differ by O(dt^2) for a smooth force, but a hard contact striking at t = 0 has its whole
// impulse there: a block against a wall at e = 0.5 took -1.5 J by the rule, +0.75 J in fact.
// The algorithmic term -(1/8) dt^2 (a^T M a - a_0^T M a_0) held the difference.
double EnergyBalance::add_start_link_work(double dt) {
  system_.links().project(previous_.velocity, start_link_rate_);
  extra_link_work_.resize(link_step_.size());
  has_extra_link_work_ = true;
  double gained = 0.0;
  for (Index r = 0; r < link_step_.size(); ++r) {
    extra_link_work_[r] =
        0.25 * previous_.link_force[r] * (dt * start_link_rate_[r] - link_step_[r]);
    gained += extra_link_work_[r];
  }
  return gained;
}

void EnergyBalance::link_rates(const integrators::State& state) {
  const integrators::LinkSet& links = system_.links();
  // B v (+ s'(t) for the whole rate) of a state: the observer sees every accepted state, so the
  // last step's end is this step's start.
  const auto rates_of = [&](const Vector& velocity, double time, Vector& rate, Vector& whole) {
    links.project(velocity, rate);
    whole = rate;
    if (!link_motion_) return;
    system_.link_motion(time, offset_, offset_rate_, offset_acceleration_);
    whole += offset_rate_;
  };
  if (rate_after_.size() != link_step_.size())
    rates_of(previous_.velocity, previous_.time, rate_after_, whole_rate_after_);
  rate_before_.swap(rate_after_);
  whole_rate_before_.swap(whole_rate_after_);
  rates_of(state.velocity, state.time, rate_after_, whole_rate_after_);
}

}  // namespace pound::results
