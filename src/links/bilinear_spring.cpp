#include "links/bilinear_spring.hpp"

#include <cmath>

namespace pound::links {

BilinearSpring::BilinearSpring(double stiffness, double yield_force, double hardening_ratio)
    : stiffness_(stiffness),
      yield_force_(yield_force),
      hardening_ratio_(hardening_ratio),
      hardening_modulus_(hardening_ratio * stiffness / (1.0 - hardening_ratio)) {}

LawResponse BilinearSpring::set_trial(const LinkKinematics& trial) {
  trial_plastic_ = committed_plastic_;
  double force = stiffness_ * (trial.penetration - committed_plastic_), slope = stiffness_;
  const double relative = force - back_force_at(committed_plastic_);
  const double excess = std::abs(relative) - yield_force_;
  if (excess > 0.0) {  // return to the yield surface, which moves with the back-force
    const double plastic_step = std::copysign(excess / (stiffness_ + hardening_modulus_), relative);
    trial_plastic_ += plastic_step;
    force -= stiffness_ * plastic_step;
    slope = hardening_ratio_ * stiffness_;
  }
  trial_force_ = force;
  return {.force = force, .stiffness = slope};
}

void BilinearSpring::commit() {
  committed_plastic_ = trial_plastic_;
  committed_force_ = trial_force_;
}

void BilinearSpring::revert() {
  trial_plastic_ = committed_plastic_;
  trial_force_ = committed_force_;
}

}  // namespace pound::links
