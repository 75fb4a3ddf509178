#pragma once
// Two-node 2-D elastic beam-column (Euler-Bernoulli: axial and bending, no shear deformation),
// for girders, piers and storey columns, in a plane frame scene. DOFs (u_x,i, u_y,i, theta_i,
// u_x,j, u_y,j, theta_j) in global axes, theta counter-clockwise.
//
// Local axes: x' from node i to node j, y' x' turned +90 degrees; u' = T u with T the rotation
// by the direction cosines (c, s) of x' at each node (theta unchanged). K = T^T K' T with
//   K' = EA/L on (u'_i, u'_j) as [[1, -1], [-1, 1]] and, on (v'_i, theta_i, v'_j, theta_j),
//        EI/L^3 [[12, 6L, -12, 6L], [6L, 4L^2, -6L, 2L^2], [-12, -6L, 12, -6L],
//                [6L, 2L^2, -6L, 4L^2]].
// Mass per length m = rho A + extra mass:
//   lumped: m L / 2 at each end along x and y, no rotary inertia;
//   consistent: T^T M' T, linear axial shapes m L / 6 [[2, 1], [1, 2]], cubic Hermitian
//   transverse shapes m L / 420 [[156, 22L, 54, -13L], [22L, 4L^2, 13L, -3L^2],
//                                [54, 13L, 156, -22L], [-13L, -3L^2, -22L, 4L^2]].
// End forces f' = K' T u: the forces and moments the nodes apply to the element, in local axes
// (N_i, V_i, M_i, N_j, V_j, M_j); a bar in tension has N_j = -N_i > 0, a cantilever fixed at i
// with a load P along y' at j has V_i = -P, M_i = -P L.
//
// Units: E [F/L^2], A [L^2], I [L^4], rho [M/L^3], extra mass [M/L]; forces [F], moments
// [F L]. Source: Przemieniecki, "Theory of Matrix Structural Analysis" (1968), chapter 5
// (stiffness) and chapter 11 (consistent mass).
#include <Eigen/Dense>
#include <array>

#include "model/element.hpp"

namespace pound::assembly {

class Beam final : public model::Element {
 public:
  struct Section {
    double youngs_modulus = 0.0;  // E [F/L^2]
    double area = 0.0;            // A [L^2]
    double inertia = 0.0;         // I [L^4]
    double density = 0.0;         // rho [M/L^3]
    double extra_mass = 0.0;      // [M/L], e.g. deck, barriers, tributary floor
  };
  // The ends are apart (the builder checks the length).
  Beam(std::string id, const std::array<model::ElementNode, 2>& ends, const Section& section,
       bool consistent_mass, std::optional<model::RayleighDamping> damping);

  std::span<const int> directions() const override;
  Matrix stiffness() const override;
  model::ElementMass mass() const override;
  std::span<const model::EndForce> end_force_names() const override;
  Vector end_forces(const Vector& u) const override;
  Matrix geometric_stiffness(const Vector& u, model::GeometricStiffness kind) const override;

 private:
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  Matrix6 make_local_stiffness() const;
  Matrix6 local_consistent_mass() const;
  Matrix6 make_rotation() const;  // T: u' = T u
  double mass_per_length() const { return section_.density * section_.area + section_.extra_mass; }

  Section section_;
  bool consistent_mass_;
  model::ElementAxis axis_;
  // Kept: a recorder or drift monitor asks for end forces at every step.
  Matrix6 local_stiffness_, rotation_;
};

}  // namespace pound::assembly
