#include "io/registry_docs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <string>

#include "integrators/integrator_catalog.hpp"
#include "io/model_schema.hpp"
#include "links/law_registry.hpp"

namespace pound::io {
namespace {

std::string code(const std::string& text) { return "`" + text + "`"; }

std::string role_text(const links::LawEntry& law) {
  std::string text;
  switch (law.traits.role) {
    case links::LinkRole::contact:
      text = "contact";
      break;
    case links::LinkRole::tension:
      text = "tension";
      break;
    case links::LinkRole::spring:
      text = "spring";
      break;
  }
  if (law.traits.constraint)
    text += "; a constraint, no stiffness";
  else if (law.traits.role == links::LinkRole::contact && !law.traits.stiff_at_first_touch)
    text += "; no stiffness at first touch";
  if (law.traits.uses_approach_velocity) text += "; uses v0";
  if (law.calibratable()) text += "; from e";
  return text;
}

std::string range_text(links::LawParameter::Range range) {
  using Range = links::LawParameter::Range;
  switch (range) {
    case Range::positive:
      return "> 0";
    case Range::non_negative:
      return ">= 0";
    case Range::restitution:
      return "in (0, 1]";
    case Range::fraction:
      return "in [0, 1)";
    case Range::unit:
      return "in (0, 1]";
    case Range::closed_unit:
      return "in [0, 1]";
  }
  return "";
}

// What the law asks for beyond its ranges: required, exactly one of, needs, excludes.
std::string rules_text(const links::LawEntry& law) {
  std::vector<std::string> rules;
  auto quoted = [](const std::vector<std::string>& names, const char* joint) {
    std::string text;
    for (std::size_t k = 0; k < names.size(); ++k)
      text += (k == 0 ? "" : (k + 1 == names.size() ? joint : ", ")) + code(names[k]);
    return text;
  };
  if (!law.required.empty()) rules.push_back("required: " + quoted(law.required, " and "));
  for (const auto& group : law.exactly_one_of)
    rules.push_back("exactly one of " + quoted(group, " or "));
  for (const auto& [name, others] : law.needs)
    rules.push_back(code(name) + " needs " + quoted(others, " and "));
  for (const auto& [name, others] : law.excludes)
    rules.push_back(code(name) + " excludes " + quoted(others, " and "));
  std::string text;
  for (const std::string& rule : rules) text += (text.empty() ? "" : "; ") + rule;
  return text;
}

// The law's example as a model file writes it: {"type": "hertz", "stiffness": 4e+10}.
std::string example_text(const links::LawEntry& law) {
  std::string text = fmt::format("{{\"type\": \"{}\"", law.name);
  for (const links::LawParameter& p : law.parameters)
    if (auto found = law.example.find(p.name); found != law.example.end())
      text += fmt::format(", \"{}\": {:g}", p.name, found->second);
  return text + "}";
}

std::string law_table() {
  std::vector<std::vector<std::string>> rows;
  for (const links::LawEntry* law : links::law_registry())
    rows.push_back({code(law->name), role_text(*law), law->formula, law->source});
  return markdown_table({"type", "role", "formula", "source"}, rows);
}

std::string law_parameter_tables() {
  std::string text;
  for (const links::LawEntry* law : links::law_registry()) {
    std::vector<std::vector<std::string>> rows;
    for (const links::LawParameter& p : law->parameters)
      rows.push_back({code(p.name), "number " + range_text(p.range), p.units,
                      p.meaning + (p.generator_only ? " (inside a rod_pair only)" : "")});
    for (const links::LawChoice& c : law->choices) {
      std::string values;
      for (const std::string& value : c.values)
        values += (values.empty() ? "" : " or ") + code("\"" + value + "\"");
      rows.push_back({code(c.name), values, "", c.meaning + " (default \"" + c.values[0] + "\")"});
    }
    text += fmt::format("\n### {}\n\n", code(law->name));
    if (std::string rules = rules_text(*law); !rules.empty()) {
      rules[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(rules[0])));
      text += fmt::format("{}.\n\n", rules);
    }
    text += markdown_table({"parameter", "value", "units", "meaning"}, rows);
    text += fmt::format("\nFor example `{}`.\n", example_text(*law));
  }
  return text;
}

std::string integrator_table() {
  std::vector<std::vector<std::string>> rows;
  for (const integrators::IntegratorEntry* entry : integrators::integrator_catalog()) {
    std::string parameters, presets;
    for (const integrators::IntegratorParameter& p : entry->parameters)
      parameters += fmt::format("{}{} (default {:g}): {}", parameters.empty() ? "" : "; ",
                                code(p.name), p.fallback, p.meaning);
    for (const integrators::IntegratorPreset& preset : entry->presets) {
      std::string values;
      for (const auto& [name, value] : preset.parameters)
        values += fmt::format("{}{} = {:.6g}", values.empty() ? "" : ", ", name, value);
      presets += (presets.empty() ? "" : "; ") + code("\"" + preset.name + "\"") +
                 (values.empty() ? "" : " (" + values + ")");
    }
    rows.push_back({code(entry->name), entry->is_explicit ? "explicit" : "implicit",
                    parameters.empty() ? "–" : parameters, presets, entry->description});
  }
  return markdown_table({"type", "kind", "parameters", "presets", "method"}, rows);
}

// The words a text quotes ("[a-z0-9_/.]+"), left to right as a regex search would find them
// (std::regex is avoided: GCC 12 warns inside it under the sanitizers, and -Werror stops).
void insert_quoted_words(const std::string& text, std::set<std::string>& words) {
  const auto allowed = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '/' || c == '.';
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '"') continue;
    std::size_t j = i + 1;
    while (j < text.size() && allowed(text[j])) ++j;
    if (j > i + 1 && j < text.size() && text[j] == '"') {
      words.insert(text.substr(i + 1, j - i - 1));
      i = j;
    }
  }
}

// Every key and name of the format: the schema's keys and the choices its tables quote, and the
// registries' names, parameters and choices.
std::set<std::string> vocabulary() {
  std::set<std::string> words;
  for (const FieldDoc& row : model_field_docs()) {
    // A nested object's rows are "scale.pga": its key and its field's.
    for (std::size_t start = 0; start <= row.key.size();) {
      const std::size_t dot = std::min(row.key.find('.', start), row.key.size());
      words.insert(row.key.substr(start, dot - start));
      start = dot + 1;
    }
    insert_quoted_words(row.type, words);
  }
  for (const links::LawEntry* law : links::law_registry()) {
    words.insert(law->name);
    for (const links::LawParameter& p : law->parameters) words.insert(p.name);
    for (const links::LawChoice& c : law->choices) {
      words.insert(c.name);
      words.insert(c.values.begin(), c.values.end());
    }
  }
  for (const integrators::IntegratorEntry* entry : integrators::integrator_catalog()) {
    words.insert(entry->name);
    for (const integrators::IntegratorParameter& p : entry->parameters) words.insert(p.name);
  }
  for (const std::string& preset : integrators::preset_names()) words.insert(preset);
  words.erase("");
  return words;
}

}  // namespace

std::vector<GeneratedSection> law_sections() {
  return {{"laws", law_table}, {"law_parameters", law_parameter_tables}};
}

GeneratedSection integrator_section() { return {"integrators", integrator_table}; }

GeneratedSection vocabulary_section() {
  return {"model_vocabulary", [] {
            std::string text;
            for (const std::string& word : vocabulary())
              text += fmt::format("\"\\\"{}\\\"\"\n", word);
            return text;
          }};
}

}  // namespace pound::io
