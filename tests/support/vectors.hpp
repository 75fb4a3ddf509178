#pragma once
// Small vectors written out in the tests: entries({1, 2, 3}).
#include <initializer_list>

#include "core/types.hpp"

namespace pound::testing {

// A vector of these entries.
inline Vector entries(std::initializer_list<double> values) {
  Vector v(static_cast<Index>(values.size()));
  Index k = 0;
  for (const double value : values) v[k++] = value;
  return v;
}

}  // namespace pound::testing
