#pragma once
// The contact laws a model file may name, with their parameters: what the reader checks a law
// object against, what the builder turns into law objects, and what docs/laws.md lists.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pound::builder {

struct LawParameter {
  enum class Range { positive, non_negative, restitution, fraction };  // >0, >=0, (0,1], [0,1)
  std::string name;
  Range range;
  std::string meaning;  // with units
};

struct LawChoice {
  std::string name;
  std::vector<std::string> values;  // the first is the default
  std::string meaning;
};

struct LawType {
  std::string type;
  std::string formula;
  std::string source;
  std::vector<LawParameter> parameters;
  std::vector<LawChoice> choices;
  std::vector<std::string> required;
  // Groups of which exactly one parameter must be given ("damping" or "restitution").
  std::vector<std::vector<std::string>> exactly_one_of;
  // A parameter that, when given, needs others or rules others out.
  std::map<std::string, std::vector<std::string>> needs;
  std::map<std::string, std::vector<std::string>> excludes;
  // Inside a rod_pair generator only (scaled by the adjacent elements).
  std::vector<std::string> generator_only;
};

const std::vector<LawType>& law_catalog();
const LawType* find_law_type(const std::string& type);
std::vector<std::string> law_type_names();

}  // namespace pound::builder
