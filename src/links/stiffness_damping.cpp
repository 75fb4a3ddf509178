#include "links/stiffness_damping.hpp"

#include <algorithm>

namespace pound::links {

StiffnessDamping::StiffnessDamping(std::unique_ptr<LinkLaw> law, double stiffness_coefficient,
                                   DampingStiffness stiffness)
    : law_(std::move(law)), stiffness_coefficient_(stiffness_coefficient), stiffness_(stiffness) {
  // k_0 of a fresh copy: this law may be handed over in any state.
  const double initial = std::max(0.0, law_->clone()->set_trial({}).stiffness);
  coefficient_ = stiffness_coefficient_ * initial;
}

StiffnessDamping::StiffnessDamping(const StiffnessDamping& other)
    : LinkLaw(other),
      law_(other.law_->clone()),
      stiffness_coefficient_(other.stiffness_coefficient_),
      stiffness_(other.stiffness_),
      coefficient_(other.coefficient_),
      trial_law_stiffness_(other.trial_law_stiffness_),
      trial_delta_(other.committed_delta_),
      committed_delta_(other.committed_delta_),
      trial_force_(other.committed_force_),
      committed_force_(other.committed_force_),
      trial_work_(other.committed_work_),
      committed_work_(other.committed_work_),
      started_(other.started_) {}

std::unique_ptr<LinkLaw> StiffnessDamping::clone() const {
  return std::make_unique<StiffnessDamping>(*this);
}

LawResponse StiffnessDamping::set_trial(const LinkKinematics& trial) {
  LawResponse response = law_->set_trial(trial);
  trial_law_stiffness_ = response.stiffness;
  if (!started_) {
    committed_delta_ = trial.penetration;
    started_ = true;
  }
  trial_delta_ = trial.penetration;
  trial_force_ = coefficient_ * trial.penetration_rate;
  trial_work_ =
      committed_work_ + 0.5 * (trial_force_ + committed_force_) * (trial_delta_ - committed_delta_);
  response.force += trial_force_;
  response.damping += coefficient_;
  return response;
}

void StiffnessDamping::commit() {
  law_->commit();
  committed_delta_ = trial_delta_;
  committed_force_ = trial_force_;
  committed_work_ = trial_work_;
  if (stiffness_ == DampingStiffness::committed)
    coefficient_ = stiffness_coefficient_ * std::max(0.0, trial_law_stiffness_);
}

void StiffnessDamping::revert() {
  law_->revert();
  trial_delta_ = committed_delta_;
  trial_force_ = committed_force_;
  trial_work_ = committed_work_;
}

}  // namespace pound::links
