#include "links/impact_onset.hpp"

namespace pound::links {

OnsetVelocity ImpactOnset::at(const LinkKinematics& trial) const {
  if (in_contact_) return {velocity_, 0.0, 0.0};
  const double before = committed_.penetration;
  const double rate_before = committed_.penetration_rate;
  if (!(before < 0.0) || trial.penetration <= before) {
    // Starting in contact (delta_n = 0, e.g. touching at t = 0): the current rate.
    return {trial.penetration_rate, 0.0, 1.0};
  }
  const double span = trial.penetration - before;
  const double theta = -before / span;
  const double rate_change = trial.penetration_rate - rate_before;
  return {rate_before + theta * rate_change, rate_change * before / (span * span), theta};
}

void ImpactOnset::commit(const LinkKinematics& trial, bool in_contact) {
  if (in_contact && !in_contact_) velocity_ = at(trial).velocity;
  in_contact_ = in_contact;
  committed_ = trial;
}

}  // namespace pound::links
