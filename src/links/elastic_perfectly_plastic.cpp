#include "links/elastic_perfectly_plastic.hpp"

#include "links/bilinear_spring.hpp"
#include "links/law_registry.hpp"

namespace pound::links {

const LawEntry& ElasticPerfectlyPlastic::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "elastic_perfectly_plastic",
      .formula =
          "`F = k·(δ − p)`, `|F| ≤ F_y`, p grows while `|F| = F_y`: `bilinear_spring` "
          "with b = 0",
      .source =
          "elastic-perfectly-plastic SDOF (Chopra, Dynamics of Structures, §7.1; "
          "OpenSees ElasticPP)",
      .parameters = {{"stiffness", Range::positive, "F/L", "elastic stiffness k"},
                     {"yield_force", Range::positive, "F", "F_y, the force while yielding"}},
      .required = {"stiffness", "yield_force"},
      .traits = {.role = LinkRole::spring, .penalty = false},
      .example = {{"stiffness", 2e7}, {"yield_force", 1e5}},
      .make = [](const LawSpec& law, const LawSource&) -> LawFactory {
        const double k = *law.number("stiffness"), yield = *law.number("yield_force");
        return [=](const LinkContext&) {
          return std::make_unique<BilinearSpring>(k, yield, 0.0, "elastic_perfectly_plastic");
        };
      }};
  return entry;
}

}  // namespace pound::links
