#pragma once
// Nonlinear viscoelastic impact law (Jankowski 2005, "Non-linear viscoelastic modelling of
// earthquake-induced structural pounding"):
//
//   F = beta delta^1.5 + c delta_dot   while approaching (delta > 0, delta_dot > 0)
//   F = beta delta^1.5                 while separating  (delta > 0, delta_dot <= 0)
//   c = 2 xi sqrt(beta sqrt(delta) m_eff),
//   xi = 9 sqrt(5)/2 (1 - e^2) / (e (e (9 pi - 16) + 16))
//
// Units: beta [F/L^1.5], m_eff [M], xi [-]. The force never turns tensile and is continuous at
// the turn (c delta_dot -> 0). Compression positive.
#include "links/link_law.hpp"

namespace pound::links {

class Jankowski final : public LinkLaw {
 public:
  Jankowski(double stiffness, double damping_ratio, double effective_mass);
  std::string name() const override { return "jankowski"; }
  // Its registry entry: parameters, traits, factory (links/law_registry.hpp).
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override { return std::make_unique<Jankowski>(*this); }
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override { committed_contact_ = trial_contact_; }
  void revert() override { trial_contact_ = committed_contact_; }
  bool in_contact() const override { return committed_contact_; }

 private:
  double stiffness_, damping_ratio_, effective_mass_;
  bool trial_contact_ = false, committed_contact_ = false;
};

}  // namespace pound::links
