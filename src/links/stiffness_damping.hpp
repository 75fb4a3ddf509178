#pragma once
// Stiffness-proportional (Rayleigh) damping of a structural spring or hinge, added to its law:
//   F = F_law(delta) + a1 k_ref d(delta)/dt
// with a1 the Rayleigh stiffness coefficient [T] and k_ref either
//   initial:   the law's stiffness at delta = 0 (a linear dashpot; OpenSees' betaKinit), or
//   committed: the law's tangent max(0, dF_law/d(delta)) at the last converged step (OpenSees'
//              betaKcomm), held through the step, so the tangent is exact: dF/d(delta_dot) = a1
//              k_ref.
// Initial-stiffness damping keeps a1 k_0 delta_dot across a member that has yielded, a viscous
// force that can exceed its yield force (Charney 2008, J. Struct. Eng. 134(4)); the committed
// tangent drops to the post-yield slope while the member yields and comes back on unloading.
// Units: F [F], a1 [T], k [F/L] (or [F L/rad] for a hinge). Signs as LinkLaw (compression > 0).
#include "links/link_law.hpp"

namespace pound::links {

enum class DampingStiffness { initial, committed };

class StiffnessDamping : public LinkLaw {
 public:
  StiffnessDamping(std::unique_ptr<LinkLaw> law, double stiffness_coefficient,
                   DampingStiffness stiffness);
  StiffnessDamping(const StiffnessDamping& other);

  std::string name() const override { return law_->name(); }  // the member's own law
  std::unique_ptr<LinkLaw> clone() const override;
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override;
  void revert() override;
  bool in_contact() const override { return law_->in_contact(); }
  std::optional<double> yield_deformation() const override { return law_->yield_deformation(); }
  std::optional<double> stored_energy(double force, double deformation) const override {
    return law_->stored_energy(force, deformation);
  }
  ViscousPart viscous_part() const override { return {committed_work_, committed_force_}; }

  double coefficient() const { return coefficient_; }  // a1 k_ref of the step [F T/L]

 private:
  std::unique_ptr<LinkLaw> law_;
  double stiffness_coefficient_;  // a1
  DampingStiffness stiffness_;
  double coefficient_ = 0.0;  // a1 k_ref, fixed through a step
  // The law's tangent at the last trial, the committed one once it converges.
  double trial_law_stiffness_ = 0.0;
  // Viscous force and work (trapezoidal in delta, as the energy balance sums link work).
  double trial_delta_ = 0.0, committed_delta_ = 0.0;
  double trial_force_ = 0.0, committed_force_ = 0.0;
  double trial_work_ = 0.0, committed_work_ = 0.0;
  bool started_ = false;  // the first trial sets committed_delta_ (a link may start deformed)
};

}  // namespace pound::links
