#include "assembly/truss.hpp"

namespace pound::assembly {
namespace {

constexpr int kDirections[] = {0, 1, 2};  // x, y, z in either numbering
constexpr model::EndForce kEndForces[] = {{"N", Dimension::force}};

}  // namespace

Truss::Truss(std::string id, const std::array<model::ElementNode, 2>& ends, int dimension,
             const Section& section, std::optional<model::RayleighDamping> damping)
    : Element(std::move(id), {ends[0].index, ends[1].index}, damping),
      dimension_(dimension),
      section_(section),
      axis_(model::element_axis(ends, dimension)),
      axial_stiffness_(section.youngs_modulus * section.area / axis_.length) {}

std::span<const int> Truss::directions() const {
  return std::span(kDirections).first(static_cast<std::size_t>(dimension_));
}

Matrix Truss::stiffness() const {
  const Index size = 2 * dimension_;
  Matrix k(size, size);
  for (Index p = 0; p < size; ++p)
    for (Index q = 0; q < size; ++q) {
      const double sign = (p / dimension_ == q / dimension_) ? 1.0 : -1.0;
      k(p, q) = sign * axial_stiffness_ * axis_.cosines[static_cast<std::size_t>(p % dimension_)] *
                axis_.cosines[static_cast<std::size_t>(q % dimension_)];
    }
  return k;
}

model::ElementMass Truss::mass() const {
  return {.lumped = Vector::Constant(2 * dimension_,
                                     0.5 * section_.density * section_.area * axis_.length)};
}

std::span<const model::EndForce> Truss::end_force_names() const { return kEndForces; }

Vector Truss::end_forces(const Vector& u) const {
  double elongation = 0.0;
  for (int d = 0; d < dimension_; ++d)
    elongation += (u[dimension_ + d] - u[d]) * axis_.cosines[static_cast<std::size_t>(d)];
  return Vector::Constant(1, axial_stiffness_ * elongation);
}

// The string stiffness N / L across the bar (both kinds: a bar has no curvature): N / L times
// the projection across it, a a^T in a plane (a: the axis turned by 90 degrees), I - c c^T in
// space.
Matrix Truss::geometric_stiffness(const Vector& u, model::GeometricStiffness) const {
  if (dimension_ == 1) return {};
  const double string = section_.axial_force.value_or(end_forces(u)[0]) / axis_.length;
  if (dimension_ == 3) {
    const Eigen::Vector3d c(axis_.cosines[0], axis_.cosines[1], axis_.cosines[2]);
    const Eigen::Matrix3d across = string * (Eigen::Matrix3d::Identity() - c * c.transpose());
    Matrix k(6, 6);
    k << across, -across, -across, across;
    return k;
  }
  const double across[2] = {-axis_.cosines[1], axis_.cosines[0]};
  Matrix k(4, 4);
  for (Index p = 0; p < 4; ++p)
    for (Index q = 0; q < 4; ++q)
      k(p, q) = (p / 2 == q / 2 ? 1.0 : -1.0) * string * across[p % 2] * across[q % 2];
  return k;
}

}  // namespace pound::assembly
