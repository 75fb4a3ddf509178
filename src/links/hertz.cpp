#include "links/hertz.hpp"

#include <cmath>

#include "links/law_registry.hpp"

namespace pound::links {

LawResponse Hertz::set_trial(const LinkKinematics& trial) {
  trial_contact_ = trial.penetration > 0.0;
  if (!trial_contact_) return {};
  const double root = std::sqrt(trial.penetration);
  return {.force = stiffness_ * trial.penetration * root, .stiffness = 1.5 * stiffness_ * root};
}

const LawEntry& Hertz::entry() {
  static const LawEntry entry{
      .name = "hertz",
      .formula = "`F = k_h·δ^1.5` for δ > 0",
      .source = "Hertz (1882); Davis (1992)",
      .parameters = {{"stiffness", LawParameter::Range::positive, "F/L^1.5", "k_h"}},
      .required = {"stiffness"},
      .traits = {.stiff_at_first_touch = false},
      .example = {{"stiffness", 4e10}},
      .make = [](const LawSpec& law, const LawSource&) -> LawFactory {
        const double k = *law.number("stiffness");
        return [k](const LinkContext&) { return std::make_unique<Hertz>(k); };
      }};
  return entry;
}

}  // namespace pound::links
