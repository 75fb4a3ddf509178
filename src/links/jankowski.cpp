#include "links/jankowski.hpp"

#include <cmath>

namespace pound::links {

Jankowski::Jankowski(double stiffness, double damping_ratio, double effective_mass)
    : stiffness_(stiffness), damping_ratio_(damping_ratio), effective_mass_(effective_mass) {}

LawResponse Jankowski::set_trial(const LinkKinematics& trial) {
  trial_contact_ = trial.penetration > 0.0;
  if (!trial_contact_) return {};
  const double delta = trial.penetration, root = std::sqrt(delta);
  LawResponse response{.force = stiffness_ * delta * root, .stiffness = 1.5 * stiffness_ * root};
  if (trial.penetration_rate > 0.0) {
    // c = 2 xi sqrt(beta m_eff) delta^(1/4); dc/d(delta) = c / (4 delta).
    const double damping =
        2.0 * damping_ratio_ * std::sqrt(stiffness_ * effective_mass_) * std::sqrt(root);
    response.force += damping * trial.penetration_rate;
    response.stiffness += damping / (4.0 * delta) * trial.penetration_rate;
    response.damping = damping;
  }
  return response;
}

}  // namespace pound::links
