#include "links/kelvin_voigt.hpp"

namespace pound::links {

KelvinVoigt::KelvinVoigt(double stiffness, double damping, bool clip_tension)
    : stiffness_(stiffness), damping_(damping), clip_tension_(clip_tension) {}

LawResponse KelvinVoigt::set_trial(const LinkKinematics& trial) {
  trial_contact_ = trial.penetration > 0.0;
  if (!trial_contact_) return {};
  const double force = stiffness_ * trial.penetration + damping_ * trial.penetration_rate;
  if (clip_tension_ && force < 0.0) return {};
  return {.force = force, .stiffness = stiffness_, .damping = damping_};
}

}  // namespace pound::links
