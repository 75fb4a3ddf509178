#include "io/json_reader.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <system_error>

namespace pound::io {
namespace {

using Json = nlohmann::json;

// One reference token of a JSON pointer (RFC 6901): '~' and '/' are escaped.
std::string pointer_token(std::string_view key) {
  std::string token;
  for (const char c : key) {
    if (c == '~')
      token += "~0";
    else if (c == '/')
      token += "~1";
    else
      token += c;
  }
  return token;
}

std::string child_path(const std::string& path, std::string_view key) {
  return path + "/" + pointer_token(key);
}

// nlohmann reports how many bytes it had read; the offending character is the last of them.
std::string line_and_column(const std::string& text, std::size_t bytes_read) {
  const std::size_t offset = std::min(bytes_read > 0 ? bytes_read - 1 : 0, text.size());
  const auto begin = text.begin();
  const auto line = 1 + std::count(begin, begin + static_cast<std::ptrdiff_t>(offset), '\n');
  const std::size_t newline = offset == 0 ? std::string::npos : text.rfind('\n', offset - 1);
  const std::size_t line_start = newline == std::string::npos ? 0 : newline + 1;
  return fmt::format("line {}, column {}", line, offset - line_start + 1);
}

// nlohmann's message without its own prefix and position ("[json.exception.parse_error.101]
// parse error at line 1, column 9: syntax error while parsing object key - unexpected '}'").
std::string describe_syntax_error(const Json::exception& error, const std::string& last_token) {
  if (error.id == 406) return fmt::format("number out of range: {}", last_token);
  std::string text = error.what();
  const std::size_t position_end = text.find(": ");
  if (text.starts_with("[json.exception.parse_error") && position_end != std::string::npos)
    text.erase(0, position_end + 2);
  const std::size_t dash = text.find(" - ");
  if (text.starts_with("syntax error while parsing") && dash != std::string::npos)
    text = "syntax error: " + text.substr(dash + 3);
  // "; last read: '<token>'" quotes from an earlier point than the position, line breaks shown as
  // <U+000A>; the line and column say it better.
  const std::size_t last_read = text.find("; last read: '");
  if (last_read != std::string::npos) {
    const std::size_t expected = text.rfind("'; expected ");
    text.erase(last_read, expected != std::string::npos && expected > last_read
                              ? expected + 1 - last_read
                              : std::string::npos);
  }
  return text;
}

// A first pass over the text that finds syntax errors (with their position) and keys repeated
// within one object, which a DOM parser would silently resolve to the last one.
class SyntaxChecker final : public Json::json_sax_t {
 public:
  SyntaxChecker(const std::string& text, const std::string& source)
      : text_(text), source_(source) {}

  const std::optional<InputError>& error() const { return error_; }

  bool null() override { return end_value(); }
  bool boolean(bool) override { return end_value(); }
  bool number_integer(number_integer_t) override { return end_value(); }
  bool number_unsigned(number_unsigned_t) override { return end_value(); }
  bool number_float(number_float_t, const string_t&) override { return end_value(); }
  bool string(string_t&) override { return end_value(); }
  bool binary(binary_t&) override { return end_value(); }

  bool start_object(std::size_t) override {
    frames_.emplace_back().in_array = false;
    return true;
  }
  bool key(string_t& key) override {
    Frame& frame = frames_.back();
    frame.key = key;
    if (frame.keys.insert(key).second) return true;
    error_.emplace(source_, pointer(), "field given twice");
    return false;
  }
  bool end_object() override {
    frames_.pop_back();
    return end_value();
  }
  bool start_array(std::size_t) override {
    frames_.emplace_back().in_array = true;
    return true;
  }
  bool end_array() override {
    frames_.pop_back();
    return end_value();
  }
  bool parse_error(std::size_t bytes_read, const std::string& last_token,
                   const Json::exception& error) override {
    error_.emplace(source_, line_and_column(text_, bytes_read),
                   describe_syntax_error(error, last_token));
    return false;
  }

 private:
  struct Frame {
    bool in_array = false;
    std::size_t index = 0;       // of the current element, in an array
    std::string key;             // of the current field, in an object
    std::set<std::string> keys;  // seen so far, in an object
  };

  bool end_value() {
    if (!frames_.empty() && frames_.back().in_array) ++frames_.back().index;
    return true;
  }

  std::string pointer() const {
    std::string path;
    for (const Frame& frame : frames_)
      path = frame.in_array ? child_path(path, std::to_string(frame.index))
                            : child_path(path, frame.key);
    return path;
  }

  const std::string& text_;
  const std::string& source_;
  std::vector<Frame> frames_;
  std::optional<InputError> error_;
};

std::string lowercase(std::string_view text) {
  std::string result(text);
  for (char& c : result) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return result;
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates) {
  const std::optional<std::string> closest = closest_name(name, candidates);
  return closest ? fmt::format(" (did you mean '{}'?)", *closest) : "";
}

std::string count_of_elements(std::size_t count) {
  return fmt::format("{} element{}", count, count == 1 ? "" : "s");
}

// int and long from any JSON number with an integral value in range (2.0 is 2, 2.5 is not).
template <class T>
T read_integer(const JsonValue& value) {
  const Json& json = value.json();
  if (!json.is_number()) value.fail("expected an integer, got " + value.kind());
  constexpr T lowest = std::numeric_limits<T>::min();
  constexpr T highest = std::numeric_limits<T>::max();
  if (json.is_number_unsigned()) {
    const auto number = json.get<std::uint64_t>();
    if (number <= static_cast<std::uint64_t>(highest)) return static_cast<T>(number);
  } else if (json.is_number_integer()) {
    const auto number = json.get<std::int64_t>();
    if (number >= lowest && number <= highest) return static_cast<T>(number);
  } else {
    const auto number = json.get<double>();
    if (number != std::floor(number))
      value.fail(fmt::format("expected an integer, got {}", number));
    // lowest is -2^k, exactly a double; the values in range are [lowest, -lowest).
    const auto bound = static_cast<double>(lowest);
    if (number >= bound && number < -bound) return static_cast<T>(number);
  }
  value.fail(
      fmt::format("expected an integer from {} to {}, got {}", lowest, highest,
                  json.is_number_float() ? fmt::format("{}", json.get<double>()) : json.dump()));
}

}  // namespace

namespace {

// What a path that is not a regular file is, for the message.
std::string kind_of_file(std::filesystem::file_type type) {
  using std::filesystem::file_type;
  switch (type) {
    case file_type::directory:
      return "is a folder, not a file";
    case file_type::fifo:
      return "not a regular file (a FIFO)";
    case file_type::character:
      return "not a regular file (a character device)";
    case file_type::block:
      return "not a regular file (a block device)";
    case file_type::socket:
      return "not a regular file (a socket)";
    default:
      return "not a regular file";
  }
}

std::filesystem::file_type type_of_mode(mode_t mode) {
  using std::filesystem::file_type;
  if (S_ISREG(mode)) return file_type::regular;
  if (S_ISDIR(mode)) return file_type::directory;
  if (S_ISFIFO(mode)) return file_type::fifo;
  if (S_ISCHR(mode)) return file_type::character;
  if (S_ISBLK(mode)) return file_type::block;
  if (S_ISSOCK(mode)) return file_type::socket;
  return file_type::unknown;
}

std::string too_large(std::uintmax_t max_bytes) {
  return fmt::format("the file is larger than {} MB, the most an input file may hold",
                     max_bytes >> 20);
}

// Closes a descriptor on every way out.
struct FileDescriptor {
  int fd;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

void check_input_file(const std::string& path, std::uintmax_t max_bytes) {
  if (path.find('\0') != std::string::npos)
    throw FileAccessError(path.substr(0, path.find('\0')) + "\\0...", "",
                          "a NUL character in the file name");
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::not_found)
    throw FileAccessError(path, "", "no such file");
  if (error) throw FileAccessError(path, "", "cannot access: " + error.message());
  if (!std::filesystem::is_regular_file(status))
    throw FileAccessError(path, "", kind_of_file(status.type()));
  if (std::filesystem::file_size(path, error) > max_bytes && !error)
    throw FileAccessError(path, "", too_large(max_bytes));
}

std::string read_text_file(const std::string& path, std::uintmax_t max_bytes) {
  check_input_file(path, max_bytes);
  // O_NONBLOCK: should the path turn into a FIFO after the check, opening it does not wait for a
  // writer; fstat below then refuses it.
  const FileDescriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
  if (file.fd < 0)
    throw FileAccessError(path, "", fmt::format("cannot open: {}", std::strerror(errno)));
  struct stat opened {};
  if (::fstat(file.fd, &opened) != 0)
    throw FileAccessError(path, "", fmt::format("cannot access: {}", std::strerror(errno)));
  if (!S_ISREG(opened.st_mode))
    throw FileAccessError(path, "", kind_of_file(type_of_mode(opened.st_mode)));
  if (static_cast<std::uintmax_t>(opened.st_size) > max_bytes)
    throw FileAccessError(path, "", too_large(max_bytes));
  // Read to the end, not to st_size: a file still growing is bounded all the same.
  // One spare byte, so a file of its stated size ends with a read of 0 bytes and no copy.
  std::string text(static_cast<std::size_t>(opened.st_size) + 1, '\0');
  std::size_t length = 0;
  for (;;) {
    if (length == text.size()) {
      if (length > max_bytes) throw FileAccessError(path, "", too_large(max_bytes));
      text.resize(static_cast<std::size_t>(
          std::min<std::uintmax_t>(max_bytes + 1, std::max<std::size_t>(4096, 2 * length))));
    }
    const ssize_t count = ::read(file.fd, text.data() + length, text.size() - length);
    if (count < 0 && errno == EINTR) continue;
    if (count < 0)
      throw FileAccessError(path, "", fmt::format("cannot read: {}", std::strerror(errno)));
    if (count == 0) break;
    length += static_cast<std::size_t>(count);
  }
  if (length > max_bytes) throw FileAccessError(path, "", too_large(max_bytes));
  text.resize(length);
  return text;
}

Json parse_json(const std::string& text, const std::string& source) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw InputError(source, "", "the file is empty (expected JSON)");
  // A model saved as UTF-16 (some Windows editors) or a binary file named by mistake: say so,
  // rather than "invalid literal" at its first byte.
  if (text.starts_with("\xFF\xFE") || text.starts_with("\xFE\xFF"))
    throw InputError(source, "", "the file is UTF-16 text; save it as UTF-8");
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
    throw InputError(source, line_and_column(text, nul + 1),
                     "a NUL byte: binary data or UTF-16 text, not UTF-8 JSON");
  SyntaxChecker checker(text, source);
  if (!Json::sax_parse(text, &checker)) {
    if (checker.error()) throw *checker.error();
    throw InputError(source, "", "invalid JSON");
  }
  return Json::parse(text);  // cannot fail: the checker accepted the same text
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Rows of the table of distances between prefixes of `a` (rows) and of `b` (columns); the row
  // before the previous one serves swaps.
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::optional<std::string> closest_name(std::string_view name,
                                        const std::vector<std::string>& candidates) {
  const std::string wanted = lowercase(name);
  std::optional<std::string> best;
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  for (const std::string& candidate : candidates) {
    const std::size_t distance = edit_distance(wanted, lowercase(candidate));
    // About one typo per three characters: "gpa" -> "gap", "matrial" -> "material", but not
    // "foo" -> "fix" or "z" -> "x".
    const std::size_t tolerance = (candidate.size() + 1) / 3;
    if (distance <= tolerance && distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

JsonValue::JsonValue(const Json& json, std::string file, std::string path)
    : json_(&json), file_(std::move(file)), path_(std::move(path)) {}

std::string JsonValue::kind() const {
  switch (json_->type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
      return "a number";
    case Json::value_t::string:
      return "a string";
    case Json::value_t::array:
      return "an array";
    case Json::value_t::object:
      return "an object";
    default:
      return "an unsupported value";
  }
}

void JsonValue::fail(const std::string& what) const { throw InputError(file_, path_, what); }

template <>
double JsonValue::as<double>() const {
  if (!json_->is_number()) fail("expected a number, got " + kind());
  const auto value = json_->get<double>();
  if (!std::isfinite(value)) fail("number out of range");
  return value;
}

template <>
int JsonValue::as<int>() const {
  return read_integer<int>(*this);
}

template <>
long JsonValue::as<long>() const {
  return read_integer<long>(*this);
}

template <>
bool JsonValue::as<bool>() const {
  if (!json_->is_boolean()) fail("expected true or false, got " + kind());
  return json_->get<bool>();
}

template <>
std::string JsonValue::as<std::string>() const {
  if (!json_->is_string()) fail("expected a string, got " + kind());
  std::string text = json_->get<std::string>();
  // A file name "a\u0000b" would open "a": no value of a model or set may hold one.
  if (text.find('\0') != std::string::npos) fail("a NUL character (\\u0000) in the string");
  return text;
}

std::string JsonValue::as_one_of(const std::vector<std::string>& options) const {
  const std::string value = as<std::string>();
  if (std::find(options.begin(), options.end(), value) != options.end()) return value;
  std::string listed;
  for (const std::string& name : options) listed += (listed.empty() ? "'" : ", '") + name + "'";
  fail(fmt::format("expected one of {}, got '{}'{}", listed, value, did_you_mean(value, options)));
}

std::vector<JsonValue> JsonValue::elements(std::size_t min_count, std::size_t max_count) const {
  if (!json_->is_array()) fail("expected an array, got " + kind());
  const std::size_t count = json_->size();
  if (count < min_count || count > max_count) {
    const std::string expected =
        min_count == max_count ? "exactly " + count_of_elements(min_count)
        : max_count == std::numeric_limits<std::size_t>::max()
            ? "at least " + count_of_elements(min_count)
            : fmt::format("{} to {}", min_count, count_of_elements(max_count));
    fail(fmt::format("expected {}, got {}", expected, count));
  }
  std::vector<JsonValue> result;
  result.reserve(count);
  for (std::size_t k = 0; k < count; ++k)
    result.emplace_back((*json_)[k], file_, child_path(path_, std::to_string(k)));
  return result;
}

void JsonValue::check_minimum(double value, Minimum minimum) const {
  const bool met = minimum.strict ? value > minimum.bound : value >= minimum.bound;
  if (!met)
    fail(fmt::format("must be {} {}, got {}", minimum.strict ? ">" : ">=", minimum.bound, value));
}

JsonObject::JsonObject(JsonValue value) : value_(std::move(value)) {
  if (!value_.json().is_object()) fail("expected an object, got " + value_.kind());
}

bool JsonObject::has(std::string_view key) {
  mark_known(key);
  return value_.json().contains(std::string(key));
}

std::optional<JsonValue> JsonObject::find(std::string_view key) {
  mark_known(key);
  const auto found = value_.json().find(std::string(key));
  if (found == value_.json().end()) return std::nullopt;
  return JsonValue(*found, value_.file(), child_path(path(), key));
}

JsonValue JsonObject::at(std::string_view key) {
  if (std::optional<JsonValue> value = find(key)) return *value;
  for (const auto& field : value_.json().items()) {
    const bool schema_name =
        std::find(expected_.begin(), expected_.end(), field.key()) != expected_.end();
    if (!is_known(field.key()) && !schema_name && closest_name(field.key(), {std::string(key)}))
      throw InputError(value_.file(), child_path(path(), field.key()),
                       fmt::format("unknown field (did you mean '{}'?)", key));
  }
  throw InputError(value_.file(), child_path(path(), key), "required field is missing");
}

std::string JsonObject::one_of(std::string_view key, const std::vector<std::string>& options) {
  return at(key).as_one_of(options);
}

std::string JsonObject::one_of(std::string_view key, const std::vector<std::string>& options,
                               std::string_view fallback) {
  const std::optional<JsonValue> value = find(key);
  return value ? value->as_one_of(options) : std::string(fallback);
}

std::vector<JsonValue> JsonObject::array(std::string_view key) {
  const std::optional<JsonValue> value = find(key);
  return value ? value->elements() : std::vector<JsonValue>{};
}

void JsonObject::finish() const {
  for (const auto& field : value_.json().items()) {
    if (!is_known(field.key()))
      throw InputError(value_.file(), child_path(path(), field.key()),
                       "unknown field" + did_you_mean(field.key(), known_));
  }
}

void JsonObject::mark_known(std::string_view key) {
  if (!is_known(key)) known_.emplace_back(key);
}

bool JsonObject::is_known(std::string_view key) const {
  return std::find(known_.begin(), known_.end(), key) != known_.end();
}

void UniqueNames::add(const std::string& name, const JsonValue& where) {
  const auto [first, inserted] = first_.emplace(name, where.path());
  if (!inserted)
    where.fail(fmt::format("duplicate {} '{}' (first at {})", what_, name, first->second));
}

}  // namespace pound::io
