#include "builder/spec.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "links/coupled_shear.hpp"

namespace pound::builder {

double level_tolerance(const AdjacentBuildingsSpec& pair) {
  double lowest = INFINITY;
  for (const BuildingSpec* building : {&pair.left, &pair.right})
    for (const StoreySpec& storey : building->storeys) lowest = std::min(lowest, storey.height);
  return 0.05 * lowest;
}

double UnitsSpec::gravity() const {
  static const std::map<std::string, double> metres = {
      {"m", 1.0}, {"cm", 0.01}, {"mm", 1e-3}, {"km", 1000.0}, {"in", 0.0254}, {"ft", 0.3048}};
  static const std::map<std::string, double> seconds = {{"s", 1.0}, {"ms", 1e-3}};
  const double metre = metres.at(length), second = seconds.at(time);
  return 9.80665 / metre * second * second;
}

namespace {
// Whether a generator's law has a coupled form once the generator sets its `numbers`.
bool couples_with(LawSpec law, const std::map<std::string, double>& numbers,
                  const links::LawSource& where) {
  for (const auto& [name, value] : numbers) law.parameters[name] = value;
  return links::CoupledShear::numbers_of(law, where).has_value();
}
}  // namespace

bool PierHingeSpec::law_couples(const links::LawSource& where) const {
  return couples_with(law, {{"stiffness", 1.0}, {"yield_force", 1.0}}, where);
}

bool StoreySpec::law_couples(const links::LawSource& where) const {
  return law && couples_with(*law, {{"stiffness", stiffness}}, where);
}

double UnitsSpec::second() const { return time == "ms" ? 1000.0 : 1.0; }

std::optional<std::string> UnitsSpec::force() const {
  if (!mass) return std::nullopt;
  static const std::map<std::string, double> metres = {
      {"m", 1.0}, {"cm", 0.01}, {"mm", 1e-3}, {"km", 1000.0}, {"in", 0.0254}, {"ft", 0.3048}};
  static const std::map<std::string, double> kilograms = {{"kg", 1.0}, {"t", 1000.0}};
  const double second = time == "ms" ? 1e-3 : 1.0;
  const double newtons = kilograms.at(*mass) * metres.at(length) / (second * second);
  for (const auto& [name, size] : {std::pair{"N", 1.0}, {"kN", 1e3}, {"MN", 1e6}, {"mN", 1e-3}})
    if (std::abs(newtons / size - 1.0) < 1e-12) return name;
  return *mass + "*" + length + "/" + time + "^2";
}

// ASCII, so that a CSV header reads the same in every spreadsheet.
UnitNames UnitsSpec::names() const {
  UnitNames units;
  auto set = [&units](Dimension dimension, std::string name) {
    units.names[static_cast<std::size_t>(dimension)] = std::move(name);
  };
  set(Dimension::time, time);
  set(Dimension::length, length);
  set(Dimension::velocity, length + "/" + time);
  set(Dimension::acceleration, length + "/" + time + "^2");
  set(Dimension::angle, "rad");
  set(Dimension::angular_velocity, "rad/" + time);
  set(Dimension::angular_acceleration, "rad/" + time + "^2");
  if (const std::optional<std::string> newton = force()) {
    set(Dimension::force, *newton);
    set(Dimension::moment, *newton + "*" + length);
  }
  return units;
}

}  // namespace pound::builder
