#pragma once
// Kelvin-Voigt impact law (Anagnostopoulos 1988, "Pounding of buildings in series during
// earthquakes"): a linear spring and a dashpot in parallel, acting while delta > 0.
//
//   F = k delta + c delta_dot      (delta > 0; compression positive)
//   c = 2 xi sqrt(k m_eff),  xi = -ln e / sqrt(pi^2 + ln^2 e)
//
// Units: k [F/L], c [F T/L]. The force jumps by c v0 at first contact and turns tensile before
// separation. With `clip_tension` (the default) a tensile force is set to 0, which raises the
// restitution actually achieved (0.5 -> about 0.55); without it the law reaches e exactly but
// pulls the bodies together for a moment. `pound verify restitution` reports both.
#include "links/link_law.hpp"

namespace pound::links {

class KelvinVoigt final : public LinkLaw {
 public:
  KelvinVoigt(double stiffness, double damping, bool clip_tension);
  std::string name() const override { return "kelvin_voigt"; }
  // Its registry entry: parameters, traits, factory (links/law_registry.hpp).
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override { return std::make_unique<KelvinVoigt>(*this); }
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override { committed_contact_ = trial_contact_; }
  void revert() override { trial_contact_ = committed_contact_; }
  bool in_contact() const override { return committed_contact_; }

 private:
  double stiffness_, damping_;
  bool clip_tension_;
  bool trial_contact_ = false, committed_contact_ = false;
};

}  // namespace pound::links
