#include "links/gap_spring.hpp"

#include "links/law_registry.hpp"

namespace pound::links {

GapSpring::GapSpring(double stiffness) : stiffness_(stiffness) {}

std::unique_ptr<LinkLaw> GapSpring::clone() const {
  auto copy = std::make_unique<GapSpring>(stiffness_);
  copy->trial_contact_ = copy->committed_contact_ = committed_contact_;
  return copy;
}

LawResponse GapSpring::set_trial(const LinkKinematics& trial) {
  trial_contact_ = trial.penetration > 0.0;
  if (!trial_contact_) return {};
  return {.force = stiffness_ * trial.penetration, .stiffness = stiffness_};
}

const LawEntry& GapSpring::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{.name = "gap_spring",
                              .formula = "`F = k·δ` for δ > 0",
                              .source = "Kawashima (1980); the linear penalty of Maison & Kasai",
                              .parameters = {{"stiffness", Range::positive, "F/L", "k"},
                                             {"stiffness_ratio", Range::positive, "-",
                                              "k over E·A/h of the softer adjacent element", true}},
                              .exactly_one_of = {{"stiffness", "stiffness_ratio"}},
                              .example = {{"stiffness", 1e9}},
                              .make = [](const LawSpec& law, const LawSource&) -> LawFactory {
                                const double k = *law.number("stiffness");
                                return [k](const LinkContext&) {
                                  return std::make_unique<GapSpring>(k);
                                };
                              }};
  return entry;
}

}  // namespace pound::links
