#include "links/backfill.hpp"

#include <stdexcept>

namespace pound::links {

Backfill::Backfill(double initial_stiffness, double ultimate_force, double ultimate_deformation)
    : stiffness_(initial_stiffness),
      ultimate_force_(ultimate_force),
      ultimate_deformation_(ultimate_deformation),
      curvature_(hyperbola_curvature(initial_stiffness, ultimate_force, ultimate_deformation)) {
  if (!(initial_stiffness > 0.0 && ultimate_force > 0.0 && ultimate_deformation > 0.0))
    throw std::invalid_argument("backfill needs positive K, F_ult and delta_ult");
  if (!(curvature_ > 0.0))
    throw std::invalid_argument("backfill needs F_ult / K < delta_ult (hyperbola D > 0)");
}

LawResponse Backfill::envelope(double penetration) const {
  if (!(penetration > 0.0)) return {};
  if (penetration > ultimate_deformation_) return {.force = ultimate_force_};
  const double denominator = 1.0 + curvature_ * penetration;
  return {.force = stiffness_ * penetration / denominator,
          .stiffness = stiffness_ / (denominator * denominator)};
}

LawResponse Backfill::set_trial(const LinkKinematics& trial) {
  const double delta = trial.penetration;
  trial_permanent_ = committed_permanent_;
  const double elastic = stiffness_ * (delta - committed_permanent_);
  trial_contact_ = elastic > 0.0;
  if (!trial_contact_) return {};  // the gap left by the permanent deformation: no tension
  // Inside the backbone: unloading/reloading with K. The backbone is concave with slopes <= K,
  // so the line K (delta - p) meets it only at delta_max; past it the soil deforms further.
  const LawResponse backbone = envelope(delta);
  if (elastic < backbone.force) return {.force = elastic, .stiffness = stiffness_};
  trial_permanent_ = delta - backbone.force / stiffness_;
  return backbone;
}

void Backfill::commit() {
  committed_permanent_ = trial_permanent_;
  committed_contact_ = trial_contact_;
}

void Backfill::revert() {
  trial_permanent_ = committed_permanent_;
  trial_contact_ = committed_contact_;
}

}  // namespace pound::links
