#pragma once
// Extended penalty (Suzuki & Toi 1987, "An extended penalty function approach to dynamic
// contact problems"; after Asano): a spring, a dashpot and a mass between the contact points,
//
//   R_n = alpha0 delta + alpha1 delta_dot + alpha2 delta_ddot     (compression positive)
//
// The mass and dashpot tame the spurious high mode a stiff penalty spring creates. Numbers from
// the two-element model (k, m: diagonal stiffness and lumped mass at the contact DOFs; a rigid
// side enters with k = m = 0):
//   alpha0 = max(k1, k2) / e*            (eq. 20; e* = 1e-3 allows 0.1 % penetration)
//   alpha2 = alpha0 (m1 + m2) / (k1 + k2)  (eq. 29)
//   alpha1 = 2 eta sqrt(alpha0 alpha2)     (eq. 34/38; eta = 1 damps the relative motion
//   critically)
// Units: alpha0 [F/L], alpha1 [F T/L], alpha2 [M].
//
// Contact rule: contact begins when delta > 0 and R_n > 0, and it is released when R_n would
// turn tensile, not only when delta < 0; otherwise the dashpot and the mass pull the bodies
// together. A penetrating pair that separates fast has R_n < 0 and stays apart.
#include "links/link_context.hpp"
#include "links/link_law.hpp"

namespace pound::links {

class ExtendedPenalty final : public LinkLaw {
 public:
  struct Numbers {
    double alpha0, alpha1, alpha2;
  };
  explicit ExtendedPenalty(Numbers numbers);
  // Suzuki & Toi's numbers for a link; tolerance e* and damping factor eta.
  static Numbers automatic(const LinkContext& context, double tolerance, double eta);

  std::string name() const override { return "extended_penalty"; }
  // Its registry entry: parameters, traits, factory (links/law_registry.hpp).
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override {
    return std::make_unique<ExtendedPenalty>(*this);
  }
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override {
    committed_contact_ = trial_contact_;
    touched_ = false;
  }
  void revert() override {
    trial_contact_ = committed_contact_;
    touched_ = false;
  }
  bool in_contact() const override { return committed_contact_; }
  const Numbers& numbers() const { return numbers_; }

 private:
  Numbers numbers_;
  bool trial_contact_ = false, committed_contact_ = false;
  bool touched_ = false;  // in contact at a trial since the last commit or revert
};

}  // namespace pound::links
