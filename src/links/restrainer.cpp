#include "links/restrainer.hpp"

namespace pound::links {

Restrainer::Restrainer(std::string name, double stiffness, double slack, double yield_force,
                       double hardening_ratio)
    : name_(std::move(name)),
      stiffness_(stiffness),
      slack_(slack),
      yield_force_(yield_force),
      hardening_(hardening_ratio * stiffness / (1.0 - hardening_ratio)) {}

LawResponse Restrainer::set_trial(const LinkKinematics& trial) {
  const double elongation = -trial.penetration - slack_ - committed_plastic_;
  trial_plastic_ = committed_plastic_;
  trial_taut_ = elongation > 0.0;
  if (!trial_taut_) return {};
  double tension = stiffness_ * elongation, slope = stiffness_;
  const double excess = tension - (yield_force_ + hardening_ * committed_plastic_);
  if (excess > 0.0) {  // return to the yield line
    const double plastic_step = excess / (stiffness_ + hardening_);
    trial_plastic_ += plastic_step;
    tension -= stiffness_ * plastic_step;
    slope = stiffness_ * hardening_ / (stiffness_ + hardening_);
  }
  // dF/d(delta) = d(-T)/d(delta) = dT/d(opening).
  return {.force = -tension, .stiffness = slope};
}

void Restrainer::commit() {
  committed_plastic_ = trial_plastic_;
  committed_taut_ = trial_taut_;
}

void Restrainer::revert() {
  trial_plastic_ = committed_plastic_;
  trial_taut_ = committed_taut_;
}

}  // namespace pound::links
