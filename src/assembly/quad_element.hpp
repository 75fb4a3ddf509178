#pragma once
// Matrices of the four-node bilinear quadrilateral (model::Quad) in global coordinates, DOFs
// ordered (u_x, u_y) node by node. Shape functions N_a = (1 + xi xi_a)(1 + eta eta_a) / 4 on
// the parent square; strains (e_xx, e_yy, gamma_xy) = B u; stresses sigma = D B u with
//   plane stress: D = E / (1 - nu^2) [[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]],
//   plane strain: D = E / ((1 + nu)(1 - 2 nu)) [[1 - nu, nu, 0], [nu, 1 - nu, 0],
//                                                [0, 0, (1 - 2 nu) / 2]].
// K = integral of B^T D B t dA and M = integral of rho t N^T N dA by 2 x 2 Gauss points: exact
// for a parallelogram (Suzuki & Toi 1987 integrate the stiffness exactly).
#include <Eigen/Dense>
#include <array>

#include "model/model.hpp"

namespace pound::assembly {

using Matrix8 = Eigen::Matrix<double, 8, 8>;
using QuadCorners = std::array<model::Coordinates, 4>;  // counter-clockwise

Eigen::Matrix3d quad_elasticity(const model::Quad& quad);
Matrix8 quad_stiffness(const model::Quad& quad, const QuadCorners& corners);
Matrix8 quad_consistent_mass(const model::Quad& quad, const QuadCorners& corners);
// Strain (e_xx, e_yy, gamma_xy) at the parent point (xi, eta) for the element displacements.
Eigen::Vector3d quad_strain(const QuadCorners& corners, const Eigen::Matrix<double, 8, 1>& u,
                            double xi, double eta);
// Smallest Jacobian determinant over the element (at its corners): <= 0 when the element is
// inverted, degenerate or numbered clockwise.
double quad_smallest_jacobian(const QuadCorners& corners);
double quad_area(const QuadCorners& corners);

}  // namespace pound::assembly
