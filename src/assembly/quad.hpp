#pragma once
// Four-node bilinear quadrilateral for plane continua (Suzuki & Toi's blocks and 2-D rods),
// nodes counter-clockwise round a convex quadrilateral. DOFs (u_x, u_y) node by node, global
// axes. Shape functions N_a = (1 + xi xi_a)(1 + eta eta_a) / 4 on the parent square; strains
// (e_xx, e_yy, gamma_xy) = B u; stresses sigma = D B u with
//   plane stress: D = E / (1 - nu^2) [[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]],
//   plane strain: D = E / ((1 + nu)(1 - 2 nu)) [[1 - nu, nu, 0], [nu, 1 - nu, 0],
//                                                [0, 0, (1 - 2 nu) / 2]]   (per thickness t).
// K = integral of B^T D B t dA and the consistent M = integral of rho t N^T N dA by 2 x 2 Gauss
// points: exact for a parallelogram (Suzuki & Toi 1987 integrate the stiffness exactly). Lumped
// mass: the row sums of the consistent one (positive for the bilinear shapes), rho t A / 4 per
// node of a parallelogram. No end forces (stresses are not reported yet).
//
// Units: E [F/L^2], t [L], rho [M/L^3]. Source: the isoparametric bilinear element of
// Zienkiewicz & Taylor, "The Finite Element Method", vol. 1 (5th ed., 2000), as used for impact
// by Suzuki & Toi (1987).
#include <Eigen/Dense>
#include <array>

#include "model/element.hpp"

namespace pound::assembly {

using Matrix8 = Eigen::Matrix<double, 8, 8>;
using QuadCorners = std::array<model::Coordinates, 4>;  // counter-clockwise

class Quad final : public model::Element {
 public:
  struct Material {
    double youngs_modulus = 0.0;  // E [F/L^2]
    double poisson_ratio = 0.0;   // nu, in [0, 0.5)
    double thickness = 0.0;       // t [L]
    double density = 0.0;         // rho [M/L^3]
    bool plane_strain = false;
  };
  // The corners go counter-clockwise (the builder checks quad_smallest_jacobian).
  Quad(std::string id, const std::array<model::ElementNode, 4>& corners, const Material& material,
       bool consistent_mass, std::optional<model::RayleighDamping> damping);

  std::span<const int> directions() const override;
  Matrix stiffness() const override;
  model::ElementMass mass() const override;
  std::span<const model::EndForce> end_force_names() const override { return {}; }
  Vector end_forces(const Vector&) const override { return {}; }

  Eigen::Matrix3d elasticity() const;  // D
  Matrix8 consistent_mass() const;

 private:
  QuadCorners corners_;
  Material material_;
  bool consistent_mass_;
};

// Strain (e_xx, e_yy, gamma_xy) at the parent point (xi, eta) for the element displacements.
Eigen::Vector3d quad_strain(const QuadCorners& corners, const Eigen::Matrix<double, 8, 1>& u,
                            double xi, double eta);
// Smallest Jacobian determinant over the element (at its corners): <= 0 when the element is
// inverted, degenerate or numbered clockwise.
double quad_smallest_jacobian(const QuadCorners& corners);
double quad_area(const QuadCorners& corners);

}  // namespace pound::assembly
