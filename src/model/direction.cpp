#include "model/direction.hpp"

#include <stdexcept>

namespace pound::model {
namespace {
constexpr Direction kPlane[] = {
    {"x", "x", false, 0}, {"y", "y", false, 1}, {"rz", "rotation", true, 2}};
constexpr Direction kSpace[] = {{"x", "x", false, 0},
                                {"y", "y", false, 1},
                                {"z", "z", false, 2},
                                {"rx", "rotation about x", true, 0},
                                {"ry", "rotation about y", true, 1},
                                {"rz", "rotation about z", true, 2}};
}  // namespace

int direction_count(int dimension) { return dimension == 3 ? 6 : 3; }

Direction direction(int index, int dimension) {
  if (index < 0 || index >= direction_count(dimension))
    throw std::out_of_range("no such direction in this scene");
  return dimension == 3 ? kSpace[index] : kPlane[index];
}

std::array<double, 6> over_directions(const std::array<double, 3>& vector, bool rotations,
                                      int dimension) {
  std::array<double, 6> components{};
  for (int d = 0; d < direction_count(dimension); ++d)
    if (const Direction along = direction(d, dimension); along.rotation == rotations)
      components[static_cast<std::size_t>(d)] = vector[static_cast<std::size_t>(along.axis)];
  return components;
}

}  // namespace pound::model
