#pragma once
// Bilinear hysteretic structural spring: an elastomeric or sliding bearing, or a pier plastic
// hinge as a zero-length spring (link with gap 0). Elastic-plastic in both directions with
// linear kinematic hardening, the standard bilinear model (OpenSees Steel01 without isotropic
// hardening; the bilinear bearing of Caltrans SDC):
//
//   F = k (delta - p)                       p: plastic deformation (history)
//   yield surface |F - alpha| <= F_y        alpha = H p: the back-force
//   H = b k / (1 - b)                       so that the post-yield slope is k H / (k + H) = b k
//
// Return mapping from the committed (p, alpha): the elastic trial k (delta - p_n) - alpha_n
// exceeding F_y by e moves p by e / (k + H) in its direction; consistent tangent k elastic,
// b k while yielding. The yield lines are F = b k delta +- (1 - b) F_y; after a reversal the
// spring yields again when F has changed by 2 F_y (Bauschinger effect). A symmetric cycle to
// +-delta_m (delta_m > delta_y = F_y / k) dissipates 4 (1 - b) F_y (delta_m - delta_y).
//
// Units: k [F/L], F_y [F], b [-] in [0, 1), delta and p [L].
#include <string>

#include "links/link_law.hpp"

namespace pound::links {

class BilinearSpring final : public LinkLaw {
 public:
  // `name`: the law it was made as; elastic_perfectly_plastic and lead_rubber are bilinear springs
  // given by other numbers (links/elastic_perfectly_plastic.hpp, links/lead_rubber.hpp).
  BilinearSpring(double stiffness, double yield_force, double hardening_ratio,
                 std::string name = "bilinear_spring");

  std::string name() const override { return name_; }
  // Its registry entry: parameters, traits, factory (links/law_registry.hpp).
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override {
    return std::make_unique<BilinearSpring>(*this);
  }
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override;
  void revert() override;
  // A spring is always attached; "in contact" means it carries a force.
  bool in_contact() const override { return committed_force_ != 0.0; }
  std::optional<double> yield_deformation() const override { return yield_force_ / stiffness_; }
  // bilinear_stored_energy: what is dissipated is then the plastic slip's (1 - b) F_y |dq| alone
  // (a lead-rubber bearing's lead, Q_d (D - delta_y) pushed to D).
  std::optional<double> stored_energy(double force, double deformation) const override {
    return bilinear_stored_energy(stiffness_, hardening_modulus_, force, deformation);
  }

  double plastic_deformation() const { return committed_plastic_; }
  double stiffness() const { return stiffness_; }
  double yield_force() const { return yield_force_; }
  double hardening_ratio() const { return hardening_ratio_; }
  double back_force() const { return back_force_at(committed_plastic_); }

 private:
  double back_force_at(double plastic) const { return hardening_modulus_ * plastic; }

  std::string name_;
  double stiffness_, yield_force_, hardening_ratio_, hardening_modulus_;
  double committed_plastic_ = 0.0, trial_plastic_ = 0.0;
  double committed_force_ = 0.0, trial_force_ = 0.0;
};

}  // namespace pound::links
