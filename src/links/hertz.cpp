#include "links/hertz.hpp"

#include <cmath>

namespace pound::links {

LawResponse Hertz::set_trial(const LinkKinematics& trial) {
  trial_contact_ = trial.penetration > 0.0;
  if (!trial_contact_) return {};
  const double root = std::sqrt(trial.penetration);
  return {.force = stiffness_ * trial.penetration * root, .stiffness = 1.5 * stiffness_ * root};
}

}  // namespace pound::links
