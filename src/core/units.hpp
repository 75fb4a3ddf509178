#pragma once
// What a number measures, so that tables can name its unit in the model's units.
#include <array>
#include <cstddef>
#include <string>

namespace pound {

enum class Dimension {
  none,
  time,
  length,
  velocity,
  acceleration,
  force,
  moment,
  angle,
  angular_velocity,
  angular_acceleration,
  count
};

// The unit each dimension is given in ("" where the model names none: forces without a mass
// unit, and dimensionless numbers).
struct UnitNames {
  std::array<std::string, static_cast<std::size_t>(Dimension::count)> names{};
  const std::string& of(Dimension dimension) const {
    return names[static_cast<std::size_t>(dimension)];
  }
};

}  // namespace pound
