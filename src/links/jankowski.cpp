#include "links/jankowski.hpp"

#include <cmath>

#include "links/law_registry.hpp"
#include "links/restitution.hpp"
#include "links/restitution_calibration.hpp"

namespace pound::links {

Jankowski::Jankowski(double stiffness, double damping_ratio, double effective_mass)
    : stiffness_(stiffness), damping_ratio_(damping_ratio), effective_mass_(effective_mass) {}

LawResponse Jankowski::set_trial(const LinkKinematics& trial) {
  trial_contact_ = trial.penetration > 0.0;
  if (!trial_contact_) return {};
  const double delta = trial.penetration, root = std::sqrt(delta);
  LawResponse response{.force = stiffness_ * delta * root, .stiffness = 1.5 * stiffness_ * root};
  if (trial.penetration_rate > 0.0) {
    // c = 2 xi sqrt(beta m_eff) delta^(1/4); dc/d(delta) = c / (4 delta).
    const double damping =
        2.0 * damping_ratio_ * std::sqrt(stiffness_ * effective_mass_) * std::sqrt(root);
    response.force += damping * trial.penetration_rate;
    response.stiffness += damping / (4.0 * delta) * trial.penetration_rate;
    response.damping = damping;
  }
  return response;
}

const LawEntry& Jankowski::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "jankowski",
      .formula =
          "`F = β·δ^1.5 + c·δ̇` approaching, `β·δ^1.5` separating; "
          "`c = 2ξ·√(β·√δ·m_eff)`",
      .source = "Jankowski (2005)",
      .parameters = {{"stiffness", Range::positive, "F/L^1.5", "β"},
                     {"damping_ratio", Range::non_negative, "-", "ξ"},
                     restitution_parameter(),
                     effective_mass_parameter()},
      .choices = {calibration_choice()},
      .required = {"stiffness"},
      .exactly_one_of = {{"damping_ratio", "restitution"}},
      .traits = {.stiff_at_first_touch = false},
      .example = {{"stiffness", 4e10}, {"restitution", 0.6}},
      .calibration = RestitutionCalibration{.unit_law =
                                                [](double ratio, const LawSpec&) {
                                                  return std::make_unique<Jankowski>(1.0, ratio,
                                                                                     1.0);
                                                },
                                            .published = jankowski_damping_ratio},
      .make = [](const LawSpec& law, const LawSource& where) -> LawFactory {
        const double k = *law.number("stiffness");
        const double ratio = law.number("damping_ratio")
                                 ? *law.number("damping_ratio")
                                 : calibrated_damping(Jankowski::entry(), law, where);
        return [=](const LinkContext& context) {
          return std::make_unique<Jankowski>(k, ratio, effective_mass(law, where, context));
        };
      }};
  return entry;
}

}  // namespace pound::links
