#include "io/model_writer.hpp"

#include <algorithm>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "io/model_schema.hpp"
#include "links/law_registry.hpp"

namespace pound::io {
namespace {

using builder::LawSpec;
using builder::ModelSpec;
using Json = nlohmann::ordered_json;  // keys in the order they are set, like the format's tables

constexpr std::size_t kLineWidth = 100;

// One-line JSON with a space after ',' and ':', as model files are written by hand.
std::string inline_text(const Json& value) {
  if (!value.is_structured()) return value.dump();  // numbers in full round-trip precision
  std::string text = value.is_object() ? "{" : "[";
  for (auto item = value.begin(); item != value.end(); ++item) {
    if (item != value.begin()) text += ", ";
    if (value.is_object()) text += Json(item.key()).dump() + ": ";
    text += inline_text(item.value());
  }
  return text + (value.is_object() ? "}" : "]");
}

// Pretty-printing that keeps what fits in a line on one line (a node, a law, an axis) and puts
// the entries of anything longer one per line, so a 200-node model stays readable.
void append_pretty(const Json& value, std::size_t column, std::size_t indent, std::string& out) {
  const std::string flat = inline_text(value);
  if (!value.is_structured() || column + flat.size() < kLineWidth) {  // room for a comma
    out += flat;
    return;
  }
  const std::string inner(indent + 2, ' ');
  out += value.is_object() ? "{\n" : "[\n";
  for (auto item = value.begin(); item != value.end(); ++item) {
    if (item != value.begin()) out += ",\n";
    const std::string key = value.is_object() ? Json(item.key()).dump() + ": " : "";
    out += inner + key;
    append_pretty(item.value(), inner.size() + key.size(), indent + 2, out);
  }
  out += "\n" + std::string(indent, ' ') + (value.is_object() ? "}" : "]");
}

}  // namespace

// Parameters in the registry's order (then any it does not list); choices only where they
// differ from the registry's default, which the reader fills in for every law.
Json law_json(const LawSpec& law) {
  Json json;
  json["type"] = law.type;
  const links::LawEntry* type = links::find_law(law.type);
  std::vector<std::string> order;
  if (type)
    for (const links::LawParameter& parameter : type->parameters) order.push_back(parameter.name);
  for (const auto& [name, value] : law.parameters)
    if (std::find(order.begin(), order.end(), name) == order.end()) order.push_back(name);
  for (const std::string& name : order)
    if (const std::optional<double> value = law.number(name)) json[name] = *value;
  for (const auto& [name, value] : law.choices) {
    std::optional<std::string> fallback;
    if (type)
      for (const links::LawChoice& choice : type->choices)
        if (choice.name == name) fallback = choice.values.front();
    if (value != fallback) json[name] = value;
  }
  return json;
}

// Always the object, with every parameter: a preset name reads back as its parameters.
Json integrator_json(const builder::IntegratorSpec& integrator) {
  Json json;
  json["type"] = integrator.method().name;
  for (const auto& [name, value] : integrator.values()) json[name] = value;
  return json;
}

std::string model_to_json(const ModelSpec& spec) {
  Context context;
  context.dimension = spec.dimension;
  std::string text;
  append_pretty(write_object(spec, model_fields(), context), 0, 0, text);
  return text + "\n";
}

}  // namespace pound::io
