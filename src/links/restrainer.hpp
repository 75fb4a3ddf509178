#pragma once
// Tension-only link with slack: a cable restrainer across a bridge joint (elastic, or yielding
// with linear hardening), or a hook (elastic tension gap; OpenSees' ElasticPPGap with a hook).
// In the shared convention (compression positive) its force is a tension, F <= 0:
//
//   opening o = -delta = (u_j - u_i) . n   (the link's gap must be 0: a restrainer has slack)
//   T = k (o - slack - p)  when positive, else 0 (the cable hangs slack)
//   yield: T <= T_y + H p,  H = b k / (1 - b)  (b: post-yield stiffness ratio)
//   F = -T
//
// p is the plastic elongation (history), so a yielded cable comes back with more slack.
// Units: k [F/L], slack [L], T_y [F]. Caltrans SDC and FHWA model cable restrainers this way.
#include <limits>

#include "links/link_law.hpp"

namespace pound::links {

class Restrainer final : public LinkLaw {
 public:
  Restrainer(std::string name, double stiffness, double slack,
             double yield_force = std::numeric_limits<double>::infinity(),
             double hardening_ratio = 0.0);
  std::string name() const override { return name_; }
  // The registry entries of the yielding restrainer and of the elastic hook
  // (links/law_registry.hpp).
  static const LawEntry& restrainer_entry();
  static const LawEntry& hook_entry();
  std::unique_ptr<LinkLaw> clone() const override { return std::make_unique<Restrainer>(*this); }
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override;
  void revert() override;
  bool in_contact() const override { return committed_taut_; }  // taut
  double permanent_deformation() const override {
    return committed_plastic_;
  }  // plastic elongation
  // The elongation beyond the slack at first yield, T_y / k; none for an elastic one (a hook).
  std::optional<double> yield_deformation() const override;
  double slack() const override { return slack_; }
  // T^2 / 2k taut and its hardening's H p^2 / 2 of the committed plastic elongation p.
  std::optional<double> stored_energy(double force, double /*deformation*/) const override {
    return 0.5 *
           (force * force / stiffness_ + hardening_ * committed_plastic_ * committed_plastic_);
  }

 private:
  std::string name_;
  double stiffness_, slack_, yield_force_, hardening_;
  double committed_plastic_ = 0.0, trial_plastic_ = 0.0;
  bool committed_taut_ = false, trial_taut_ = false;
};

}  // namespace pound::links
