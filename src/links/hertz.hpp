#pragma once
// Hertz impact law (elastic): F = k_h delta^1.5 for delta > 0 (compression positive).
// Units: k_h [F/L^1.5]. Closed forms of one impact: links/restitution.hpp (hertz_impact).
// Source: Hertz (1882); for pounding, Davis (1992), Muthukumar & DesRoches (2006).
#include "links/link_law.hpp"

namespace pound::links {

class Hertz final : public LinkLaw {
 public:
  explicit Hertz(double stiffness) : stiffness_(stiffness) {}
  std::string name() const override { return "hertz"; }
  // Its registry entry: parameters, traits, factory (links/law_registry.hpp).
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override { return std::make_unique<Hertz>(*this); }
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override { committed_contact_ = trial_contact_; }
  void revert() override { trial_contact_ = committed_contact_; }
  bool in_contact() const override { return committed_contact_; }

 private:
  double stiffness_;
  bool trial_contact_ = false, committed_contact_ = false;
};

}  // namespace pound::links
