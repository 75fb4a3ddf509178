#pragma once
// Hard contact: non-penetration as a constraint, with no stiffness to choose.
//
//   delta <= 0,   F >= 0,   F delta = 0          (compression positive)
//
// and Newton's impact law on the normal relative velocity across an impact,
//
//   delta_dot+ = -e delta_dot-,   0 <= e <= 1,
//
// so an impact of two bodies loses exactly (1 - e^2) of its normal approach energy
// 1/2 m_eff delta_dot-^2 (e = 1 conserves it). The law has no force of its own: the integrator
// finds F from the constraint over all the hard contacts of a step together and imposes it
// (integrators/central_difference.hpp: Carpenter, Taylor & Katona's forward-increment Lagrange
// multipliers, with the impact law at velocity level as in Moreau-Jean time stepping;
// integrators/newmark.hpp: the same impact law as a bound in the condensed Newton, the force an
// impulse of its step, between masses only). F is released as soon as it would turn tensile. e = 0
// suits contact between finite element meshes (their own elasticity makes the bounce, as in the rod
// benchmark); e > 0 lumped masses that stand for whole bodies. Units: e [-]; F [F].
#include "links/link_law.hpp"

namespace pound::links {

class HardContact final : public LinkLaw {
 public:
  explicit HardContact(double restitution) : restitution_(restitution) {}

  std::string name() const override { return "hard_contact"; }
  // Its registry entry: parameters, traits, factory (links/law_registry.hpp).
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override;
  // The force last imposed: the law does not make one.
  LawResponse set_trial(const LinkKinematics&) override { return {.force = trial_force_}; }
  void commit() override { committed_force_ = trial_force_; }
  void revert() override { trial_force_ = committed_force_; }
  bool in_contact() const override { return committed_force_ > 0.0; }
  HardContact* hard_contact() override { return this; }
  bool is_hard_contact() const override { return true; }

  double restitution() const { return restitution_; }
  // The constraint force the integrator found for the trial state (>= 0).
  void impose(double force) { trial_force_ = force; }

 private:
  double restitution_;
  double trial_force_ = 0.0, committed_force_ = 0.0;
};

}  // namespace pound::links
