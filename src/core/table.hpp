#pragma once
// Numeric columns of equal length with names: what recorders produce and io/ writes as CSV.
#include <cstddef>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace pound {

// A column of text (an envelope's quantities and their units): a value per row.
struct TextColumn {
  std::string name;
  std::vector<std::string> values;
};

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;  // values[column][row]
  // Each numeric column's unit ("" for none), written into CSV headers as "name [unit]"; empty
  // when the table names no units.
  std::vector<std::string> units;
  // Written before the numeric columns.
  std::vector<TextColumn> text_columns;
};

// A table with these columns and no rows yet.
inline Table table_with_columns(std::vector<std::string> columns) {
  const std::size_t count = columns.size();
  return {std::move(columns), std::vector<std::vector<double>>(count)};
}

// Appends one row: a value per column, in column order.
inline void append_row(Table& table, std::initializer_list<double> row) {
  std::size_t column = 0;
  for (double value : row) table.values[column++].push_back(value);
}

}  // namespace pound
