#include "assembly/beam.hpp"

#include <array>

#include "core/packets.hpp"

namespace pound::assembly {
namespace {

constexpr int kDirections[] = {0, 1, 2};
constexpr model::EndForce kEndForces[] = {{"N_i", Dimension::force},  {"V_i", Dimension::force},
                                          {"M_i", Dimension::moment}, {"N_j", Dimension::force},
                                          {"V_j", Dimension::force},  {"M_j", Dimension::moment}};

}  // namespace

Beam::Beam(std::string id, const std::array<model::ElementNode, 2>& ends, const Section& section,
           bool consistent_mass, std::optional<model::RayleighDamping> damping)
    : Element(std::move(id), {ends[0].index, ends[1].index}, damping),
      section_(section),
      consistent_mass_(consistent_mass),
      axis_(model::element_axis(ends, 2)),
      local_stiffness_(make_local_stiffness()),
      rotation_(make_rotation()) {}

std::span<const int> Beam::directions() const { return kDirections; }

Beam::Matrix6 Beam::make_local_stiffness() const {
  const double ea = section_.youngs_modulus * section_.area / axis_.length;
  const double ei = section_.youngs_modulus * section_.inertia;
  const double l2 = axis_.length * axis_.length, l3 = l2 * axis_.length;
  Matrix6 k = Matrix6::Zero();
  k(0, 0) = k(3, 3) = ea;
  k(0, 3) = k(3, 0) = -ea;
  k(1, 1) = k(4, 4) = 12 * ei / l3;
  k(1, 4) = k(4, 1) = -12 * ei / l3;
  k(1, 2) = k(2, 1) = k(1, 5) = k(5, 1) = 6 * ei / l2;
  k(4, 2) = k(2, 4) = k(4, 5) = k(5, 4) = -6 * ei / l2;
  k(2, 2) = k(5, 5) = 4 * ei / axis_.length;
  k(2, 5) = k(5, 2) = 2 * ei / axis_.length;
  return k;
}

Beam::Matrix6 Beam::local_consistent_mass() const {
  const double m = mass_per_length() * axis_.length, l = axis_.length;
  Matrix6 mass = Matrix6::Zero();
  mass(0, 0) = mass(3, 3) = m / 3.0;
  mass(0, 3) = mass(3, 0) = m / 6.0;
  const double c = m / 420.0;
  mass(1, 1) = mass(4, 4) = 156 * c;
  mass(1, 4) = mass(4, 1) = 54 * c;
  mass(1, 2) = mass(2, 1) = 22 * l * c;
  mass(4, 5) = mass(5, 4) = -22 * l * c;
  mass(1, 5) = mass(5, 1) = -13 * l * c;
  mass(2, 4) = mass(4, 2) = 13 * l * c;
  mass(2, 2) = mass(5, 5) = 4 * l * l * c;
  mass(2, 5) = mass(5, 2) = -3 * l * l * c;
  return mass;
}

Beam::Matrix6 Beam::make_rotation() const {
  const double cosine = axis_.cosines[0], sine = axis_.cosines[1];
  Matrix6 t = Matrix6::Zero();
  for (int node = 0; node < 2; ++node) {
    const int o = 3 * node;
    t(o, o) = cosine;
    t(o, o + 1) = sine;
    t(o + 1, o) = -sine;
    t(o + 1, o + 1) = cosine;
    t(o + 2, o + 2) = 1.0;
  }
  return t;
}

// The products at fixed size, as the assembly has always rounded them.
Matrix Beam::stiffness() const {
  const Matrix6& t = rotation_;
  const Matrix6 k = t.transpose() * local_stiffness_ * t;
  return k;
}

model::ElementMass Beam::mass() const {
  if (consistent_mass_) {
    const Matrix6& t = rotation_;
    const Matrix6 m = t.transpose() * local_consistent_mass() * t;
    return {.consistent = m};
  }
  const double half = 0.5 * mass_per_length() * axis_.length;
  return {.lumped = Vector{{half, half, 0.0, half, half, 0.0}}};
}

std::span<const model::EndForce> Beam::end_force_names() const { return kEndForces; }

Vector Beam::end_forces(const Vector& u) const {
  // K' (T u), each row of each product summed from 0 in column order (core/packets.hpp).
  std::array<double, 6> local_displacements;
  multiply_by_columns<6, 6>(rotation_.data(), u.data(), local_displacements.data());
  Vector forces(6);
  multiply_by_columns<6, 6>(local_stiffness_.data(), local_displacements.data(), forces.data());
  return forces;
}

// Local geometric stiffness on (v'_i, theta_i, v'_j, theta_j) (Przemieniecki 1968, chapter 15),
// global as K = T^T K'_G T.
Matrix Beam::geometric_stiffness(const Vector& u, model::GeometricStiffness kind) const {
  const double axial = end_forces(u)[3], l = axis_.length;  // N_j: tension positive
  Matrix6 k = Matrix6::Zero();
  constexpr int kTransverse[] = {1, 2, 4, 5};
  if (kind == model::GeometricStiffness::chord) {
    k(1, 1) = k(4, 4) = axial / l;
    k(1, 4) = k(4, 1) = -axial / l;
  } else {
    const double c = axial / (30.0 * l);
    const double shape[4][4] = {{36, 3 * l, -36, 3 * l},
                                {3 * l, 4 * l * l, -3 * l, -l * l},
                                {-36, -3 * l, 36, -3 * l},
                                {3 * l, -l * l, -3 * l, 4 * l * l}};
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) k(kTransverse[a], kTransverse[b]) = c * shape[a][b];
  }
  const Matrix6& t = rotation_;
  const Matrix6 global = t.transpose() * k * t;
  return global;
}

}  // namespace pound::assembly
