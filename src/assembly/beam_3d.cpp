#include "assembly/beam_3d.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "core/packets.hpp"

namespace pound::assembly {
namespace {

constexpr int kDirections[] = {0, 1, 2, 3, 4, 5};
constexpr model::EndForce kEndForces[] = {
    {"N_i", Dimension::force},  {"Vy_i", Dimension::force},  {"Vz_i", Dimension::force},
    {"T_i", Dimension::moment}, {"My_i", Dimension::moment}, {"Mz_i", Dimension::moment},
    {"N_j", Dimension::force},  {"Vy_j", Dimension::force},  {"Vz_j", Dimension::force},
    {"T_j", Dimension::moment}, {"My_j", Dimension::moment}, {"Mz_j", Dimension::moment}};

// Local DOFs of one end: u', v', w', theta_x', theta_y', theta_z'; the other end is 6 further.
enum Local { kU = 0, kV = 1, kW = 2, kTx = 3, kTy = 4, kTz = 5 };

using Matrix12 = Eigen::Matrix<double, 12, 12>;

// Adds [[diagonal, coupling], [coupling, diagonal]] on local DOF `d` of the two ends (axial and
// torsional stiffness and mass).
void add_pair(Matrix12& k, int d, double diagonal, double coupling) {
  k(d, d) += diagonal;
  k(d + 6, d + 6) += diagonal;
  k(d, d + 6) += coupling;
  k(d + 6, d) += coupling;
}

using Block4 = std::array<std::array<double, 4>, 4>;

// Adds factor x `block` on (deflection_i, rotation_i, deflection_j, rotation_j) of one bending
// plane, its deflection-rotation terms times `sign` (-1 in the x'-z' plane, where
// theta_y' = -dw'/dx').
void add_bending(Matrix12& k, int deflection, int rotation, const Block4& block, double factor,
                 double sign) {
  const int dofs[4] = {deflection, rotation, deflection + 6, rotation + 6};
  const bool is_rotation[4] = {false, true, false, true};
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      k(dofs[a], dofs[b]) +=
          (is_rotation[a] != is_rotation[b] ? sign : 1.0) * (factor * block[a][b]);
}

// Adds factor x `block` in both bending planes.
void add_both_bendings(Matrix12& k, const Block4& block, double factor_v, double factor_w) {
  add_bending(k, kV, kTz, block, factor_v, 1.0);
  add_bending(k, kW, kTy, block, factor_w, -1.0);
}

Eigen::Matrix3d skew(const Point3& o) {
  Eigen::Matrix3d s;
  s << 0.0, -o.z(), o.y(), o.z(), 0.0, -o.x(), -o.y(), o.x(), 0.0;
  return s;
}

}  // namespace

Beam3d::Beam3d(std::string id, const std::array<End, 2>& ends, const Point3& orientation,
               const Section& section, bool consistent_mass,
               std::optional<model::RayleighDamping> damping)
    : Element(std::move(id), {ends[0].node, ends[1].node}, damping),
      section_(section),
      consistent_mass_(consistent_mass) {
  const Point3 axis = (ends[1].position + ends[1].offset) - (ends[0].position + ends[0].offset);
  length_ = std::hypot(axis.x(), axis.y(), axis.z());  // no overflow before the length does
  if (!(length_ > 0.0))
    throw std::invalid_argument("the beam's ends (its nodes plus their offsets) coincide");
  if (!std::isfinite(length_))
    throw std::invalid_argument("the beam is longer than the number range holds");
  const Point3 x = axis / length_;
  // Only its direction counts: scaled to a largest component of 1, no size overflows below.
  const double largest = orientation.cwiseAbs().maxCoeff();
  if (!(largest > 0.0))
    throw std::invalid_argument(
        "the orientation vector is zero: it must fix the local x'-z' plane");
  const Point3 v = orientation / largest;
  const Point3 y = v.cross(x);
  // A vector nearly along the beam fixes no plane: its cross product is all round-off.
  if (!(y.norm() > 1e-6 * v.norm()))
    throw std::invalid_argument(
        "the orientation vector is parallel to the beam: it must fix the local x'-z' plane");
  axes_.row(0) = x.transpose();
  axes_.row(1) = y.normalized().transpose();
  axes_.row(2) = x.cross(y.normalized()).transpose();
  local_stiffness_ = make_local_stiffness();
  transformation_ = make_transformation(ends);
}

std::span<const int> Beam3d::directions() const { return kDirections; }

Beam3d::Matrix12 Beam3d::make_local_stiffness() const {
  const double l = length_, e = section_.youngs_modulus;
  Matrix12 k = Matrix12::Zero();
  add_pair(k, kU, e * section_.area / l, -e * section_.area / l);
  add_pair(k, kTx, section_.shear_modulus * section_.torsion / l,
           -section_.shear_modulus * section_.torsion / l);
  // The cubic Hermitian bending stiffness (Przemieniecki), each entry rounded as the plane beam
  // rounds it (assembly/beam.cpp), so that a 3-D frame in a plane gives the 2-D numbers.
  const double l2 = l * l, l3 = l2 * l;
  const auto bending = [&](double inertia) {
    const double ei = e * inertia;
    const double shear = 12 * ei / l3, coupling = 6 * ei / l2;
    const double near = 4 * ei / l, far = 2 * ei / l;
    return Block4{{{shear, coupling, -shear, coupling},
                   {coupling, near, -coupling, far},
                   {-shear, -coupling, shear, -coupling},
                   {coupling, far, -coupling, near}}};
  };
  const auto in_xy = bending(section_.inertia_z), in_xz = bending(section_.inertia_y);
  add_bending(k, kV, kTz, in_xy, 1.0, 1.0);
  add_bending(k, kW, kTy, in_xz, 1.0, -1.0);
  return k;
}

Beam3d::Matrix12 Beam3d::local_consistent_mass() const {
  const double l = length_, m = mass_per_length() * l;
  Matrix12 mass = Matrix12::Zero();
  add_pair(mass, kU, m / 3.0, m / 6.0);
  const double polar = section_.density * (section_.inertia_y + section_.inertia_z) * l;
  add_pair(mass, kTx, polar / 3.0, polar / 6.0);
  const Block4 hermitian = {{{156, 22 * l, 54, -13 * l},
                             {22 * l, 4 * l * l, 13 * l, -3 * l * l},
                             {54, 13 * l, 156, -22 * l},
                             {-13 * l, -3 * l * l, -22 * l, 4 * l * l}}};
  add_both_bendings(mass, hermitian, m / 420.0, m / 420.0);
  return mass;
}

Beam3d::Matrix12 Beam3d::make_transformation(const std::array<End, 2>& ends) const {
  Matrix12 rigid = Matrix12::Identity(), rotation = Matrix12::Zero();
  for (int end = 0; end < 2; ++end) {
    rigid.block<3, 3>(6 * end, 6 * end + 3) = -skew(ends[end].offset);  // theta x o = -[o] theta
    for (int block = 0; block < 2; ++block)
      rotation.block<3, 3>(6 * end + 3 * block, 6 * end + 3 * block) = axes_;
  }
  const Matrix12 transformation = rotation * rigid;
  return transformation;
}

Matrix Beam3d::stiffness() const {
  const Matrix12 k = transformation_.transpose() * local_stiffness_ * transformation_;
  return k;
}

model::ElementMass Beam3d::mass() const {
  if (consistent_mass_) {
    const Matrix12 m = transformation_.transpose() * local_consistent_mass() * transformation_;
    return {.consistent = m};
  }
  const double half = 0.5 * mass_per_length() * length_;
  Vector lumped = Vector::Zero(12);
  for (int end = 0; end < 2; ++end) lumped.segment<3>(6 * end).setConstant(half);
  return {.lumped = lumped};
}

std::span<const model::EndForce> Beam3d::end_force_names() const { return kEndForces; }

Vector Beam3d::end_forces(const Vector& u) const {
  // K' (T u), each row of each product summed from 0 in column order (core/packets.hpp).
  std::array<double, 12> local_displacements;
  multiply_by_columns<12, 12>(transformation_.data(), u.data(), local_displacements.data());
  Vector forces(12);
  multiply_by_columns<12, 12>(local_stiffness_.data(), local_displacements.data(), forces.data());
  return forces;
}

Matrix Beam3d::geometric_stiffness(const Vector& u, model::GeometricStiffness kind) const {
  const double axial = end_forces(u)[6], l = length_;  // N_j: tension positive
  Matrix12 k = Matrix12::Zero();
  if (kind == model::GeometricStiffness::chord) {
    add_pair(k, kV, axial / l, -axial / l);
    add_pair(k, kW, axial / l, -axial / l);
  } else {
    const Block4 hermitian = {{{36, 3 * l, -36, 3 * l},
                               {3 * l, 4 * l * l, -3 * l, -l * l},
                               {-36, -3 * l, 36, -3 * l},
                               {3 * l, -l * l, -3 * l, 4 * l * l}}};
    add_both_bendings(k, hermitian, axial / (30.0 * l), axial / (30.0 * l));
  }
  const Matrix12 global = transformation_.transpose() * k * transformation_;
  return global;
}

}  // namespace pound::assembly
