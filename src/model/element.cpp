#include "model/element.hpp"

#include <algorithm>
#include <cmath>

namespace pound::model {

Matrix Element::geometric_stiffness(const Vector&, GeometricStiffness) const { return {}; }

std::vector<ElementDof> Element::dofs() const {
  std::vector<ElementDof> dofs;
  dofs.reserve(nodes_.size() * directions().size());
  for (Index node : nodes_)
    for (int direction : directions()) dofs.push_back({node, direction});
  return dofs;
}

Matrix end_force_map(const Element& element) {
  const auto dofs = static_cast<Index>(element.dofs().size());
  Matrix map(static_cast<Index>(element.end_force_names().size()), dofs);
  Vector unit = Vector::Zero(dofs);
  for (Index j = 0; j < dofs; ++j) {
    unit[j] = 1.0;
    map.col(j) = element.end_forces(unit);
    unit[j] = 0.0;
  }
  return map;
}

Coordinates to_coordinates(std::span<const double> components) {
  Coordinates coordinates{};
  std::copy_n(components.begin(), std::min(components.size(), coordinates.size()),
              coordinates.begin());
  return coordinates;
}

double distance(const Coordinates& a, const Coordinates& b, int dimension) {
  if (dimension == 3) return std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  return std::hypot(b[0] - a[0], dimension == 2 ? b[1] - a[1] : 0.0);
}

Coordinates cross(const Coordinates& a, const Coordinates& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

ElementAxis element_axis(const std::array<ElementNode, 2>& ends, int dimension) {
  const Coordinates& i = ends[0].position;
  const Coordinates& j = ends[1].position;
  const double length = distance(i, j, dimension);
  if (dimension == 3)
    return {length, {(j[0] - i[0]) / length, (j[1] - i[1]) / length, (j[2] - i[2]) / length}};
  return {length, {(j[0] - i[0]) / length, (j[1] - i[1]) / length, 0.0}};
}

}  // namespace pound::model
