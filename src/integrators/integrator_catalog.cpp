#include "integrators/integrator_catalog.hpp"

#include <stdexcept>

#include "integrators/central_difference.hpp"
#include "integrators/newmark.hpp"

namespace pound::integrators {

bool IntegratorParameter::admits(double value) const {
  const bool above = minimum_strict ? value > minimum : value >= minimum;
  return above && (!maximum || value <= *maximum);
}

const IntegratorParameter* IntegratorEntry::parameter(std::string_view wanted) const {
  for (const IntegratorParameter& p : parameters)
    if (p.name == wanted) return &p;
  return nullptr;
}

const std::vector<const IntegratorEntry*>& integrator_catalog() {
  // One integrator a line.
  // clang-format off
  static const std::vector<const IntegratorEntry*> entries{
      &Newmark::newmark_entry(),
      &Newmark::hht_entry(),
      &Newmark::generalized_alpha_entry(),
      &CentralDifference::entry(),
  };
  // clang-format on
  return entries;
}

const IntegratorEntry* find_integrator(std::string_view name) {
  for (const IntegratorEntry* entry : integrator_catalog())
    if (entry->name == name) return entry;
  return nullptr;
}

std::vector<std::string> integrator_names() {
  std::vector<std::string> names;
  for (const IntegratorEntry* entry : integrator_catalog()) names.push_back(entry->name);
  return names;
}

std::vector<std::string> preset_names() {
  std::vector<std::string> names;
  for (const IntegratorEntry* entry : integrator_catalog())
    for (const IntegratorPreset& preset : entry->presets) names.push_back(preset.name);
  return names;
}

IntegratorChoice::IntegratorChoice() : IntegratorChoice(preset("newmark_average_acceleration")) {}

IntegratorChoice::IntegratorChoice(const IntegratorEntry& method,
                                   std::map<std::string, double> parameters)
    : method_(&method), parameters_(std::move(parameters)) {}

IntegratorChoice IntegratorChoice::preset(std::string_view name) {
  for (const IntegratorEntry* entry : integrator_catalog())
    for (const IntegratorPreset& preset : entry->presets)
      if (preset.name == name) return IntegratorChoice(*entry, preset.parameters);
  throw std::invalid_argument("unknown integrator '" + std::string(name) + "'");
}

std::vector<IntegratorChoice> IntegratorChoice::studied() {
  std::vector<IntegratorChoice> choices;
  for (const IntegratorEntry* entry : integrator_catalog())
    choices.emplace_back(*entry, entry->study_parameters);
  return choices;
}

double IntegratorChoice::parameter(const std::string& name) const {
  if (auto given = parameters_.find(name); given != parameters_.end()) return given->second;
  const IntegratorParameter* known = method_->parameter(name);
  if (!known) throw std::invalid_argument(method_->name + " has no parameter " + name);
  return known->fallback;
}

std::map<std::string, double> IntegratorChoice::values() const {
  std::map<std::string, double> all;
  for (const IntegratorParameter& p : method_->parameters) all[p.name] = parameter(p.name);
  return all;
}

std::string IntegratorChoice::label() const {
  for (const IntegratorPreset& preset : method_->presets)
    if (IntegratorChoice(*method_, preset.parameters).values() == values()) return preset.name;
  return method_->name;
}

std::unique_ptr<Integrator> IntegratorChoice::make(const ConvergenceTest& test) const {
  return method_->make(values(), test);
}

double IntegratorChoice::acceleration_energy() const {
  return method_->acceleration_energy ? method_->acceleration_energy(values()) : 0.0;
}

std::optional<double> IntegratorChoice::stability_limit() const {
  return method_->stability_limit ? method_->stability_limit(values()) : std::nullopt;
}

bool IntegratorChoice::dissipates() const {
  return method_->dissipates && method_->dissipates(values());
}

}  // namespace pound::integrators
