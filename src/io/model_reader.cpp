#include "io/model_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "integrators/integrator_catalog.hpp"
#include "io/model_schema.hpp"
#include "links/law_registry.hpp"

namespace pound::io {

void read_record_fields(JsonObject& object, builder::ExcitationSpec& excitation) {
  Context context;
  read_fields(object, record_fields(), excitation, context);
}

namespace {

using builder::IntegratorSpec;
using builder::LawSpec;

Minimum lower_bound(links::LawParameter::Range range) {
  using Range = links::LawParameter::Range;
  return range == Range::positive || range == Range::restitution || range == Range::unit
             ? positive
             : non_negative;
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k)
    text += fmt::format("{}'{}'", k == 0 ? "" : (k + 1 == names.size() ? " or " : ", "), names[k]);
  return text;
}

// A law object checked against its entry in the law registry.
LawSpec read_law(JsonObject& object, LawPlace place) {
  using Range = links::LawParameter::Range;
  LawSpec law;
  law.type = object.one_of("type", links::law_names());
  const links::LawEntry& type = *links::find_law(law.type);
  const std::vector<std::string> no_parameters;
  const std::vector<std::string>& generated_parameters =
      place == LawPlace::pier_hinge ? kGeneratedHingeParameters
      : place == LawPlace::storey   ? kGeneratedStoreyParameters
                                    : no_parameters;
  const auto generated = [&generated_parameters](const std::string& name) {
    return std::ranges::find(generated_parameters, name) != generated_parameters.end();
  };
  for (const std::string& name : type.required)
    if (!generated(name)) (void)object.at(name);
  for (const links::LawParameter& parameter : type.parameters) {
    const std::optional<JsonValue> value = object.find(parameter.name);
    if (!value) continue;
    if (generated(parameter.name))
      value->fail(place == LawPlace::storey
                      ? "the storey's own `stiffness` sets it: leave it out"
                      : "set by the generator (the hinge's elastic stiffness and its yield "
                        "moment): leave it out");
    const double number = value->as<double>(lower_bound(parameter.range));
    if (parameter.range == Range::restitution && number > 1.0)
      value->fail(fmt::format("must be <= 1 (a coefficient of restitution), got {}", number));
    if (parameter.range == Range::fraction && number >= 1.0)
      value->fail(fmt::format("must be < 1, got {}", number));
    if ((parameter.range == Range::unit || parameter.range == Range::closed_unit) && number > 1.0)
      value->fail(fmt::format("must be <= 1, got {}", number));
    if (parameter.generator_only && place != LawPlace::rod_pair)
      value->fail("only allowed inside a rod_pair generator");
    law.parameters[parameter.name] = number;
  }
  for (const links::LawChoice& choice : type.choices)
    law.choices[choice.name] = object.one_of(choice.name, choice.values, choice.values.front());
  object.finish();  // so that a misspelt parameter is reported as such, not as a missing one
  auto given = [&law](const std::string& name) { return law.parameters.count(name) > 0; };
  for (const std::vector<std::string>& group : type.exactly_one_of) {
    const auto count = std::count_if(group.begin(), group.end(), given);
    if (count > 1)
      object.fail(group.size() == 2
                      ? fmt::format("give either '{}' or '{}', not both", group[0], group[1])
                      : fmt::format("give only one of {}", quoted_list(group)));
    if (count == 0) {
      std::vector<std::string> allowed = group;
      if (place != LawPlace::rod_pair)
        std::erase_if(allowed, [&type](const std::string& name) {
          return type.parameter(name)->generator_only;
        });
      object.fail(fmt::format("{} needs {}", law.type, quoted_list(allowed)));
    }
  }
  for (const auto& [name, needed] : type.needs)
    for (const std::string& other : needed)
      if (given(name) && !given(other)) object.fail(fmt::format("'{}' needs '{}'", name, other));
  for (const auto& [name, excluded] : type.excludes)
    for (const std::string& other : excluded)
      if (given(name) && given(other))
        object.at(other).fail(fmt::format("not allowed together with '{}'", name));
  return law;
}

}  // namespace

LawSpec read_law_in(const JsonValue& value, LawPlace place) {
  return read_object(value, [place](JsonObject& law) { return read_law(law, place); });
}

// A method's object ({"type": "hht", "alpha": -0.05}) or the name of a preset.
IntegratorSpec read_integrator(const JsonValue& value) {
  if (value.json().is_string())
    return IntegratorSpec::preset(value.as_one_of(integrators::preset_names()));
  if (!value.json().is_object())
    value.fail("expected an object or a preset name string, got " + value.kind());
  return read_object(value, [](JsonObject& object) {
    IntegratorSpec integrator(
        *integrators::find_integrator(object.one_of("type", integrators::integrator_names())));
    for (const integrators::IntegratorParameter& parameter : integrator.method().parameters) {
      const std::optional<JsonValue> given = object.find(parameter.name);
      if (!given) continue;
      const double number = given->as<double>(Minimum{parameter.minimum, parameter.minimum_strict});
      if (parameter.maximum && number > *parameter.maximum)
        given->fail(fmt::format("must be <= {}, got {}", *parameter.maximum, number));
      integrator.set(parameter.name, number);
    }
    return integrator;
  });
}

builder::ModelSpec parse_model(const std::string& text, const std::string& source) {
  const nlohmann::json document = parse_json(text, source);
  builder::ModelSpec spec;
  spec.source = source;
  Context context;
  read_into(JsonValue(document, source, ""), model_fields(), spec, context);
  return spec;
}

builder::ModelSpec read_model_file(const std::string& path) {
  return parse_model(read_text_file(path), path);
}

}  // namespace pound::io
