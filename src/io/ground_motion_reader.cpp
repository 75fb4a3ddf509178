#include "io/ground_motion_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/uuid/detail/sha1.hpp>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "core/errors.hpp"
#include "io/json_reader.hpp"

namespace pound::io {
namespace {

constexpr double kStandardGravity = 9.80665;    // m/s^2, exact by definition
constexpr std::size_t kHeaderSearchLines = 12;  // an AT2's NPTS line is among the first lines
constexpr std::size_t kPeerHeaderLines = 4;     // a PEER AT2's NPTS line is the 4th
constexpr double kTimeStepAgreement = 1e-6;     // relative: a dt given twice must agree
constexpr double kTimeColumnJitter = 0.01;      // of dt: printed times are rounded
constexpr std::size_t kQuoteLength = 72;

struct Line {
  std::string_view text;
  int number;  // 1-based
};

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
  throw InputError(path, line > 0 ? fmt::format("line {}", line) : std::string(), what);
}

// "1 value", "2 values".
std::string count_of(std::size_t count, std::string_view noun) {
  return fmt::format("{} {}{}", count, noun, count == 1 ? "" : "s");
}

bool is_blank(std::string_view text) {
  return text.find_first_not_of(" \t\f\v") == std::string_view::npos;
}

std::string_view trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t\f\v");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\f\v") - first + 1);
}

// A piece of the file for a message: trimmed and cut short.
std::string quoted(std::string_view text) {
  text = trimmed(text);
  if (text.size() <= kQuoteLength) return fmt::format("'{}'", text);
  return fmt::format("'{}...'", text.substr(0, kQuoteLength));
}

std::string lowercase(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

// Lines ending in "\n", "\r\n" or a lone "\r" (classic Mac files).
std::vector<Line> split_lines(std::string_view text) {
  std::vector<Line> lines;
  int number = 1;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find_first_of("\r\n", start);
    if (end == std::string_view::npos) {
      lines.push_back({text.substr(start), number});
      break;
    }
    lines.push_back({text.substr(start, end - start), number++});
    const bool crlf = text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n';
    start = end + (crlf ? 2 : 1);
  }
  return lines;
}

// Control characters other than white space mean the file is not text (a spreadsheet, an
// archive, a binary record). Bytes above 0x7f may be Latin-1 or UTF-8 header text.
void reject_binary(const std::string& path, const std::vector<Line>& lines) {
  for (const Line& line : lines) {
    for (std::size_t column = 0; column < line.text.size(); ++column) {
      const auto byte = static_cast<unsigned char>(line.text[column]);
      const bool space = byte == '\t' || byte == '\f' || byte == '\v';
      if ((byte < 0x20 && !space) || byte == 0x7f)
        fail(path, line.number,
             fmt::format("binary data, not a text record (byte 0x{:02x} in column {})", byte,
                         column + 1));
    }
  }
}

// ---- numbers -------------------------------------------------------------------------------

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_sign(char c) { return c == '+' || c == '-'; }
bool is_word_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_word_char(char c) { return is_word_start(c) || is_digit(c); }

// Length of the Fortran-style number at the start of `text`: [+-] digits [. digits]
// [EeDd [+-] digits] with at least one mantissa digit; 0 if there is none.
std::size_t number_length(std::string_view text) {
  std::size_t i = 0, digits = 0;
  if (i < text.size() && is_sign(text[i])) ++i;
  for (; i < text.size() && is_digit(text[i]); ++i) ++digits;
  if (i < text.size() && text[i] == '.')
    for (++i; i < text.size() && is_digit(text[i]); ++i) ++digits;
  if (digits == 0) return 0;
  if (i < text.size() && std::string_view("EeDd").find(text[i]) != std::string_view::npos) {
    std::size_t j = i + 1;
    if (j < text.size() && is_sign(text[j])) ++j;
    const std::size_t exponent = j;
    while (j < text.size() && is_digit(text[j])) ++j;
    if (j > exponent) i = j;
  }
  return i;
}

bool is_whole_number(std::string_view number) {
  return number.find_first_of(".EeDd") == std::string_view::npos;
}

// The value of a number accepted by number_length (Fortran D exponents included); infinite when
// it overflows.
double number_value(std::string_view number) {
  std::string text(number.substr(number.front() == '+' ? 1 : 0));
  for (char& c : text)
    if (c == 'D' || c == 'd') c = 'e';
  double value = 0.0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  // Out of range is an overflow (infinite) or an underflow (zero or subnormal); strtod says which.
  if (result.ec == std::errc::result_out_of_range) return std::strtod(text.c_str(), nullptr);
  return value;
}

bool names_non_finite(std::string_view field) {
  if (!field.empty() && is_sign(field.front())) field.remove_prefix(1);
  const std::string word = lowercase(field);
  return word == "nan" || word == "inf" || word == "infinity" || word.starts_with("nan(") ||
         word.starts_with("1.#");  // 1.#INF, 1.#QNAN from old Windows runtimes
}

enum class FieldKind { numbers, not_a_number, not_finite };

// Appends the numbers of one field. A field may hold several numbers glued together by
// Fortran fixed-width output ("-.1234E-02-.5678E-03"): a sign right after a number starts the
// next one.
FieldKind read_field(std::string_view field, std::vector<double>& numbers) {
  if (names_non_finite(field)) return FieldKind::not_finite;
  const std::size_t before = numbers.size();
  while (!field.empty()) {
    const std::size_t length = number_length(field);
    if (length == 0 || (length < field.size() && !is_sign(field[length]))) {
      numbers.resize(before);
      return FieldKind::not_a_number;
    }
    const double value = number_value(field.substr(0, length));
    if (!std::isfinite(value)) {
      numbers.resize(before);
      return FieldKind::not_finite;
    }
    numbers.push_back(value);
    field.remove_prefix(length);
  }
  return FieldKind::numbers;
}

// Fields of a data line: separated by blanks, tabs, commas or semicolons.
std::vector<std::string_view> split_fields(std::string_view text) {
  std::vector<std::string_view> fields;
  constexpr std::string_view separators = " \t\f\v,;";
  std::size_t start = text.find_first_not_of(separators);
  while (start != std::string_view::npos) {
    const std::size_t end = text.find_first_of(separators, start);
    fields.push_back(text.substr(start, end == std::string_view::npos ? end : end - start));
    start = text.find_first_not_of(separators, end);
  }
  return fields;
}

// Whether a line reads as data (numbers, possibly NaN, which is then reported as such).
bool is_data_line(std::string_view text) {
  const std::vector<std::string_view> fields = split_fields(text);
  std::vector<double> ignored;
  return !fields.empty() && std::all_of(fields.begin(), fields.end(), [&](std::string_view field) {
    return read_field(field, ignored) != FieldKind::not_a_number;
  });
}

std::vector<double> read_numbers(const std::string& path, const Line& line, std::string_view text) {
  std::vector<double> numbers;
  for (std::string_view field : split_fields(text)) {
    switch (read_field(field, numbers)) {
      case FieldKind::numbers:
        break;
      case FieldKind::not_a_number:
        fail(path, line.number, fmt::format("{} is not a number", quoted(field)));
      case FieldKind::not_finite:
        fail(path, line.number,
             fmt::format("{} is not a finite number (an acceleration must be finite)",
                         quoted(field)));
    }
  }
  return numbers;
}

// ---- header lines --------------------------------------------------------------------------

struct Token {
  enum class Kind { word, number, symbol } kind;
  std::string_view text;
};

// Words (a letter, then letters, digits, '_'), numbers and single other characters.
std::vector<Token> header_tokens(std::string_view line) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    if (is_blank(line.substr(i, 1))) {
      ++i;
      continue;
    }
    std::size_t length = number_length(line.substr(i));
    Token::Kind kind = Token::Kind::number;
    if (length == 0 && is_word_start(line[i])) {
      kind = Token::Kind::word;
      for (length = 1; i + length < line.size() && is_word_char(line[i + length]); ++length) {
      }
    } else if (length == 0) {
      kind = Token::Kind::symbol;
      length = 1;
    }
    tokens.push_back({kind, line.substr(i, length)});
    i += length;
  }
  return tokens;
}

bool is_word(const Token& token, std::string_view name) {
  return token.kind == Token::Kind::word && lowercase(token.text) == lowercase(name);
}

bool is_symbol(const Token& token, std::string_view symbols) {
  return token.kind == Token::Kind::symbol &&
         symbols.find(token.text.front()) != std::string_view::npos;
}

std::optional<std::size_t> find_word(const std::vector<Token>& tokens, std::string_view name) {
  for (std::size_t i = 0; i < tokens.size(); ++i)
    if (is_word(tokens[i], name)) return i;
  return std::nullopt;
}

// The number right after "label =" or "label:".
std::optional<std::size_t> labelled_value(const std::vector<Token>& tokens, std::size_t label) {
  if (label + 2 < tokens.size() && is_symbol(tokens[label + 1], "=:") &&
      tokens[label + 2].kind == Token::Kind::number)
    return label + 2;
  return std::nullopt;
}

bool has_assignment(const std::vector<Token>& tokens, std::size_t label) {
  return label + 1 < tokens.size() && is_symbol(tokens[label + 1], "=:");
}

std::vector<std::size_t> numbers_between(const std::vector<Token>& tokens, std::size_t begin,
                                         std::size_t end) {
  std::vector<std::size_t> numbers;
  for (std::size_t i = begin; i < end; ++i)
    if (tokens[i].kind == Token::Kind::number) numbers.push_back(i);
  return numbers;
}

// Token indices of the NPTS and DT values on an AT2 size line. By label where there are labels:
// "NPTS=  5372, DT=   .0100 SEC" (NGA-West2, PEER 2000), "4096  0.0100  NPTS, DT"
// (NGA-West1), "NPTS, DT = 4000, 0.01"; else the first whole number and the first real one.
struct SizeTokens {
  std::optional<std::size_t> npts, dt;
};

SizeTokens locate_size(const std::vector<Token>& tokens) {
  SizeTokens found;
  const auto npts_label = find_word(tokens, "NPTS"), dt_label = find_word(tokens, "DT");
  bool npts_assigned = npts_label && has_assignment(tokens, *npts_label);
  bool dt_assigned = dt_label && has_assignment(tokens, *dt_label);
  if (npts_label && dt_label &&
      std::max(*npts_label, *dt_label) - std::min(*npts_label, *dt_label) == 2 &&
      is_symbol(tokens[std::min(*npts_label, *dt_label) + 1], ",")) {
    // A list of labels: its values follow "=" or precede the list, in the labels' order.
    const std::size_t first = std::min(*npts_label, *dt_label),
                      last = std::max(*npts_label, *dt_label);
    std::vector<std::size_t> values;
    if (has_assignment(tokens, last)) {
      values = numbers_between(tokens, last + 2, tokens.size());
      if (values.size() > 2) values.resize(2);
    } else {
      values = numbers_between(tokens, 0, first);
      if (values.size() > 2) values.erase(values.begin(), values.end() - 2);
    }
    if (values.size() == 2) {
      const bool npts_first = *npts_label < *dt_label;
      found.npts = values[npts_first ? 0 : 1];
      found.dt = values[npts_first ? 1 : 0];
    }
    npts_assigned = dt_assigned = true;  // no guessing for a list without its values
  } else {
    if (npts_assigned) found.npts = labelled_value(tokens, *npts_label);
    if (dt_assigned) found.dt = labelled_value(tokens, *dt_label);
  }
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (tokens[i].kind != Token::Kind::number || i == found.npts || i == found.dt) continue;
    if (is_whole_number(tokens[i].text)) {
      if (!npts_assigned && !found.npts) found.npts = i;
    } else if (!dt_assigned && !found.dt) {
      found.dt = i;
    }
  }
  return found;
}

struct RecordSize {
  std::size_t points;
  double time_step;
};

RecordSize read_size_line(const std::string& path, const Line& line) {
  const std::vector<Token> tokens = header_tokens(line.text);
  const SizeTokens found = locate_size(tokens);
  if (!found.npts || !found.dt)
    fail(path, line.number,
         fmt::format("expected the number of points and the time step, as in 'NPTS=  5372, DT=   "
                     ".0100 SEC' or '5372  0.0100  NPTS, DT'; found {}",
                     quoted(line.text)));
  const std::string_view npts = tokens[*found.npts].text, dt = tokens[*found.dt].text;
  long points = 0;
  const auto parsed = std::from_chars(npts.data() + (npts.front() == '+' ? 1 : 0),
                                      npts.data() + npts.size(), points);
  if (!is_whole_number(npts) || parsed.ec != std::errc())
    fail(path, line.number, fmt::format("NPTS must be a whole number of points; found '{}'", npts));
  if (points < 2)
    fail(path, line.number,
         fmt::format("NPTS must be at least 2 (one sample lasts no time); found '{}'", npts));
  const double time_step = number_value(dt);
  if (!(time_step > 0.0) || !std::isfinite(time_step))
    fail(path, line.number, fmt::format("DT must be a positive time step; found '{}'", dt));
  return {static_cast<std::size_t>(points), time_step};
}

// The "dt = 0.005" a columns file may state in its header ("Acc. in cm/sec^2 and dt=0.005 sec.").
struct StatedTimeStep {
  double value;
  int line;
};

std::optional<StatedTimeStep> stated_time_step(const std::string& path,
                                               const std::vector<Line>& header) {
  for (const Line& line : header) {
    const std::vector<Token> tokens = header_tokens(line.text);
    const auto label = find_word(tokens, "dt");
    if (!label) continue;
    const auto value = labelled_value(tokens, *label);
    if (!value) continue;
    const double time_step = number_value(tokens[*value].text);
    if (!(time_step > 0.0) || !std::isfinite(time_step))
      fail(path, line.number,
           fmt::format("the header's dt must be a positive time step; found '{}'",
                       tokens[*value].text));
    return StatedTimeStep{time_step, line.number};
  }
  return std::nullopt;
}

// `in_file` and `given` in the model's time unit, of which `second` is one second.
void require_same_time_step(const std::string& path, int line, double in_file,
                            const std::optional<double>& given, double second) {
  if (!given) return;
  if (std::abs(*given - in_file) > kTimeStepAgreement * std::abs(in_file))
    fail(path, line,
         second == 1.0
             ? fmt::format("the file gives dt = {:g} but the time step given is {:g}", in_file,
                           *given)
             : fmt::format("the file gives dt = {:g} s, {:g} in the model's time unit, but the "
                           "time step given is {:g}",
                           in_file / second, in_file, *given));
}

// ---- units ---------------------------------------------------------------------------------

const char* unit_name(AccelerationUnit unit) {
  switch (unit) {
    case AccelerationUnit::g:
      return "g";
    case AccelerationUnit::m_per_s2:
      return "m/s2";
    case AccelerationUnit::cm_per_s2:
      return "cm/s2";
    case AccelerationUnit::model:
      return "model";
  }
  return "?";
}

}  // namespace

double to_model_units(AccelerationUnit unit, double g_in_model_units) {
  switch (unit) {
    case AccelerationUnit::g:
      return g_in_model_units;
    case AccelerationUnit::m_per_s2:
      return g_in_model_units / kStandardGravity;
    case AccelerationUnit::cm_per_s2:
      return g_in_model_units / (100.0 * kStandardGravity);
    case AccelerationUnit::model:
      return 1.0;
  }
  return 1.0;
}

namespace {

// Whether `text` (lower case) has `word` with no letter right before or after it.
bool has_word(const std::string& text, std::string_view word) {
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const bool open = at == 0 || !std::isalpha(static_cast<unsigned char>(text[at - 1]));
    const std::size_t end = at + word.size();
    const bool close = end == text.size() || !std::isalpha(static_cast<unsigned char>(text[end]));
    if (open && close) return true;
  }
  return false;
}

// The units a header states for its values ("UNITS OF G", "(g)", "Acc. in cm/sec^2"), when it
// names exactly one.
struct StatedUnit {
  AccelerationUnit unit;
  const Line* line;
};

std::optional<StatedUnit> stated_unit(const std::vector<Line>& header) {
  std::vector<StatedUnit> stated;
  auto note = [&](AccelerationUnit unit, const Line& line) {
    if (std::none_of(stated.begin(), stated.end(),
                     [&](const StatedUnit& s) { return s.unit == unit; }))
      stated.push_back({unit, &line});
  };
  for (const Line& line : header) {
    const std::string text = lowercase(line.text);
    if (text.find("cm/s") != std::string::npos || has_word(text, "gal") || has_word(text, "gals"))
      note(AccelerationUnit::cm_per_s2, line);
    if (has_word(text, "m/s") || has_word(text, "m/s2") || has_word(text, "m/sec"))
      note(AccelerationUnit::m_per_s2, line);
    if (has_word(text, "units of g") || text.find("(g)") != std::string::npos ||
        has_word(text, "in g"))
      note(AccelerationUnit::g, line);
  }
  if (stated.size() != 1) return std::nullopt;
  return stated.front();
}

// Reading cm/s^2 as g multiplies a record by 981: refuse a header that says otherwise. Read as
// "model" units (the model's length over its time squared), values the header states in another
// unit are as wrong (a file in g read as m/s^2 is 9.81 times too weak).
void require_stated_units(const std::string& path, const std::vector<Line>& header,
                          AccelerationUnit units, double g_in_model_units) {
  const auto stated = stated_unit(header);
  if (!stated || stated->unit == units) return;
  if (units == AccelerationUnit::model) {
    const double factor = to_model_units(stated->unit, g_in_model_units);
    if (std::abs(factor - 1.0) <= 1e-12) return;  // the model's unit is the stated one
    throw StatedUnitsError(
        path, fmt::format("line {}", stated->line->number),
        fmt::format("the header says the values are in {} ({}) but they are being read as "
                    "model units, of which 1 {} is {:.6g}; set the units to {}",
                    unit_name(stated->unit), quoted(stated->line->text), unit_name(stated->unit),
                    factor, unit_name(stated->unit)));
  }
  throw StatedUnitsError(
      path, fmt::format("line {}", stated->line->number),
      fmt::format("the header says the values are in {} ({}) but they are being read as {}; "
                  "set the units to {}",
                  unit_name(stated->unit), quoted(stated->line->text), unit_name(units),
                  unit_name(stated->unit)));
}

// PEER also distributes velocity (.VT2) and displacement (.DT2) files in the same layout.
void require_acceleration(const std::string& path, const std::vector<Line>& header) {
  for (const Line& line : header) {
    const std::string text = lowercase(line.text);
    if (text.find("accel") != std::string::npos) return;
  }
  for (const Line& line : header) {
    const std::string text = lowercase(line.text);
    for (const char* kind : {"velocity", "displacement"})
      if (text.find(kind) != std::string::npos)
        fail(path, line.number,
             fmt::format("this is a {} record ({}); an acceleration record is expected", kind,
                         quoted(line.text)));
  }
}

// ---- formats -------------------------------------------------------------------------------

bool names_npts(const Line& line) {
  const std::vector<Token> tokens = header_tokens(line.text);
  return find_word(tokens, "NPTS").has_value();
}

std::vector<double> read_at2(const std::string& path, const std::vector<Line>& lines,
                             const RecordFormat& format, double g_in_model_units,
                             double& time_step) {
  // The size line: the first line naming NPTS near the top, else the 4th line (PEER's place).
  const std::size_t search = std::min(lines.size(), kHeaderSearchLines);
  auto size_index = static_cast<std::size_t>(
      std::find_if(lines.begin(), lines.begin() + static_cast<std::ptrdiff_t>(search), names_npts) -
      lines.begin());
  if (size_index == search) {
    if (lines.size() < kPeerHeaderLines)
      fail(path, lines.back().number,
           fmt::format("the file ends after {} lines, before the NPTS and DT line (a PEER .AT2 "
                       "file has 4 header lines, the 4th giving NPTS and DT)",
                       lines.size()));
    size_index = kPeerHeaderLines - 1;
  }
  const Line& size_line = lines[size_index];
  const std::vector<Line> header(lines.begin(),
                                 lines.begin() + static_cast<std::ptrdiff_t>(size_index) + 1);
  require_acceleration(path, header);
  const RecordSize size = read_size_line(path, size_line);
  time_step = size.time_step * format.second;
  require_same_time_step(path, size_line.number, time_step, format.time_step, format.second);
  require_stated_units(path, header, format.units, g_in_model_units);

  // NPTS is only the file's claim: a corrupt one (10^18) must end as "the file ends after n of
  // the values", not exhaust memory. Each value takes at least one character of the file.
  std::size_t characters_left = 0;
  for (std::size_t i = size_index + 1; i < lines.size(); ++i)
    characters_left += lines[i].text.size();
  std::vector<double> values;
  values.reserve(std::min(size.points, characters_left));
  for (std::size_t i = size_index + 1; i < lines.size(); ++i) {
    const Line& line = lines[i];
    // Text between the size line and the data ("*** Begin data ***") is header too.
    if (values.empty() && !is_data_line(line.text)) continue;
    const std::vector<double> numbers = read_numbers(path, line, line.text);
    if (values.size() + numbers.size() > size.points)
      fail(path, line.number,
           fmt::format("more values than NPTS = {} (line {}): value {} is on this line",
                       size.points, size_line.number, size.points + 1));
    values.insert(values.end(), numbers.begin(), numbers.end());
  }
  if (values.size() < size.points)
    fail(path, lines.back().number,
         fmt::format("the file ends after {} of the {} values NPTS gives (line {})", values.size(),
                     size.points, size_line.number));
  return values;
}

// Comments start with '%', '#' or '!' (anywhere) or "//" (at the start of a line).
std::string_view without_comment(std::string_view text) {
  const std::string_view content = trimmed(text);
  if (content.starts_with("//")) return {};
  return text.substr(0, text.find_first_of("%#!"));
}

// dt from a uniform time column; the record's time origin moves to its first row. Each step is
// compared with the median step, so a missing or repeated row is reported where it is.
double time_column_step(const std::string& path, const std::vector<double>& times,
                        const std::vector<int>& rows) {
  if (times.size() < 2)
    fail(path, rows.front(), "a time column needs at least two rows to give the time step");
  std::vector<double> steps;
  for (std::size_t k = 1; k < times.size(); ++k) steps.push_back(times[k] - times[k - 1]);
  std::vector<double> sorted = steps;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2),
                   sorted.end());
  const double typical = sorted[sorted.size() / 2];
  if (!(typical > 0.0)) fail(path, rows[1], "the time column does not increase");
  for (std::size_t k = 1; k < times.size(); ++k) {
    if (std::abs(steps[k - 1] - typical) > kTimeColumnJitter * typical)
      fail(path, rows[k],
           fmt::format("the time column is not uniform: t = {:g} after t = {:g} (line {}), a "
                       "step of {:g} where the other steps are {:g}",
                       times[k], times[k - 1], rows[k - 1], steps[k - 1], typical));
  }
  return (times.back() - times.front()) / static_cast<double>(times.size() - 1);
}

double columns_time_step(const std::string& path, const std::vector<Line>& header,
                         const RecordFormat& format, const std::vector<double>& times,
                         const std::vector<int>& rows) {
  auto stated = stated_time_step(path, header);
  if (stated) stated->value *= format.second;
  if (format.time_column) {
    const double time_step = time_column_step(path, times, rows) * format.second;
    require_same_time_step(path, rows.front(), time_step, format.time_step, format.second);
    if (stated) require_same_time_step(path, stated->line, stated->value, time_step, format.second);
    return time_step;
  }
  if (format.time_step) {
    if (!(*format.time_step > 0.0) || !std::isfinite(*format.time_step))
      fail(path, 0, fmt::format("the time step must be positive; got {:g}", *format.time_step));
    if (stated)
      require_same_time_step(path, stated->line, stated->value, format.time_step, format.second);
    return *format.time_step;
  }
  if (stated) return stated->value;
  fail(path, 0,
       "the file does not give its time step: give it (\"time_step\" in a model or a set, --dt "
       "on the command line, dt= in Python), or read the first column as time");
}

std::vector<double> read_columns(const std::string& path, const std::vector<Line>& lines,
                                 const RecordFormat& format, double g_in_model_units,
                                 double& time_step) {
  if (format.column < 1)
    fail(path, 0, fmt::format("column {} does not exist: columns count from 1", format.column));
  if (format.time_column && format.column == 1)
    fail(path, 0, "column 1 is the time column; read the acceleration from column 2 or later");
  const auto column = static_cast<std::size_t>(format.column);
  std::vector<Line> header;  // comment and text lines before the data
  const Line* first_row = nullptr;
  std::size_t width = 0;
  std::vector<double> values, times;
  std::vector<int> rows;
  for (const Line& line : lines) {
    const std::string_view content = without_comment(line.text);
    if (!first_row && (is_blank(content) || !is_data_line(content))) {
      header.push_back(line);
      continue;
    }
    if (is_blank(content)) continue;  // comments and blank lines within the data
    const std::vector<double> numbers = read_numbers(path, line, content);
    if (!first_row) {
      first_row = &line;
      width = numbers.size();
    }
    if (numbers.size() < column)
      fail(path, line.number,
           fmt::format("column {} does not exist: this line has {}", column,
                       count_of(numbers.size(), "value")));
    if (numbers.size() != width)
      fail(path, line.number,
           fmt::format("this line has {} where the first data line (line {}) has {}",
                       count_of(numbers.size(), "value"), first_row->number, width));
    values.push_back(numbers[column - 1]);
    if (format.time_column) times.push_back(numbers.front());
    rows.push_back(line.number);
  }
  if (!first_row)
    fail(path, lines.back().number, "no data: expected rows of numbers after the header lines");
  // One sample lasts no time: a run under it would end before its first step.
  if (values.size() < 2)
    fail(path, rows.back(), "only 1 row of data: a record needs at least 2 samples");
  require_stated_units(path, header, format.units, g_in_model_units);
  time_step = columns_time_step(path, header, format, times, rows);
  return values;
}

bool reads_as_at2(const std::string& path, const std::string& format,
                  const std::vector<Line>& lines) {
  if (format == "at2") return true;
  if (format == "columns") return false;
  if (format != "auto")
    fail(path, 0, fmt::format("unknown record format '{}' (known: at2, columns, auto)", format));
  if (lowercase(std::filesystem::path(path).extension().string()) == ".at2") return true;
  const std::size_t search = std::min(lines.size(), kHeaderSearchLines);
  return std::any_of(lines.begin(), lines.begin() + static_cast<std::ptrdiff_t>(search),
                     names_npts);
}

// A UTF-8 byte-order mark (Windows editors) and DOS end-of-file marks (Ctrl-Z) are not content.
std::string_view without_markers(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  while (!text.empty() && text.back() == '\x1a') text.remove_suffix(1);
  return text;
}

}  // namespace

model::GroundMotion read_ground_motion(const std::string& path, const RecordFormat& format,
                                       double g_in_model_units, RecordSource* source) {
  const std::string text = read_text_file(path, kMaxRecordBytes);
  model::GroundMotion motion = parse_ground_motion(text, path, format, g_in_model_units);
  if (source) {
    const std::vector<Line> lines = split_lines(without_markers(text));
    source->format = reads_as_at2(path, format.format, lines) ? "at2" : "columns";
    source->sha1 = sha1_hex(text);
  }
  return motion;
}

std::string sha1_hex(std::string_view bytes) {
  boost::uuids::detail::sha1 hash;
  hash.process_bytes(bytes.data(), bytes.size());
  boost::uuids::detail::sha1::digest_type digest;
  hash.get_digest(digest);
  std::string hex;
  for (unsigned int word : digest) hex += fmt::format("{:08x}", word);
  return hex;
}

model::GroundMotion parse_ground_motion(const std::string& text, const std::string& path,
                                        const RecordFormat& format, double g_in_model_units) {
  if (!(g_in_model_units > 0.0) || !std::isfinite(g_in_model_units))
    throw std::invalid_argument("the acceleration of gravity in model units must be positive");
  const std::vector<Line> lines = split_lines(without_markers(text));
  reject_binary(path, lines);
  if (std::all_of(lines.begin(), lines.end(), [](const Line& line) { return is_blank(line.text); }))
    fail(path, 1, "the file is empty (expected a ground-acceleration record)");

  model::GroundMotion motion;
  motion.name = std::filesystem::path(path).filename().string();
  const bool at2 = reads_as_at2(path, format.format, lines);
  // An .AT2 file is one component in rows of values: a column asked of it (a pair's second
  // component as another column of the same file) would read that component again, unawares.
  if (at2 && (format.column != 1 || format.time_column))
    throw ColumnOfAt2Error(
        path, "",
        fmt::format("a PEER .AT2 file holds one component, its values in rows: {} "
                    "applies to columns files only (a pair's second component is "
                    "its own .AT2 file)",
                    format.time_column ? std::string("a time column")
                                       : fmt::format("column {}", format.column)));
  motion.acceleration = at2 ? read_at2(path, lines, format, g_in_model_units, motion.time_step)
                            : read_columns(path, lines, format, g_in_model_units, motion.time_step);
  model::scale(motion, to_model_units(format.units, g_in_model_units));
  // A value that overflows in model units (1.7e308 g) would make every result infinite.
  for (std::size_t k = 0; k < motion.acceleration.size(); ++k)
    if (!std::isfinite(motion.acceleration[k]))
      throw InputError(path, "",
                       fmt::format("sample {} overflows the number range in model units (a "
                                   "value far beyond any ground acceleration)",
                                   k + 1));
  return motion;
}

AccelerationUnit parse_acceleration_unit(const std::string& text) {
  const std::string name = lowercase(text);
  if (name == "g") return AccelerationUnit::g;
  if (name == "m/s2" || name == "m/s^2") return AccelerationUnit::m_per_s2;
  if (name == "cm/s2" || name == "cm/s^2" || name == "gal") return AccelerationUnit::cm_per_s2;
  if (name == "model") return AccelerationUnit::model;
  throw std::invalid_argument(
      fmt::format("unknown acceleration unit '{}' (known: g, m/s2, cm/s2 or gal, model)", text));
}

namespace {

// dt of uniform sample times, each step against the median as a time column's.
double uniform_time_step(const std::string& name, const std::vector<double>& times) {
  std::vector<double> steps;
  for (std::size_t k = 1; k < times.size(); ++k) {
    if (!std::isfinite(times[k]) || !std::isfinite(times[k - 1]))
      throw InputError(name, fmt::format("times[{}]", std::isfinite(times[k]) ? k - 1 : k),
                       "a time that is not a finite number");
    steps.push_back(times[k] - times[k - 1]);
  }
  std::vector<double> sorted = steps;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2),
                   sorted.end());
  const double typical = sorted[sorted.size() / 2];
  if (!(typical > 0.0)) throw InputError(name, "times", "the times do not increase");
  for (std::size_t k = 1; k < times.size(); ++k)
    if (std::abs(steps[k - 1] - typical) > kTimeColumnJitter * typical)
      throw InputError(name, fmt::format("times[{}]", k),
                       fmt::format("the times are not uniform: t = {:g} after t = {:g}, a step of "
                                   "{:g} where the other steps are {:g}",
                                   times[k], times[k - 1], steps[k - 1], typical));
  return (times.back() - times.front()) / static_cast<double>(times.size() - 1);
}

}  // namespace

model::GroundMotion ground_motion_from_samples(const std::string& name,
                                               const std::vector<double>& accelerations,
                                               std::optional<double> time_step,
                                               const std::vector<double>& times,
                                               AccelerationUnit unit, double g_in_model_units) {
  if (!(g_in_model_units > 0.0) || !std::isfinite(g_in_model_units))
    throw std::invalid_argument("the acceleration of gravity in model units must be positive");
  if (accelerations.size() < 2)
    throw InputError(name, "accelerations",
                     fmt::format("{} sample{}: a record needs at least 2", accelerations.size(),
                                 accelerations.size() == 1 ? "" : "s"));
  model::GroundMotion motion;
  motion.name = name;
  if (time_step) {
    if (!(*time_step > 0.0) || !std::isfinite(*time_step))
      throw InputError(name, "time_step",
                       fmt::format("a time step must be a positive number, got {:g}", *time_step));
    motion.time_step = *time_step;
  } else {
    if (times.size() != accelerations.size())
      throw InputError(name, "times",
                       fmt::format("{} times for {} accelerations: give one time per sample",
                                   times.size(), accelerations.size()));
    motion.time_step = uniform_time_step(name, times);
  }
  const double factor = to_model_units(unit, g_in_model_units);
  motion.acceleration = accelerations;
  for (std::size_t k = 0; k < accelerations.size(); ++k) {
    if (!std::isfinite(accelerations[k]))
      throw InputError(name, fmt::format("accelerations[{}]", k),
                       fmt::format("{:g} is not a finite number", accelerations[k]));
  }
  model::scale(motion, factor);
  for (std::size_t k = 0; k < motion.acceleration.size(); ++k)
    if (!std::isfinite(motion.acceleration[k]))
      throw InputError(name, fmt::format("accelerations[{}]", k),
                       "overflows the number range in model units (a value far beyond any ground "
                       "acceleration)");
  return motion;
}

}  // namespace pound::io
