#include "links/law_registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "links/backfill.hpp"
#include "links/bilinear_impact.hpp"
#include "links/bilinear_spring.hpp"
#include "links/bouc_wen.hpp"
#include "links/clough.hpp"
#include "links/elastic_perfectly_plastic.hpp"
#include "links/elastic_spring.hpp"
#include "links/extended_penalty.hpp"
#include "links/gap_spring.hpp"
#include "links/hard_contact.hpp"
#include "links/hertz.hpp"
#include "links/hertz_damp.hpp"
#include "links/jankowski.hpp"
#include "links/kelvin_voigt.hpp"
#include "links/lead_rubber.hpp"
#include "links/restrainer.hpp"
#include "links/takeda.hpp"
#include "links/viscous_damper.hpp"

namespace pound::links {

std::optional<double> LawSpec::number(const std::string& name) const {
  auto found = parameters.find(name);
  return found == parameters.end() ? std::nullopt : std::optional<double>(found->second);
}

std::string LawSpec::choice(const std::string& name, const std::string& fallback) const {
  auto found = choices.find(name);
  return found == choices.end() ? fallback : found->second;
}

const LawParameter* LawEntry::parameter(std::string_view wanted) const {
  for (const LawParameter& p : parameters)
    if (p.name == wanted) return &p;
  return nullptr;
}

bool LawEntry::accepts(const std::string& wanted, const LawSpec& law) const {
  if (!parameter(wanted)) return false;
  for (const auto& [given, excluded] : excludes)
    if (law.number(given) && std::find(excluded.begin(), excluded.end(), wanted) != excluded.end())
      return false;
  return true;
}

LawParameter restitution_parameter() {
  return {"restitution", LawParameter::Range::restitution, "-",
          "target coefficient of restitution e, 0 < e <= 1"};
}

LawChoice calibration_choice() {
  return {
      "calibration",
      {"exact", "published"},
      "how 'restitution' becomes damping: exact (the two-mass impact reaches e) or published (the "
      "source's formula, approximate)"};
}

LawParameter effective_mass_parameter() {
  return {"mass", LawParameter::Range::positive, "M",
          "effective mass m1 m2 / (m1 + m2); default: from the model's lumped masses at the two "
          "nodes"};
}

double effective_mass(const LawSpec& law, const LawSource& where, const LinkContext& context) {
  const double mass = law.number("mass").value_or(context.effective_mass());
  if (!(mass > 0.0) || !std::isfinite(mass))
    throw InputError(where.file, where.path + "/mass",
                     fmt::format("{} needs the effective mass of the bodies it joins, and the "
                                 "model gives {} ({}): give 'mass'",
                                 law.type, mass,
                                 std::isfinite(mass) && mass <= 0.0
                                     ? "both ends fixed or massless, or masses so small that "
                                       "m1 m2 underflows"
                                     : "m1 m2 / (m1 + m2) of its end masses overflows: masses far "
                                       "beyond physical ones"));
  return mass;
}

const std::vector<const LawEntry*>& law_registry() {
  // One law a line.
  // clang-format off
  static const std::vector<const LawEntry*> entries{
      &GapSpring::entry(),
      &KelvinVoigt::entry(),
      &Hertz::entry(),
      &HertzDamp::entry(),
      &Jankowski::entry(),
      &BilinearImpact::entry(),
      &ExtendedPenalty::entry(),
      &HardContact::entry(),
      &Restrainer::restrainer_entry(),
      &Restrainer::hook_entry(),
      &ElasticSpring::entry(),
      &BilinearSpring::entry(),
      &Takeda::entry(),
      &Clough::entry(),
      &ElasticPerfectlyPlastic::entry(),
      &LeadRubber::entry(),
      &BoucWen::entry(),
      &Backfill::entry(),
      &ViscousDamper::entry(),
  };
  // clang-format on
  return entries;
}

const LawEntry* find_law(std::string_view name) {
  for (const LawEntry* entry : law_registry())
    if (entry->name == name) return entry;
  return nullptr;
}

std::vector<std::string> law_names() {
  std::vector<std::string> names;
  for (const LawEntry* entry : law_registry()) names.push_back(entry->name);
  return names;
}

LawFactory make_law(const LawSpec& law, const LawSource& where) {
  const LawEntry* entry = find_law(law.type);
  if (!entry) throw std::invalid_argument("unknown link law " + law.type);
  return entry->make(law, where);
}

}  // namespace pound::links
