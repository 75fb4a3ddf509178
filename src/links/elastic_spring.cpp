#include "links/elastic_spring.hpp"

#include "links/law_registry.hpp"

namespace pound::links {

LawResponse ElasticSpring::set_trial(const LinkKinematics& trial) {
  trial_loaded_ = trial.penetration != 0.0;
  return {.force = stiffness_ * trial.penetration, .stiffness = stiffness_};
}

const LawEntry& ElasticSpring::entry() {
  static const LawEntry entry{
      .name = "elastic_spring",
      .formula = "`F = k·δ` in compression and tension",
      .source = "linear bearing / abutment spring (Caltrans SDC; OpenSees Elastic material)",
      .parameters = {{"stiffness", LawParameter::Range::positive, "F/L", "k"}},
      .required = {"stiffness"},
      .traits = {.role = LinkRole::spring, .penalty = false},
      .example = {{"stiffness", 2e7}},
      .make = [](const LawSpec& law, const LawSource&) -> LawFactory {
        const double k = *law.number("stiffness");
        return [k](const LinkContext&) { return std::make_unique<ElasticSpring>(k); };
      }};
  return entry;
}

}  // namespace pound::links
