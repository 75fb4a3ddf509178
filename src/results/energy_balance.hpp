#pragma once
// Energy balance of a run, accumulated step by step:
//   kinetic + strain + damping + links = input + (kinetic + strain at the start)
// kinetic 1/2 v^T M v, strain 1/2 u^T K u of the linear elements, damping sum du^T C v_avg,
// links sum F_avg . B du over every link row (impact, spring and friction work on the
// structure, elastic or dissipated; the same as F d(delta) unless supports move the links), input
// sum du^T f_avg with f = loads - M iota a_g (relative formulation). Work terms use step averages,
// which makes the balance exact for the trapezoidal rule (Newmark beta = 1/4, gamma = 1/2) up to
// the Newton tolerance, so a large error means a step was not resolved (or another integrator's own
// dissipation). Other Newmark methods with gamma = 1/2, central difference among them (beta = 0),
// balance exactly with their algorithmic energy c dt^2 a^T M a, c = (beta - 1/4) / 2, beside the
// kinetic energy: for any forces M a, sum f_avg . du = Delta(1/2 v^T M v) + c dt^2 Delta(a^T M a).
// The balance error includes it; without it a central-difference run from rest shows its half-step
// velocity lag as a 100 % error at its first step. The check for created energy does not: an
// unstable step conserves that modified energy too, while the physical one grows.
#include "core/types.hpp"
#include "integrators/integrator.hpp"
#include "integrators/second_order_system.hpp"
#include "results/observer.hpp"

namespace pound::results {

struct EnergyTerms {
  // Work of loads and ground motion since the start; where supports or belts move links, also
  // theirs through the links.
  double input = 0.0;
  double kinetic = 0.0;      // now
  double strain = 0.0;       // now, linear elements
  double damping = 0.0;      // dissipated by C since the start
  double links = 0.0;        // work done on the links since the start
  double algorithmic = 0.0;  // c dt^2 a^T M a now less at the start (0: trapezoidal rule)
  double initial = 0.0;      // kinetic + strain at the start
  // Energies below this are round-off: 1e-9 of the kinetic energy the loads would give the
  // lumped masses in one step, 1/2 sum (f_i dt)^2 / m_i, at its largest over the run (sampled
  // at the first step and every 64th). A block
  // held at rest by hard contacts has no energy at all, and its terms' round-off (1e-22 J) must
  // not read as 100 % of the largest.
  double round_off = 0.0;
  // The largest term any step of the run has had so far: a free mass (a deck on a slider, a
  // storey past its yield force of nothing) has its input and kinetic energy pass through zero
  // together, and its balance's round-off must not read then as 22 % of a term near zero.
  double peak = 0.0;
  // max(|input|, kinetic, strain, |damping|, |links|, initial, round_off, peak)
  double largest_term() const;
  // kinetic + strain + damping + links - input - initial: the physical energy made up.
  double residual() const;
  // |kinetic + algorithmic + strain + damping + links - input - initial| over the largest term.
  double balance_error() const;
  // The same without the absolute value and the algorithmic energy: > 0 when the structure holds
  // or has dissipated more energy than was put in, i.e. the integration created energy.
  double created_fraction() const;
  // Energy the links have given the structure, -links when negative, over the largest term.
  // Passive links (every law) store or dissipate what is done on them, so this stays at the
  // discretisation error of a contact (about 1 %); a blow-up through a link makes it about 1,
  // while the balance itself still closes (the links' negative work cancels the structure's
  // energy), so created_fraction alone would miss it.
  double link_created_fraction() const;
};

// A run whose created energy passes this fraction of the largest term stops as failed
// (docs/design.md §2.4; also the stability map's definition of an unstable cell).
inline constexpr double kEnergyGrowthLimit = 0.10;
// ... in this many steps in a row (a blow-up grows, a start-up transient of an explicit method
// falls below the limit within 3 steps).
inline constexpr int kEnergyGrowthSteps = 10;

class EnergyBalance : public Observer {
 public:
  // `acceleration_energy`: c of the integrator's algorithmic energy
  // (IntegratorChoice::acceleration_energy). `predicted_damping`: the integrator's damping force
  // is C v* with v* = v_n + dt a_n (central difference's), whose work the balance then takes.
  explicit EnergyBalance(const integrators::SecondOrderSystem& system,
                         double acceleration_energy = 0.0, bool predicted_damping = false)
      : system_(system),
        acceleration_energy_(acceleration_energy),
        link_motion_(system.has_link_motion()),
        predicted_damping_(predicted_damping && system.has_damping()) {}
  void record(const integrators::State& state) override;
  // Rows whose force is its step's average (LinkSummaries::set_step_forces): their work is
  // F_{n+1} B du.
  void set_step_forces(const std::vector<char>& by_row);
  const EnergyTerms& terms() const { return terms_; }
  // Each link row's work this step beyond what LinkSummaries' rules take (the trapezoidal one,
  // the rectangle one for step forces), which LinkSummaries::add_work then adds: central
  // difference's first step, and an implicit step's impulses. None where there is none.
  const Vector* extra_link_work() const {
    return has_extra_link_work_ ? &extra_link_work_ : nullptr;
  }
  // The largest balance error seen over the run (not only at the end): its largest |residual|
  // over the run's largest term, so that a step's error is measured against the energies the run
  // reaches, not those of its first steps (HHT, alpha -0.1, on a damped SDOF under a record at
  // dt = 0.01: its start-up error was 9.0e-2 of the early terms, and is 1.35e-3 of the run's).
  double worst_balance_error() const {
    return terms_.peak > 0.0 ? worst_residual_ / terms_.peak : 0.0;
  }

 private:
  double mass_norm(const Vector& acceleration);  // a^T M a
  // A step's terms: with a lumped mass and no algorithmic energy, the sums over the DOFs in one
  // pass; otherwise (and at the start) term by term.
  void record_step_lumped(const integrators::State& state, const Vector& mass);
  void record_general(const integrators::State& state, bool algorithmic);
  // The round-off floor, every kRoundOffStride steps.
  void sample_round_off(double dt);
  // F_avg . B du over the link rows, from step_ (du).
  void add_link_work(const integrators::State& state);
  // Central difference's first step (see the .cpp): each row's work beyond the trapezoidal rule.
  double add_start_link_work(double dt);
  // add_link_work's sums with step forces (see the .cpp).
  void add_impulse_work(const integrators::State& state, bool moving, double& work, double& whole);
  // The rates of the link rows at the ends of the step (rate_before_ ... whole_rate_after_): the
  // start's are the last step's end's, taken then (the first step takes its own).
  void link_rates(const integrators::State& state);
  // 1/2 sum (f_i dt)^2 / m_i over the lumped masses (0 with consistent ones).
  double step_load_energy(double dt);

  const integrators::SecondOrderSystem& system_;
  double acceleration_energy_ = 0.0;
  bool link_motion_ = false;  // supports or belts move links (add_link_work)
  // Central difference's damping velocity v* at this step and the previous one, from the previous
  // state's v and a (its acceleration kept for it).
  bool predicted_damping_ = false;
  Vector damping_velocity_, previous_damping_velocity_, previous_acceleration_;
  double initial_acceleration_norm_ = 0.0;  // a_0^T M a_0
  double initial_algorithmic_ = 0.0;        // -c dt_1^2 a_0^T M a_0, dt_1 the first step's
  // What the first step's link work gained over the trapezoidal rule (start_link_work_), taken
  // from the algorithmic term, which held it, at every step after: the balance is unchanged.
  double start_algorithmic_ = 0.0;
  Vector extra_link_work_, start_link_rate_;
  bool has_extra_link_work_ = false;  // this step's extra_link_work_ holds some (kept allocated)
  // The link rows' rates at the step's two ends, with the supports' part (whole) and without:
  // for the impulses' work. The end's are the next step's start.
  Vector rate_before_, rate_after_, whole_rate_before_, whole_rate_after_, offset_, offset_rate_,
      offset_acceleration_;
  EnergyTerms terms_;
  double worst_residual_ = 0.0;  // the largest |residual + algorithmic| of a step
  bool started_ = false;
  integrators::State previous_;
  // work_ has the DOFs' size, link_step_ the link rows': one buffer for both would be reallocated
  // twice a step.
  Vector previous_external_, external_, work_, link_step_, average_, step_;
  Vector inverse_mass_;  // 1 / m_i of the lumped masses, 0 where none (step_load_energy)
  static constexpr long kRoundOffStride = 64;  // steps between samples of the round-off floor
  long recorded_steps_ = 0;                    // since the start
  Vector step_force_weight_;  // by row: 1 for a step-average force, else 0 (empty: none)
  // K u at this step and the previous one: with Rayleigh damping (by DOF) the damping work
  // follows from them (du^T diag(a1) K v_avg = v_avg^T diag(a1) (K u_{n+1} - K u_n)), one
  // product less per step.
  Vector stiffness_force_, previous_stiffness_force_;
};

}  // namespace pound::results
