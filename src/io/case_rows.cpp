#include "io/case_rows.hpp"

#include <fmt/format.h>

#include <charconv>
#include <functional>
#include <optional>

#include "core/errors.hpp"
#include "io/json_reader.hpp"
#include "results/batch_quantities.hpp"

namespace pound::io {
namespace {

using results::CaseSummary;

std::string number(const std::optional<double>& value) {
  return value ? fmt::format("{}", *value) : std::string();
}

std::string quoted(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::optional<double> parse_number(const std::string& cell) {
  if (cell.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (error != std::errc() || end != cell.data() + cell.size())
    throw std::invalid_argument(fmt::format("'{}' is not a number", cell));
  return value;
}

// A column, with how it prints and how it reads back.
struct Column {
  std::string name;
  std::function<std::string(const CaseSummary&)> print;
  std::function<void(CaseSummary&, const std::string&)> read;  // throws std::invalid_argument
};

Column text_column(std::string name, std::string CaseSummary::*field) {
  return {std::move(name), [field](const CaseSummary& c) { return quoted(c.*field); },
          [field](CaseSummary& c, const std::string& cell) { c.*field = cell; }};
}

Column status_column() {
  return {"status", [](const CaseSummary& c) { return quoted(results::status_name(c.status)); },
          [](CaseSummary& c, const std::string& cell) {
            const std::optional<results::CaseStatus> status = results::status_from_name(cell);
            if (!status) throw std::invalid_argument("not a case status: '" + cell + "'");
            c.status = *status;
          }};
}

Column number_column(std::string name, std::optional<double> CaseSummary::*field) {
  return {std::move(name), [field](const CaseSummary& c) { return number(c.*field); },
          [field](CaseSummary& c, const std::string& cell) { c.*field = parse_number(cell); }};
}

Column scale_column() {
  return {"scale", [](const CaseSummary& c) { return fmt::format("{}", c.scale); },
          [](CaseSummary& c, const std::string& cell) {
            const std::optional<double> value = parse_number(cell);
            if (!value) throw std::invalid_argument("the scale is missing");
            c.scale = *value;
          }};
}

Column unseated_column() {
  return {"unseated",
          [](const CaseSummary& c) {
            return c.unseated ? std::string(*c.unseated ? "true" : "false") : std::string();
          },
          [](CaseSummary& c, const std::string& cell) {
            if (cell.empty())
              c.unseated.reset();
            else if (cell == "true" || cell == "false")
              c.unseated = cell == "true";
            else
              throw std::invalid_argument(fmt::format("'{}' is not true or false", cell));
          }};
}

// The columns that follow a quantity's own and qualify it: the link that carried a peak force,
// the margin left on the seats and whether a girder came off one.
std::vector<Column> qualifiers(const results::BatchQuantity& quantity) {
  if (quantity.value == &CaseSummary::max_pounding_force)
    return {text_column("max_pounding_link", &CaseSummary::max_pounding_link)};
  if (quantity.value == &CaseSummary::max_restrainer_force)
    return {text_column("max_restrainer_link", &CaseSummary::max_restrainer_link)};
  if (quantity.value == &CaseSummary::max_seat_movement)
    return {number_column("min_unseating_margin", &CaseSummary::min_unseating_margin),
            unseated_column()};
  return {};
}

// The case, its record and how far it went; each response quantity in the table's order with
// its qualifiers; the count of result warnings, and the run time last.
std::vector<Column> make_columns() {
  std::vector<Column> all = {text_column("name", &CaseSummary::name),
                             text_column("model", &CaseSummary::model),
                             text_column("record", &CaseSummary::record),
                             scale_column(),
                             status_column(),
                             text_column("reason", &CaseSummary::reason),
                             number_column("pga_g", &CaseSummary::pga_g),
                             number_column("intensity", &CaseSummary::intensity),
                             number_column("end_time", &CaseSummary::end_time),
                             number_column("steps", &CaseSummary::steps)};
  for (const results::BatchQuantity& quantity : results::batch_quantities()) {
    all.push_back(number_column(std::string(quantity.name), quantity.value));
    for (Column& qualifier : qualifiers(quantity)) all.push_back(std::move(qualifier));
  }
  all.push_back(number_column("warnings", &CaseSummary::warnings));
  all.push_back(number_column("run_time_s", &CaseSummary::run_time_s));
  return all;
}

const std::vector<Column>& columns() {
  static const std::vector<Column> all = make_columns();
  return all;
}

// Splits one CSV line into cells, undoing the quoting of quoted().
std::vector<std::string> split_cells(const std::string& row) {
  std::vector<std::string> cells(1);
  bool in_quotes = false;
  for (std::size_t i = 0; i < row.size(); ++i) {
    const char c = row[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < row.size() && row[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        cells.back() += c;
      }
    } else if (c == '"') {
      in_quotes = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  if (in_quotes) throw std::invalid_argument("a quoted cell is not closed");
  return cells;
}

}  // namespace

std::string case_row_header() {
  std::string header;
  for (const Column& column : columns()) header += (header.empty() ? "" : ",") + column.name;
  return header;
}

std::string case_row(const CaseSummary& summary) {
  std::string row;
  bool first = true;
  for (const Column& column : columns()) {
    if (!first) row += ',';
    row += column.print(summary);
    first = false;
  }
  return row;
}

CaseSummary parse_case_row(const std::string& row, const std::string& source) {
  CaseSummary summary;
  try {
    const std::vector<std::string> cells = split_cells(row);
    if (cells.size() != columns().size())
      throw std::invalid_argument(
          fmt::format("{} cells where {} were expected", cells.size(), columns().size()));
    for (std::size_t k = 0; k < cells.size(); ++k) {
      try {
        columns()[k].read(summary, cells[k]);
      } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(fmt::format("column {}: {}", columns()[k].name, error.what()));
      }
    }
  } catch (const std::invalid_argument& error) {
    throw InputError(source, "line 2", fmt::format("not a case summary row: {}", error.what()));
  }
  return summary;
}

CaseSummary read_case_file(const std::string& path, std::string& row) {
  const std::string text = read_text_file(path);
  const std::size_t header_end = text.find('\n');
  if (header_end == std::string::npos || text.substr(0, header_end) != case_row_header())
    throw InputError(path, "line 1",
                     "not the header of a case summary (written by another version?)");
  std::size_t row_end = text.find('\n', header_end + 1);
  if (row_end == std::string::npos || row_end + 1 != text.size())
    throw InputError(path, "line 2", "expected exactly one row ending in a newline");
  row = text.substr(header_end + 1, row_end - header_end - 1);
  return parse_case_row(row, path);
}

}  // namespace pound::io
