#pragma once
// Input structs described once. Each field of a spec struct is a Field: its JSON key, the member
// it fills, the kind of value (a number with its bounds, a choice, a unit vector, a nested
// object, ...), its default (the member's initial value in the struct) and a one-line meaning.
// read_fields() reads a struct from its list with JsonObject's checks, so a field the list does
// not ask for is an unknown field with the closest valid name suggested; write_fields() writes it
// back in list order, leaving out values at their default; field_table() renders the list as a
// markdown table for the docs.
//
//   Fields<NodeSpec> fields = {
//       unique_id(&NodeSpec::id, "nodes", "the node's name"),
//       required("x", &NodeSpec::x, Number<>{}, "coordinate [L]"),
//       optional("y", &NodeSpec::y, Number<>{}, "coordinate [L]").in_dimensions(2, 3),
//   };
//
// A rule between fields (exactly one of, needs, excludes) is an entry of the list too: it runs
// where it stands while reading, once the fields before it are read, so that of several faults
// the one reported first stays the same.
#include <fmt/format.h>

#include <array>
#include <concepts>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "io/json_reader.hpp"

namespace pound::io {

using OrderedJson = nlohmann::ordered_json;  // keys in the order they are written

// What a field may depend on beyond its struct: the scene's dimension (y components exist only
// in 2-D), the index of the array entry being read (default file names), and names that must be
// unique within an array or across arrays that share them (link and contact ids).
class Context {
 public:
  int dimension = 1;
  std::size_t index = 0;

  UniqueNames& unique(const std::string& scope, const std::string& what);

 private:
  std::map<std::string, UniqueNames> scopes_;
};

// One row of a field table in the docs.
struct FieldDoc {
  std::string key;
  std::string type;          // "number > 0", "`"lumped"` or `"consistent"`", ...
  std::string default_text;  // "required", "–" or the default value
  std::string meaning;       // with units, and where the field exists ("beam only", "2-D only")
};

// Fails at `value` unless the scene's dimension is within lowest..highest.
void require_dimension(const JsonValue& value, const Context& context, int lowest, int highest);
// Fails at `value` unless the scene is 2-D.
void require_plane(const JsonValue& value, const Context& context);

template <class Spec>
struct Field {
  std::string key;  // empty: a rule
  std::function<void(JsonObject&, Spec&, Context&)> read;
  // The field's JSON, or nothing when the member holds no value (an empty std::optional).
  std::function<std::optional<OrderedJson>(const Spec&, const Context&)> value;
  // The JSON of its default, a value equal to which is left out; none: written whenever set.
  std::function<OrderedJson(const Context&)> fallback;
  std::function<bool(const Spec&)> applies;         // for fields of some variants only
  std::string variants;                             // which, as the docs say ("beam only")
  int lowest_dimension = 1, highest_dimension = 3;  // the scenes it exists in
  std::vector<FieldDoc> docs;  // its row, then those of an inline nested object's fields

  // Read and written only for the variants `applies` accepts (e.g. a beam, from the "type" read
  // before it); for the others the field is unknown. `which` says which, in the docs.
  Field when(std::function<bool(const Spec&)> predicate, const std::string& which) && {
    applies = std::move(predicate);
    docs.front().meaning += " (" + which + ")";
    variants = which;
    return std::move(*this);
  }
  // Only in scenes of dimension lowest..highest; in the others the field is refused where it
  // stands and not written.
  Field in_dimensions(int lowest, int highest) && {
    lowest_dimension = lowest;
    highest_dimension = highest;
    docs.front().meaning += lowest == highest ? fmt::format(" ({}-D only)", lowest)
                                              : fmt::format(" ({}-D and {}-D)", lowest, highest);
    return std::move(*this);
  }
  Field in_plane() && { return std::move(*this).in_dimensions(2, 2); }
  Field in_space() && { return std::move(*this).in_dimensions(3, 3); }
  // Written at its default value too (what a reader of the file looks for first).
  Field always_written() && {
    fallback = nullptr;
    return std::move(*this);
  }
  // For a default the struct cannot show ("the longest record's duration").
  Field default_text(std::string text) && {
    docs.front().default_text = std::move(text);
    return std::move(*this);
  }
};

template <class Spec>
using Fields = std::vector<Field<Spec>>;

// A field given where it does not apply (a beam's field on a truss, backwall_mass without
// backfill), unless another field of the same key does: refused at it with where it applies,
// where "unknown field" alone would send the reader looking for a typo.
template <class Spec>
void refuse_if_given(JsonObject& object, const Fields<Spec>& fields, const Field<Spec>& field,
                     const Spec& spec) {
  if (field.key.empty()) return;
  for (const Field<Spec>& other : fields)
    if (&other != &field && other.key == field.key && (!other.applies || other.applies(spec)))
      return;
  if (const std::optional<JsonValue> value = object.find(field.key))
    value->fail(
        fmt::format("unknown field here: it applies only where the docs say ({})", field.variants));
}

// Reads the fields of `fields` from `object` into `spec`, in order (no check for unknown ones).
template <class Spec>
void read_fields(JsonObject& object, const Fields<Spec>& fields, Spec& spec, Context& context) {
  for (const Field<Spec>& field : fields)
    if (!field.key.empty()) object.expect(field.key);
  for (const Field<Spec>& field : fields) {
    if (field.applies && !field.applies(spec)) {
      refuse_if_given(object, fields, field, spec);
      continue;
    }
    if (context.dimension < field.lowest_dimension || context.dimension > field.highest_dimension) {
      // Not in this scene: refused where it stands, never required.
      if (const std::optional<JsonValue> value = object.find(field.key))
        require_dimension(*value, context, field.lowest_dimension, field.highest_dimension);
      continue;
    }
    field.read(object, spec, context);
  }
}

// Reads an object into `spec`, then rejects every field the list did not ask for.
template <class Spec>
void read_into(const JsonValue& value, const Fields<Spec>& fields, Spec& spec, Context& context) {
  JsonObject object(value);
  read_fields(object, fields, spec, context);
  object.finish();
}

template <class Spec>
void write_fields(const Spec& spec, const Fields<Spec>& fields, OrderedJson& json,
                  const Context& context) {
  for (const Field<Spec>& field : fields) {
    if (!field.value || (field.applies && !field.applies(spec))) continue;
    if (context.dimension < field.lowest_dimension || context.dimension > field.highest_dimension)
      continue;
    std::optional<OrderedJson> value = field.value(spec, context);
    if (value && !(field.fallback && *value == field.fallback(context)))
      json[field.key] = std::move(*value);
  }
}

template <class Spec>
OrderedJson write_object(const Spec& spec, const Fields<Spec>& fields, const Context& context) {
  OrderedJson json = OrderedJson::object();
  write_fields(spec, fields, json, context);
  return json;
}

// The docs table of rows: field, type, default, meaning.
std::string field_table(const std::vector<FieldDoc>& rows);

// The docs rows of a field list (an inline nested object's fields after their field).
template <class Spec>
std::vector<FieldDoc> field_docs(const Fields<Spec>& fields) {
  std::vector<FieldDoc> rows;
  for (const Field<Spec>& field : fields)
    rows.insert(rows.end(), field.docs.begin(), field.docs.end());
  return rows;
}

template <class Spec>
std::string field_table(const Fields<Spec>& fields) {
  return field_table(field_docs(fields));
}

// ---- Reaching members ----

// A field reaches its member through a pointer to member, or through an accessor: a callable on
// the struct that names it as spec_type (an entry of an array, the struct itself).
template <class Access>
struct AccessTraits {
  using Spec = typename Access::spec_type;
};
template <class Struct, class Member>
struct AccessTraits<Member Struct::*> {
  using Spec = Struct;
};
template <class Access>
using SpecOf = typename AccessTraits<Access>::Spec;

template <class Spec, class Access>
auto& member_of(Spec& spec, const Access& access) {
  if constexpr (std::is_member_object_pointer_v<Access>)
    return spec.*access;
  else
    return access(spec);
}

// Entry N of a std::array (a coefficient of a pair, an edge's pressure).
template <class Array, std::size_t N>
struct Entry {
  using spec_type = Array;
  template <class A>
  auto& operator()(A& array) const {
    return std::get<N>(array);
  }
};

// The struct itself: a nested object whose fields belong to the struct that holds it.
template <class Spec>
struct Self {
  using spec_type = Spec;
  template <class S>
  S& operator()(S& spec) const {
    return spec;
  }
};

template <class T>
inline constexpr bool is_optional_v = false;
template <class T>
inline constexpr bool is_optional_v<std::optional<T>> = true;

// ---- Kinds of values ----
// A kind reads a JSON value into its value_type (checking it), writes it and names its type for
// the docs. Objects also give their fields' rows.

template <class Kind>
concept ValueKind = requires(const Kind kind, const JsonValue& json,
                             typename Kind::value_type& target, Context& context) {
  kind.read(json, target, context);
  { kind.write(std::as_const(target), std::as_const(context)) } -> std::same_as<OrderedJson>;
  { kind.type() } -> std::convertible_to<std::string>;
};

// An upper bound: `value < bound` when strict, else `value <= bound`. `message` replaces the
// usual "must be <= 30, got 31"; a "{}" in it shows the value.
struct Maximum {
  double bound;
  bool strict;
  const char* message = nullptr;
};
constexpr Maximum at_most(double bound, const char* message = nullptr) {
  return {bound, false, message};
}
constexpr Maximum below(double bound, const char* message = nullptr) {
  return {bound, true, message};
}

// The checks of a number and their words in the docs, shared by the kinds that hold numbers.
void check_maximum(const JsonValue& where, double value, const Maximum& maximum);
std::string number_type(const char* noun, const std::optional<Minimum>& minimum,
                        const std::optional<Maximum>& maximum = std::nullopt);

// double: any finite number; int or long: an integral value in range.
template <JsonNumber T = double>
struct Number {
  using value_type = T;
  std::optional<Minimum> minimum;
  std::optional<Maximum> maximum;

  void read(const JsonValue& value, T& target, Context&) const {
    target = minimum ? value.as<T>(*minimum) : value.as<T>();
    if (maximum) check_maximum(value, static_cast<double>(target), *maximum);
  }
  OrderedJson write(const T& value, const Context&) const { return value; }
  std::string type() const {
    return number_type(std::same_as<T, double> ? "number" : "integer", minimum, maximum);
  }
};

struct Text {
  using value_type = std::string;
  bool non_empty = false;

  void read(const JsonValue& value, std::string& target, Context&) const;
  OrderedJson write(const std::string& value, const Context&) const { return value; }
  std::string type() const { return non_empty ? "non-empty string" : "string"; }
};

// A non-empty name, unique among the entries of the arrays that share `scope`.
struct UniqueName {
  using value_type = std::string;
  std::string scope;

  void read(const JsonValue& value, std::string& target, Context& context) const;
  OrderedJson write(const std::string& value, const Context&) const { return value; }
  std::string type() const { return "string, unique"; }
};

struct Flag {
  using value_type = bool;
  void read(const JsonValue& value, bool& target, Context&) const { target = value.as<bool>(); }
  OrderedJson write(bool value, const Context&) const { return value; }
  std::string type() const { return "true or false"; }
};

// One of a list of names, each standing for a value of the member: a bool
// ({"lumped", false}, {"consistent", true}), a string, an enum.
template <class V>
struct Choice {
  using value_type = V;
  std::vector<std::pair<std::string, V>> table;

  void read(const JsonValue& value, V& target, Context&) const {
    const std::string name = value.as_one_of(names());
    for (const auto& [entry, meant] : table)
      if (entry == name) target = meant;
  }
  OrderedJson write(const V& value, const Context&) const {
    for (const auto& [name, meant] : table)
      if (meant == value) return name;
    throw std::logic_error("a value missing from its choice table");
  }
  std::string type() const;
  std::vector<std::string> names() const {
    std::vector<std::string> result;
    for (const auto& entry : table) result.push_back(entry.first);
    return result;
  }
};

// The table of a string member whose values are the names themselves.
Choice<std::string> names_choice(const std::vector<std::string>& names);

// Lists the names for the docs: `"a"`, `"b"` or `"c"`.
std::string quoted_names(const std::vector<std::string>& names);

template <class V>
std::string Choice<V>::type() const {
  return quoted_names(names());
}

// Two numbers, [a, b]; `distinct` is the message when they are equal (two periods).
template <JsonNumber T = double>
struct Pair {
  using value_type = std::array<T, 2>;
  std::optional<Minimum> minimum;
  const char* distinct = nullptr;

  void read(const JsonValue& value, value_type& target, Context&) const {
    const std::vector<JsonValue> items = value.elements(2, 2);
    for (std::size_t k = 0; k < 2; ++k)
      target[k] = minimum ? items[k].as<T>(*minimum) : items[k].as<T>();
    if (distinct && target[0] == target[1]) value.fail(distinct);
  }
  OrderedJson write(const value_type& value, const Context&) const {
    return OrderedJson::array({value[0], value[1]});
  }
  std::string type() const {
    const char* noun = std::same_as<T, double> ? "number" : "integer";
    const std::string each = number_type("", minimum);
    return fmt::format("[{0}, {0}]{1}{2}{3}", noun, each.empty() ? "" : ", each", each,
                       distinct ? ", different" : "");
  }
};

// Three numbers [x, y, z] (a vector in space); `nonzero`: not all 0.
struct Triple {
  using value_type = std::array<double, 3>;
  bool nonzero = false;

  void read(const JsonValue& value, value_type& target, Context&) const {
    const std::vector<JsonValue> items = value.elements(3, 3);
    for (std::size_t k = 0; k < 3; ++k) target[k] = items[k].as<double>();
    if (nonzero && target == value_type{}) value.fail("must not be the zero vector");
  }
  OrderedJson write(const value_type& value, const Context&) const {
    return OrderedJson::array({value[0], value[1], value[2]});
  }
  std::string type() const { return nonzero ? "[x, y, z], not all 0" : "[x, y, z]"; }
};

// Up to `max_count` points [x, y, z] (a floor's corners).
struct Triples {
  using value_type = std::vector<std::array<double, 3>>;
  std::size_t max_count = 16;

  void read(const JsonValue& value, value_type& target, Context& context) const {
    target.clear();
    for (const JsonValue& item : value.elements(1, max_count))
      Triple{}.read(item, target.emplace_back(), context);
  }
  OrderedJson write(const value_type& value, const Context& context) const {
    OrderedJson points = OrderedJson::array();
    for (const auto& point : value) points.push_back(Triple{}.write(point, context));
    return points;
  }
  std::string type() const { return fmt::format("array of 1 … {} [x, y, z]", max_count); }
};

// A unit vector with a component per dimension of the scene (a std::vector), or [nx, ny].
void read_unit_vector(const JsonValue& value, double* components, std::size_t count);

template <class Container>
struct UnitVector {
  using value_type = Container;

  void read(const JsonValue& value, Container& target, Context& context) const {
    if constexpr (std::same_as<Container, std::vector<double>>)
      target.resize(static_cast<std::size_t>(context.dimension));
    read_unit_vector(value, target.data(), target.size());
  }
  OrderedJson write(const Container& value, const Context&) const {
    return OrderedJson(std::vector<double>(value.begin(), value.end()));
  }
  std::string type() const {
    return std::same_as<Container, std::vector<double>>
               ? "unit vector: [n] in 1-D, [nx, ny] in 2-D, [nx, ny, nz] in 3-D"
               : "unit vector [nx, ny]";
  }
};

// Distinct names (node ids, edges) of min_count..max_count entries; `options` limits them.
struct Names {
  using value_type = std::vector<std::string>;
  std::string what = "node";  // "duplicate node 'a' ..."; the docs say "node ids"
  std::size_t min_count = 1;
  std::size_t max_count = std::numeric_limits<std::size_t>::max();
  std::vector<std::string> options;

  void read(const JsonValue& value, value_type& target, Context&) const;
  OrderedJson write(const value_type& value, const Context&) const { return value; }
  std::string type() const;
};

// min_count..max_count numbers, each above `minimum` (the spans of a bridge).
struct Numbers {
  using value_type = std::vector<double>;
  std::size_t min_count = 0;
  std::size_t max_count = std::numeric_limits<std::size_t>::max();
  std::optional<Minimum> minimum;

  void read(const JsonValue& value, value_type& target, Context&) const;
  OrderedJson write(const value_type& value, const Context&) const { return value; }
  std::string type() const;
};

// Whether the docs list a nested object's fields in the table of the field that holds it
// ("scale.pga"), or the object has a table of its own (friction, used by several).
enum class Docs { inline_rows, own_table };

// A nested object read into a struct member (or into the struct itself, with Self).
template <class Sub>
struct Object {
  using value_type = Sub;
  Fields<Sub> fields;
  Docs docs = Docs::inline_rows;

  void read(const JsonValue& value, Sub& target, Context& context) const {
    read_into(value, fields, target, context);
  }
  OrderedJson write(const Sub& value, const Context& context) const {
    return write_object(value, fields, context);
  }
  std::string type() const { return "object"; }
  std::vector<FieldDoc> rows() const {
    std::vector<FieldDoc> result;
    if (docs == Docs::inline_rows)
      for (const Field<Sub>& field : fields)
        result.insert(result.end(), field.docs.begin(), field.docs.end());
    return result;
  }
};

// An array of objects, each read from `fields` (the array index in Context::index).
template <class Sub>
struct Objects {
  using value_type = std::vector<Sub>;
  Fields<Sub> fields;
  std::size_t min_count = 0;
  bool in_plane = false;  // every entry only in a 2-D scene

  void read(const JsonValue& value, value_type& target, Context& context) const {
    const std::vector<JsonValue> items = value.elements(min_count);
    const std::size_t outer = context.index;
    for (std::size_t k = 0; k < items.size(); ++k) {
      if (in_plane) require_plane(items[k], context);
      context.index = k;
      read_into(items[k], fields, target.emplace_back(), context);
    }
    context.index = outer;
  }
  OrderedJson write(const value_type& value, const Context& context) const {
    OrderedJson json = OrderedJson::array();
    for (const Sub& item : value) json.push_back(write_object(item, fields, context));
    return json;
  }
  std::string type() const {
    return min_count > 0 ? "non-empty array of objects" : "array of objects";
  }
};

// ---- Fields ----

namespace detail {

std::string default_text(const OrderedJson& value);

template <ValueKind Kind, class Access>
Field<SpecOf<Access>> typed_field(std::string key, Access access, Kind kind, bool required,
                                  std::string meaning) {
  using Spec = SpecOf<Access>;
  using Member = std::remove_cvref_t<decltype(member_of(std::declval<Spec&>(), access))>;
  // A std::optional member holds a value only when the file gives one, unless the kind itself
  // reads and writes the std::optional (adaptive stepping: true, false or an object).
  constexpr bool wrapped =
      is_optional_v<Member> && !std::same_as<Member, typename Kind::value_type>;
  // Shared by the functions below: an object kind holds the field lists of its members.
  const auto shared = std::make_shared<const Kind>(std::move(kind));
  Field<Spec> field;
  field.key = key;
  field.read = [key, access, shared, required](JsonObject& object, Spec& spec, Context& context) {
    const std::optional<JsonValue> value = required ? object.at(key) : object.find(key);
    if (!value) return;  // the member keeps its default
    Member& target = member_of(spec, access);
    if constexpr (wrapped)
      shared->read(*value, target.emplace(), context);
    else
      shared->read(*value, target, context);
  };
  field.value = [access, shared](const Spec& spec,
                                 const Context& context) -> std::optional<OrderedJson> {
    const Member& member = member_of(spec, access);
    if constexpr (wrapped) {
      if (!member) return std::nullopt;
      return shared->write(*member, context);
    } else {
      return shared->write(member, context);
    }
  };
  std::string shown_default = required ? "required" : "–";
  if constexpr (!wrapped) {
    if (!required) {
      field.fallback = [access, shared](const Context& context) {
        const Spec defaults{};
        return shared->write(member_of(defaults, access), context);
      };
      shown_default = default_text(field.fallback(Context{}));
    }
  }
  field.docs.push_back({key, shared->type(), shown_default, std::move(meaning)});
  if constexpr (requires { shared->rows(); })
    for (FieldDoc row : shared->rows()) {
      row.key = key + "." + row.key;
      field.docs.push_back(std::move(row));
    }
  return field;
}

}  // namespace detail

// A field that must be given.
template <class Access, ValueKind Kind>
Field<SpecOf<Access>> required(std::string key, Access access, Kind kind, std::string meaning) {
  return detail::typed_field(std::move(key), access, std::move(kind), true, std::move(meaning));
}

// A field that may be left out: the member then keeps its initial value in the struct (or stays
// empty, for a std::optional), which the writer leaves out too unless always_written().
template <class Access, ValueKind Kind>
Field<SpecOf<Access>> optional(std::string key, Access access, Kind kind, std::string meaning) {
  return detail::typed_field(std::move(key), access, std::move(kind), false, std::move(meaning));
}

// The struct's "id": a non-empty name unique among the arrays that share `scope`.
template <class Access>
Field<SpecOf<Access>> unique_id(Access access, std::string scope, std::string meaning) {
  return required("id", access, UniqueName{std::move(scope)}, std::move(meaning));
}

// A field that needs code: `read` finds its key in the object itself, `value` gives its JSON
// (nothing: not written).
template <class Spec>
Field<Spec> custom(FieldDoc doc, std::function<void(JsonObject&, Spec&, Context&)> read,
                   std::function<std::optional<OrderedJson>(const Spec&, const Context&)> value) {
  Field<Spec> field;
  field.key = doc.key;
  field.read = std::move(read);
  field.value = std::move(value);
  field.docs.push_back(std::move(doc));
  return field;
}

// A "type" that names what the object is: checked against `name` when given, always written.
template <class Spec>
Field<Spec> tag(std::string key, std::string name, std::string meaning) {
  return custom<Spec>(
      {key, quoted_names({name}), "required", std::move(meaning)},
      [key, name](JsonObject& object, Spec&, Context&) { (void)object.one_of(key, {name}, name); },
      [name](const Spec&, const Context&) -> std::optional<OrderedJson> { return name; });
}

// A nested object whose fields belong to the struct itself ("scale": {"pga": 0.4}); left out
// when it would read the same as a default struct's.
template <class Spec>
Field<Spec> nested(std::string key, Fields<Spec> fields, std::string meaning) {
  return optional(std::move(key), Self<Spec>{}, Object<Spec>{std::move(fields)},
                  std::move(meaning));
}

// The index of the array entry being read, kept in the struct (surfaces and contacts are named by
// it in messages).
template <class Spec>
Field<Spec> array_index(int Spec::*member) {
  Field<Spec> field;
  field.read = [member](JsonObject&, Spec& spec, Context& context) {
    spec.*member = static_cast<int>(context.index);
  };
  return field;
}

// A rule between fields: runs where it stands in the list while reading.
template <class Spec>
Field<Spec> rule(std::function<void(JsonObject&, Spec&, Context&)> check) {
  Field<Spec> field;
  field.read = std::move(check);
  return field;
}

}  // namespace pound::io
