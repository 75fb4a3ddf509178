#pragma once
// Numeric columns of equal length with names: what recorders produce and io/ writes as CSV.
#include <cstddef>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace pound {

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;  // values[column][row]
  // A first column of text when label_column is named (an envelope's quantities): a label per
  // row.
  std::string label_column;
  std::vector<std::string> labels;
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
