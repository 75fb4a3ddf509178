#include "verification/restitution.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <numbers>

#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "integrators/transient_analysis.hpp"
#include "links/law_registry.hpp"
#include "links/restitution.hpp"
#include "verification/transient_run.hpp"

namespace pound::verification {

RestitutionRow simulate_impact(const ImpactSetup& s, const builder::LawSpec& law,
                               double contact_estimate) {
  const double closing = s.velocity_1 - s.velocity_2;
  builder::ModelSpec spec;
  spec.source = "restitution";
  spec.nodes = {{"a", 0.0, 0.0}, {"b", 0.0, 0.0}};
  spec.masses = {{"a", s.mass_1}, {"b", s.mass_2}};
  spec.initial_velocities = {{"a", s.velocity_1, 0.0}, {"b", s.velocity_2, 0.0}};
  builder::LinkSpec link;
  link.id = "impact";
  link.node_i = "a";
  link.node_j = "b";
  link.gap = s.gap;
  link.axis = std::vector<double>{1.0};
  link.law = law;
  spec.links = {link};
  spec.analysis.time_step = contact_estimate / s.steps_per_contact;
  spec.analysis.duration = s.gap / closing + 4.0 * contact_estimate;
  spec.recorders_given = true;
  const builder::BuiltModel built = builder::build(spec);
  assembly::StructuralSystem system(built.model);

  RestitutionRow row;
  double start = -1.0, end = -1.0, previous_time = 0.0, previous_force = 0.0,
         previous_penetration = 0.0;
  integrators::State state = initial_state(built, system);
  run_analysis(
      built, system, state, [&](const integrators::State& x, const integrators::StepResult&) {
        const double force = x.link_force[0], penetration = x.link_penetration[0];
        const bool contact = force != 0.0;  // tension counts as contact (Kelvin-Voigt, allowed)
        if (contact && start < 0.0) {
          // Contact began where the penetration crossed zero inside the step.
          start = previous_time + (x.time - previous_time) * (-previous_penetration) /
                                      (penetration - previous_penetration);
        }
        if (!contact && previous_force != 0.0 && end < 0.0) {
          // Ended where the penetration crossed zero, or where the force did.
          end = penetration <= 0.0
                    ? previous_time + (x.time - previous_time) * previous_penetration /
                                          (previous_penetration - penetration)
                    : x.time;
        }
        row.peak_force = std::max(row.peak_force, force);
        row.max_penetration = std::max(row.max_penetration, penetration);
        previous_time = x.time;
        previous_force = force;
        previous_penetration = penetration;
      });
  row.contact_time = end - start;
  row.achieved = (state.velocity[1] - state.velocity[0]) / closing;
  return row;
}

namespace {

// Every combination of a law's choices, each a value per choice (the defaults first).
std::vector<std::map<std::string, std::string>> choice_combinations(const links::LawEntry& law) {
  std::vector<std::map<std::string, std::string>> combinations{{}};
  for (const links::LawChoice& choice : law.choices) {
    std::vector<std::map<std::string, std::string>> extended;
    for (const auto& combination : combinations)
      for (const std::string& value : choice.values) {
        extended.push_back(combination);
        extended.back()[choice.name] = value;
      }
    combinations = std::move(extended);
  }
  return combinations;
}

// "kelvin_voigt (clip, exact)": the law and its choices in the registry's order.
std::string variant_label(const links::LawEntry& law,
                          const std::map<std::string, std::string>& choices) {
  std::string values;
  for (const links::LawChoice& choice : law.choices)
    values += (values.empty() ? "" : ", ") + choices.at(choice.name);
  return values.empty() ? law.name : fmt::format("{} ({})", law.name, values);
}

}  // namespace

std::vector<RestitutionRow> restitution_study(const ImpactSetup& s) {
  const double effective_mass = s.mass_1 * s.mass_2 / (s.mass_1 + s.mass_2);
  const double closing = s.velocity_1 - s.velocity_2;
  const double linear_contact = std::numbers::pi * std::sqrt(effective_mass / s.linear_stiffness);
  const double hertz_contact =
      links::hertz_impact(s.hertz_stiffness, effective_mass, closing).duration;
  std::vector<RestitutionRow> rows;
  auto add = [&](const std::string& label, const builder::LawSpec& law, double target,
                 bool calibrated, double contact_estimate) {
    RestitutionRow row = simulate_impact(s, law, contact_estimate);
    row.law = label;
    row.target = target;
    row.calibrated = calibrated;
    rows.push_back(row);
  };
  // Every contact law made from a stiffness alone: once if elastic, at each e in every variant
  // of its choices if it takes a restitution (calibrated: exactly, when not "published").
  for (const double e : {1.0, 0.3, 0.5, 0.7, 0.9})
    for (const links::LawEntry* law : links::law_registry()) {
      if (law->traits.role != links::LinkRole::contact || !law->parameter("stiffness")) continue;
      if (law->calibratable() == (e == 1.0)) continue;
      const bool hertzian = !law->traits.stiff_at_first_touch;
      builder::LawSpec spec{
          .type = law->name,
          .parameters = {{"stiffness", hertzian ? s.hertz_stiffness : s.linear_stiffness}}};
      if (e < 1.0) spec.parameters["restitution"] = e;
      for (const auto& choices : choice_combinations(*law)) {
        spec.choices = choices;
        add(variant_label(*law, choices), spec, e,
            e < 1.0 && spec.choice("calibration", "exact") == "exact",
            hertzian ? hertz_contact : linear_contact);
      }
    }
  return rows;
}

}  // namespace pound::verification
