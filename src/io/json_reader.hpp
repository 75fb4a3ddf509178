#pragma once
// Checked reading of JSON input files (models, batch sets). Every value carries its file name and
// JSON pointer, so a wrong type, a value out of range, a missing or an unknown field is reported
// as an InputError that says exactly where it is and what was expected:
//
//   JsonObject link(value);                                     // "expected an object, got ..."
//   const double gap = link.optional<double>("gap", 0.0, non_negative);
//   link.finish();                       // "/links/0/gpa: unknown field (did you mean 'gap'?)"
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/errors.hpp"

namespace pound::io {

// Upper bounds on one input file, checked before it is read, so a file named by mistake (a disk
// image, a log) is refused at once rather than read into memory. A model or set is text a person
// writes or a generator emits: the largest explicit models (10^6 nodes at ~100 bytes each) stay
// well under 256 MB. A record of 10 minutes at 1 kHz is ~10 MB of text; 1 GB is ~60 million
// samples, beyond any recorded or synthetic ground motion.
inline constexpr std::uintmax_t kMaxDocumentBytes = std::uintmax_t{256} << 20;
inline constexpr std::uintmax_t kMaxRecordBytes = std::uintmax_t{1} << 30;

// An input file that cannot be read at all (missing, not a regular file, too large,
// unreadable), as opposed to one whose content is wrong: a caller that knows where the name came
// from (a model's JSON path) re-reports it there.
class FileAccessError : public InputError {
 public:
  using InputError::InputError;
};

// Fails as read_text_file would, without reading: for files checked early and read later.
void check_input_file(const std::string& path, std::uintmax_t max_bytes = kMaxDocumentBytes);

// Reads a whole regular file (symlinks followed) of at most `max_bytes`. Missing files, folders,
// FIFOs, devices, sockets, larger files and unreadable files are FileAccessErrors naming `path`;
// nothing blocks and nothing is read beyond `max_bytes`.
std::string read_text_file(const std::string& path, std::uintmax_t max_bytes = kMaxDocumentBytes);

// Parses JSON text. Syntax errors name the line and column; a key given twice in one object (which
// JSON parsers silently resolve) names its JSON path; empty text is an error too.
nlohmann::json parse_json(const std::string& text, const std::string& source);

// Levenshtein distance that also counts a swap of two adjacent characters ("gpa") as one edit
// (optimal string alignment).
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to a misspelt `name`, if it is close enough to be a likely typo.
std::optional<std::string> closest_name(std::string_view name,
                                        const std::vector<std::string>& candidates);

// A lower bound for a number: `value > bound` when strict, else `value >= bound`.
struct Minimum {
  double bound;
  bool strict;
};
inline constexpr Minimum positive{0.0, true};
inline constexpr Minimum non_negative{0.0, false};
constexpr Minimum at_least(double bound) { return {bound, false}; }

// A string that must not be empty (ids, names).
struct NonEmpty {};
inline constexpr NonEmpty non_empty{};

template <class T>
concept JsonNumber = std::same_as<T, double> || std::same_as<T, int> || std::same_as<T, long>;

// One value of a parsed document with the file and JSON pointer it came from. It refers to the
// document, which must outlive it.
class JsonValue {
 public:
  JsonValue(const nlohmann::json& json, std::string file, std::string path);

  const nlohmann::json& json() const { return *json_; }
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }

  // What kind of value this is, for messages: "a number", "an object", ...
  std::string kind() const;

  // Throws an InputError located at this value.
  [[noreturn]] void fail(const std::string& what) const;

  // The value as T: double (any finite number), int or long (an integer in range; 2.0 counts),
  // bool or std::string (without NUL characters, which would cut a file name short). Anything else
  // fails with "expected a number, got a string".
  template <class T>
  T as() const;

  template <JsonNumber T>
  T as(Minimum minimum) const {
    const T value = as<T>();
    check_minimum(static_cast<double>(value), minimum);
    return value;
  }

  template <std::same_as<std::string> T>
  T as(NonEmpty) const {
    T value = as<T>();
    if (value.empty()) fail("expected a non-empty string");
    return value;
  }

  // A string that must be one of `options`; a near miss is suggested.
  std::string as_one_of(const std::vector<std::string>& options) const;

  // The elements of an array with min_count..max_count elements.
  std::vector<JsonValue> elements(
      std::size_t min_count = 0,
      std::size_t max_count = std::numeric_limits<std::size_t>::max()) const;

 private:
  void check_minimum(double value, Minimum minimum) const;

  const nlohmann::json* json_;
  std::string file_;
  std::string path_;
};

template <>
double JsonValue::as<double>() const;
template <>
int JsonValue::as<int>() const;
template <>
long JsonValue::as<long>() const;
template <>
bool JsonValue::as<bool>() const;
template <>
std::string JsonValue::as<std::string>() const;

// A JSON object whose fields are read by name. Every name asked for counts as a valid field;
// finish() then rejects any other field, suggesting the closest valid name. Checks pass on to
// JsonValue::as, e.g. required<double>("area", positive) or required<std::string>("id", non_empty).
class JsonObject {
 public:
  explicit JsonObject(JsonValue value);  // fails unless the value is an object

  const JsonValue& value() const { return value_; }
  const std::string& path() const { return value_.path(); }
  [[noreturn]] void fail(const std::string& what) const { value_.fail(what); }

  bool has(std::string_view key);
  // `key` is a field of this object's schema, read later or not at all (another variant's): a
  // missing required field is not reported as a typo of it. finish() still rejects it unless
  // asked for.
  void expect(std::string_view key) { expected_.emplace_back(key); }
  std::optional<JsonValue> find(std::string_view key);
  // A required field. When it is missing but a field not asked for is a near miss of it, that
  // typo is reported instead ("/e/0/matrial: unknown field (did you mean 'material'?)").
  JsonValue at(std::string_view key);

  template <class T, class... Check>
  T required(std::string_view key, const Check&... check) {
    return at(key).template as<T>(check...);
  }

  template <class T, class... Check>
  T optional(std::string_view key, T fallback, const Check&... check) {
    const std::optional<JsonValue> value = find(key);
    return value ? value->template as<T>(check...) : fallback;
  }

  template <class T, class... Check>
  std::optional<T> if_present(std::string_view key, const Check&... check) {
    const std::optional<JsonValue> value = find(key);
    if (!value) return std::nullopt;
    return value->template as<T>(check...);
  }

  std::string one_of(std::string_view key, const std::vector<std::string>& options);
  std::string one_of(std::string_view key, const std::vector<std::string>& options,
                     std::string_view fallback);

  // The elements of an optional array field; none when it is absent.
  std::vector<JsonValue> array(std::string_view key);

  // Fails on the first field that was never asked for.
  void finish() const;

 private:
  void mark_known(std::string_view key);
  bool is_known(std::string_view key) const;

  JsonValue value_;
  std::vector<std::string> known_;
  // Names of this object's schema not asked for yet: never taken for a typo of another field.
  std::vector<std::string> expected_;
};

// Names that must be unique within one list (ids, file names); a repeat fails naming both places.
class UniqueNames {
 public:
  explicit UniqueNames(std::string what) : what_(std::move(what)) {}
  void add(const std::string& name, const JsonValue& where);

 private:
  std::string what_;                          // "id", "file name", ...
  std::map<std::string, std::string> first_;  // name -> JSON path of its first use
};

// Reads an object with `read`, then rejects every field that `read` did not ask for.
template <class Read>
auto read_object(const JsonValue& value, Read read) {
  JsonObject object(value);
  if constexpr (std::is_void_v<std::invoke_result_t<Read, JsonObject&>>) {
    read(object);
    object.finish();
  } else {
    auto spec = read(object);
    object.finish();
    return spec;
  }
}

}  // namespace pound::io
