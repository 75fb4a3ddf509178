#pragma once
// Numeric columns of equal length with names: what recorders produce and io/ writes as CSV.
#include <string>
#include <vector>

namespace pound {

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;  // values[column][row]
};

}  // namespace pound
