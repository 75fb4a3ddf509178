#pragma once
// Columns of a run's tables by name, for tests that read histories.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/table.hpp"

namespace pound::testing {

// The values of column `name` (a test failure, and no values, when there is none).
inline const std::vector<double>& column(const Table& table, const std::string& name) {
  for (std::size_t c = 0; c < table.columns.size(); ++c)
    if (table.columns[c] == name) return table.values[c];
  ADD_FAILURE() << "no column " << name;
  static const std::vector<double> none;
  return none;
}

}  // namespace pound::testing
