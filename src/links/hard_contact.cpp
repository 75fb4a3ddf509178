#include "links/hard_contact.hpp"

#include "links/law_registry.hpp"

namespace pound::links {

std::unique_ptr<LinkLaw> HardContact::clone() const {
  auto copy = std::make_unique<HardContact>(restitution_);
  copy->trial_force_ = copy->committed_force_ = committed_force_;
  return copy;
}

const LawEntry& HardContact::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "hard_contact",
      .formula = "δ ≤ 0, F ≥ 0, F·δ = 0; across an impact δ̇⁺ = −e·δ̇⁻",
      .source =
          "Carpenter, Taylor & Katona (1991), forward-increment Lagrange multipliers; Moreau "
          "(1988) and Jean (1999) for the impact law at velocity level",
      .parameters = {{"restitution", Range::closed_unit, "-",
                      "e in [0, 1]: 0 between meshes (their elasticity bounces), e of the bodies "
                      "for lumped masses"}},
      .required = {"restitution"},
      .traits = {.role = LinkRole::contact,
                 .stiff_at_first_touch = false,
                 .penalty = false,
                 .constraint = true},
      .example = {{"restitution", 0.6}},
      .make = [](const LawSpec& law, const LawSource&) -> LawFactory {
        const double e = *law.number("restitution");
        return [e](const LinkContext&) { return std::make_unique<HardContact>(e); };
      }};
  return entry;
}

}  // namespace pound::links
