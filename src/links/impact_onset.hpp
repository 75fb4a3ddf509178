#pragma once
// The approach velocity at the instant of first contact, v0 = d(delta)/dt where delta crosses 0,
// which several impact laws use (Hertz-damp's damping, the bilinear law's calibration). It is
// interpolated inside the step in which contact begins, between the committed state (delta_n <= 0)
// and the trial (delta > 0):
//   theta = -delta_n / (delta - delta_n),  v0 = rate_n + theta (rate - rate_n),
// so it does not depend on which step first penetrates. While contact lasts, v0 is the committed
// value. The derivatives of v0 with respect to the trial delta and rate are given so the laws'
// tangents stay consistent in the step of first contact.
#include "links/link_law.hpp"

namespace pound::links {

struct OnsetVelocity {
  double velocity = 0.0;       // v0 [L/T]
  double d_penetration = 0.0;  // dv0/d(delta) [1/T]
  double d_rate = 0.0;         // dv0/d(delta_dot) [-]
};

class ImpactOnset {
 public:
  // v0 for a trial that is in contact.
  OnsetVelocity at(const LinkKinematics& trial) const;
  // Records the trial as committed; v0 is fixed at the first contact and kept while it lasts.
  void commit(const LinkKinematics& trial, bool in_contact);

  bool in_contact() const { return in_contact_; }
  const LinkKinematics& committed() const { return committed_; }
  double impact_velocity() const { return velocity_; }  // of the current or last contact

 private:
  LinkKinematics committed_;
  bool in_contact_ = false;
  double velocity_ = 0.0;
};

}  // namespace pound::links
