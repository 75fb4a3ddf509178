#include "links/gap_spring.hpp"

namespace pound::links {

GapSpring::GapSpring(double stiffness) : stiffness_(stiffness) {}

std::unique_ptr<LinkLaw> GapSpring::clone() const {
  auto copy = std::make_unique<GapSpring>(stiffness_);
  copy->trial_contact_ = copy->committed_contact_ = committed_contact_;
  return copy;
}

LawResponse GapSpring::set_trial(const LinkKinematics& trial) {
  trial_contact_ = trial.penetration > 0.0;
  if (!trial_contact_) return {};
  return {.force = stiffness_ * trial.penetration, .stiffness = stiffness_};
}

}  // namespace pound::links
