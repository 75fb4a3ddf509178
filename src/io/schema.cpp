#include "io/schema.hpp"

#include <fmt/format.h>

#include <cmath>

#include "io/generated_docs.hpp"

namespace pound::io {
namespace {

// Axes and directions must have length 1 to this tolerance; 1e-9 leaves room for a unit
// vector's components typed with nine or more significant digits.
constexpr double kUnitLengthTolerance = 1e-9;

// A JSON value as the docs show it: 0.05, "lumped", [0, 0].
std::string shown(const OrderedJson& value) {
  if (value.is_number_float()) return fmt::format("{}", value.get<double>());
  if (!value.is_array()) return value.dump();
  std::string text = "[";
  for (std::size_t k = 0; k < value.size(); ++k) text += (k == 0 ? "" : ", ") + shown(value[k]);
  return text + "]";
}

}  // namespace

void require_dimension(const JsonValue& value, const Context& context, int lowest, int highest) {
  if (context.dimension >= lowest && context.dimension <= highest) return;
  value.fail(lowest == highest
                 ? fmt::format("only allowed when dimension is {}", lowest)
                 : fmt::format("only allowed when dimension is {} or {}", lowest, highest));
}

void require_plane(const JsonValue& value, const Context& context) {
  require_dimension(value, context, 2, 2);
}

UniqueNames& Context::unique(const std::string& scope, const std::string& what) {
  return scopes_.try_emplace(scope, what).first->second;
}

std::string field_table(const std::vector<FieldDoc>& rows) {
  std::vector<std::vector<std::string>> cells;
  for (const FieldDoc& row : rows)
    cells.push_back({"`" + row.key + "`", row.type, row.default_text, row.meaning});
  return markdown_table({"field", "type", "default", "meaning"}, cells);
}

void check_maximum(const JsonValue& where, double value, const Maximum& maximum) {
  if (maximum.strict ? value < maximum.bound : value <= maximum.bound) return;
  if (maximum.message) where.fail(fmt::format(fmt::runtime(maximum.message), value));
  where.fail(
      fmt::format("must be {} {}, got {}", maximum.strict ? "<" : "<=", maximum.bound, value));
}

std::string number_type(const char* noun, const std::optional<Minimum>& minimum,
                        const std::optional<Maximum>& maximum) {
  std::string text = noun;
  if (minimum) text += fmt::format(" {} {}", minimum->strict ? ">" : "≥", minimum->bound);
  if (maximum)
    text +=
        fmt::format("{} {} {}", minimum ? "," : "", maximum->strict ? "<" : "≤", maximum->bound);
  return text;
}

void Text::read(const JsonValue& value, std::string& target, Context&) const {
  target = non_empty ? value.as<std::string>(io::non_empty) : value.as<std::string>();
}

void UniqueName::read(const JsonValue& value, std::string& target, Context& context) const {
  target = value.as<std::string>(non_empty);
  context.unique(scope, "id").add(target, value);
}

Choice<std::string> names_choice(const std::vector<std::string>& names) {
  Choice<std::string> choice;
  for (const std::string& name : names) choice.table.emplace_back(name, name);
  return choice;
}

std::string quoted_names(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k)
    text +=
        fmt::format("{}`\"{}\"`", k == 0 ? "" : (k + 1 == names.size() ? " or " : ", "), names[k]);
  return text;
}

void read_unit_vector(const JsonValue& value, double* components, std::size_t count) {
  double length_squared = 0.0;
  const std::vector<JsonValue> items = value.elements(count, count);
  for (std::size_t k = 0; k < count; ++k) {
    components[k] = items[k].as<double>();
    length_squared += components[k] * components[k];
  }
  const double length = std::sqrt(length_squared);
  if (std::abs(length - 1.0) > kUnitLengthTolerance)
    value.fail(fmt::format("must be a unit vector (length 1 within {}), got length {}",
                           kUnitLengthTolerance, length));
}

void Names::read(const JsonValue& value, value_type& target, Context&) const {
  UniqueNames seen(what);
  target.clear();
  for (const JsonValue& item : value.elements(min_count, max_count)) {
    target.push_back(options.empty() ? item.as<std::string>(non_empty) : item.as_one_of(options));
    seen.add(target.back(), item);
  }
}

std::string Names::type() const {
  const std::string names = options.empty() ? what + " ids" : quoted_names(options);
  return min_count == max_count ? fmt::format("{} {}", min_count, names) : "array of " + names;
}

void Numbers::read(const JsonValue& value, value_type& target, Context&) const {
  target.clear();
  for (const JsonValue& item : value.elements(min_count, max_count))
    target.push_back(minimum ? item.as<double>(*minimum) : item.as<double>());
}

std::string Numbers::type() const {
  return fmt::format("array of {} to {} {}", min_count, max_count, number_type("numbers", minimum));
}

namespace detail {

std::string default_text(const OrderedJson& value) {
  if (value.is_null() || value.is_object() || value.empty() || value == "") return "–";
  return "`" + shown(value) + "`";
}

}  // namespace detail

}  // namespace pound::io
