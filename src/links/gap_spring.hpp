#pragma once
// Gap impact spring (Kawashima 1980, "An analytical model of contact and impact in dynamic
// response analysis", eqs. 5-9): a linear spring that acts only while the facing points
// overlap.
//
//   F = k_I * delta   for delta > 0 (penetration; compression positive)
//   F = 0             for delta <= 0
//
// Kawashima writes S = k_I <r> r with r = u_J - u_I = -delta and S = -F; the tangent
// k~ = k_I <r> is the same. Units: k_I [F/L], delta [L], F [F]. The law is elastic (no
// history), so commit/revert only move the contact flag. Kawashima's study: k_I about the axial
// stiffness of the adjacent element (k_I L / (n E A) ~ 1) balances penetration against
// spurious oscillation.
#include "links/link_law.hpp"

namespace pound::links {

class GapSpring final : public LinkLaw {
 public:
  explicit GapSpring(double stiffness);

  std::string name() const override { return "gap_spring"; }
  // Its registry entry: parameters, traits, factory (links/law_registry.hpp).
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override;
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override { committed_contact_ = trial_contact_; }
  void revert() override { trial_contact_ = committed_contact_; }
  bool in_contact() const override { return committed_contact_; }

  double stiffness() const { return stiffness_; }

 private:
  double stiffness_;
  bool trial_contact_ = false;
  bool committed_contact_ = false;
};

}  // namespace pound::links
