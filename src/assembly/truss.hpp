#pragma once
// Two-node axial element (rod, truss bar), linear elastic, in a 1-D scene (DOF u_x at each node),
// a plane one (u_x, u_y) or a 3-D one (u_x, u_y, u_z). DOFs (u_x,i [, u_y,i [, u_z,i]], u_x,j
// ...), global axes.
//
//   K = (E A / L) [[c c^T, -c c^T], [-c c^T, c c^T]],  c = (x_j - x_i) / L  (1-D: c = +-1)
//   M lumped: rho A L / 2 at each node in each direction
//   end force N = (E A / L) (u_j - u_i) . c, tension positive
//
// Units: E [F/L^2], A [L^2], rho [M/L^3], N [F]. Source: the pin-jointed bar of matrix
// structural analysis, e.g. Przemieniecki, "Theory of Matrix Structural Analysis" (1968),
// chapter 5 (stiffness) and chapter 11 (lumped mass).
#include <array>
#include <optional>

#include "model/element.hpp"

namespace pound::assembly {

class Truss final : public model::Element {
 public:
  struct Section {
    double youngs_modulus = 0.0;  // E [F/L^2]
    double area = 0.0;            // A [L^2]
    double density = 0.0;         // rho [M/L^3]
    // The axial force [F] (tension +) of the geometric stiffness, instead of the one u gives: a
    // leaning column whose ends the model holds vertically still carries the weight above it.
    std::optional<double> axial_force;
  };
  // `dimension` 1 (y, z ignored), 2 (z ignored) or 3; the ends are apart (the builder checks the
  // length).
  Truss(std::string id, const std::array<model::ElementNode, 2>& ends, int dimension,
        const Section& section, std::optional<model::RayleighDamping> damping);

  std::span<const int> directions() const override;
  Matrix stiffness() const override;
  model::ElementMass mass() const override;
  std::span<const model::EndForce> end_force_names() const override;
  Vector end_forces(const Vector& u) const override;
  Matrix geometric_stiffness(const Vector& u, model::GeometricStiffness kind) const override;

 private:
  int dimension_;
  Section section_;
  model::ElementAxis axis_;
  double axial_stiffness_;  // E A / L
};

}  // namespace pound::assembly
