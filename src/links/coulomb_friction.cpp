#include "links/coulomb_friction.hpp"

#include <cmath>

namespace pound::links {

CoulombFriction::CoulombFriction(std::unique_ptr<LinkLaw> normal, double coefficient,
                                 StickPenalty stick, std::optional<double> radius)
    : normal_(std::move(normal)),
      coefficient_(coefficient),
      stick_(stick),
      radius_(radius),
      hard_(normal_->hard_contact()) {}

CoulombFriction::CoulombFriction(const CoulombFriction& other)
    : normal_(other.normal_->clone()),
      coefficient_(other.coefficient_),
      stick_(other.stick_),
      radius_(other.radius_),
      hard_(normal_->hard_contact()),
      committed_tangential_force_(other.committed_tangential_force_),
      trial_tangential_force_(other.committed_tangential_force_),
      committed_anchor_(other.committed_anchor_),
      trial_anchor_(other.committed_anchor_),
      committed_slip_(other.committed_slip_),
      trial_slip_(other.committed_slip_),
      committed_slide_(other.committed_slide_),
      trial_slide_(other.committed_slide_),
      committed_normal_force_(other.committed_normal_force_),
      trial_normal_force_(other.committed_normal_force_) {}

FrictionResponse CoulombFriction::set_trial(const LinkKinematics& normal,
                                            const LinkKinematics& tangential) {
  if (hard_) return imposed(normal, tangential);
  FrictionResponse out = coulomb(normal, tangential);
  trial_normal_force_ = out.normal.force;
  // A flat slider's arithmetic stays exactly the Coulomb law's (no "+ 0" anywhere).
  if (radius_ && out.normal.force > 0.0) add_restoring(tangential, out);
  return out;
}

FrictionResponse CoulombFriction::imposed(const LinkKinematics& normal,
                                          const LinkKinematics& tangential) {
  FrictionResponse out;
  out.normal = normal_->set_trial(normal);
  out.tangential_force = trial_tangential_force_;
  out.slipping = trial_slip_;
  trial_slide_ = tangential.penetration;
  trial_normal_force_ = out.normal.force;
  return out;
}

// R_t += R_n s / R: its derivatives are R_n / R along s and (s / R) dR_n along the normal
// quantities, the vertical load's share of the restoring force.
void CoulombFriction::add_restoring(const LinkKinematics& tangential,
                                    FrictionResponse& response) const {
  const double lever = tangential.penetration / *radius_;
  response.tangential_force += response.normal.force * lever;
  response.tangential_on_slip.stiffness += response.normal.force / *radius_;
  response.tangential_on_normal.stiffness += lever * response.normal.stiffness;
  response.tangential_on_normal.damping += lever * response.normal.damping;
  response.tangential_on_normal.mass += lever * response.normal.mass;
}

FrictionResponse CoulombFriction::coulomb(const LinkKinematics& normal,
                                          const LinkKinematics& tangential) {
  FrictionResponse out;
  out.normal = normal_->set_trial(normal);
  trial_slide_ = tangential.penetration;
  trial_slip_ = false;
  if (!(out.normal.force > 0.0)) {
    trial_anchor_ = tangential.penetration;  // a new contact sticks where it lands
    return out;
  }
  // A contact that begins in this step sticks from where the step began.
  const double anchor = normal_->in_contact() ? committed_anchor_ : committed_slide_;
  trial_anchor_ = anchor;
  const double stick_force = stick_.stiffness * (tangential.penetration - anchor) +
                             stick_.damping * tangential.penetration_rate +
                             stick_.mass * tangential.penetration_acceleration;
  const double limit = coefficient_ * out.normal.force;
  if (std::abs(stick_force) <= limit) {
    out.tangential_force = stick_force;
    out.tangential_on_slip = {0.0, stick_.stiffness, stick_.damping, stick_.mass};
    return out;
  }
  // Slip against the relative tangential velocity (at rest: against the stick force).
  const double direction = tangential.penetration_rate != 0.0
                               ? std::copysign(1.0, tangential.penetration_rate)
                               : std::copysign(1.0, stick_force);
  trial_slip_ = true;
  out.slipping = true;
  out.tangential_force = direction * limit;
  const double scale = direction * coefficient_;
  out.tangential_on_normal = {0.0, scale * out.normal.stiffness, scale * out.normal.damping,
                              scale * out.normal.mass};
  // Move the anchor so that the stick force would equal the slip force: no jump on sticking.
  if (stick_.stiffness > 0.0)
    trial_anchor_ = tangential.penetration -
                    (out.tangential_force - stick_.damping * tangential.penetration_rate -
                     stick_.mass * tangential.penetration_acceleration) /
                        stick_.stiffness;
  return out;
}

void CoulombFriction::commit() {
  normal_->commit();
  committed_anchor_ = trial_anchor_;
  committed_slip_ = trial_slip_;
  committed_slide_ = trial_slide_;
  committed_normal_force_ = trial_normal_force_;
  committed_tangential_force_ = trial_tangential_force_;
}

void CoulombFriction::anchor_at_rest(double tangential_force) {
  // Only F_c sticks: the pendulum's R_n s / R is not part of the stick penalty.
  if (radius_ && committed_normal_force_ > 0.0)
    tangential_force -= committed_normal_force_ * committed_slide_ / *radius_;
  if (stick_.stiffness > 0.0)
    committed_anchor_ = committed_slide_ - tangential_force / stick_.stiffness;
  trial_anchor_ = committed_anchor_;
}

void CoulombFriction::revert() {
  normal_->revert();
  trial_anchor_ = committed_anchor_;
  trial_slip_ = committed_slip_;
  trial_slide_ = committed_slide_;
  trial_normal_force_ = committed_normal_force_;
  trial_tangential_force_ = committed_tangential_force_;
}

}  // namespace pound::links
