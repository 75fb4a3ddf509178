#pragma once
// Hertz-damp impact law (Muthukumar & DesRoches 2006, "A Hertz contact model with non-linear
// damping for pounding simulation"; damping from e after Ye, Li & Zhu 2009):
//
//   F = k_h delta^1.5 (1 + xi_bar delta_dot / v0)    (delta > 0; compression positive)
//   xi_bar = 8 (1 - e) / (5 e)
//
// v0 is the approach velocity at the instant of first contact, interpolated inside the step
// (links/impact_onset.hpp). Units: k_h [F/L^1.5], xi_bar [-]. The force is set to 0 when the
// damping term would make it tensile near separation. With v0 <= 0 (bodies placed in contact
// at rest) there is no impact to damp and the law is elastic Hertz.
#include "links/impact_onset.hpp"
#include "links/link_law.hpp"

namespace pound::links {

class HertzDamp final : public LinkLaw {
 public:
  HertzDamp(double stiffness, double damping_ratio);
  std::string name() const override { return "hertz_damp"; }
  // Its registry entry: parameters, traits, factory (links/law_registry.hpp).
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override { return std::make_unique<HertzDamp>(*this); }
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override { onset_.commit(trial_, trial_.penetration > 0.0); }
  void revert() override { trial_ = onset_.committed(); }
  bool in_contact() const override { return onset_.in_contact(); }

 private:
  double stiffness_, damping_ratio_;
  ImpactOnset onset_;
  LinkKinematics trial_;
};

}  // namespace pound::links
