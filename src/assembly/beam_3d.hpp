#pragma once
// Two-node 3-D elastic beam-column (Euler-Bernoulli bending about both principal axes, axial,
// Saint-Venant torsion; no shear deformation, no warping), for girders, piers and columns of a
// 3-D scene (docs/design.md 4.5). DOFs per node (u_x, u_y, u_z, theta_x, theta_y, theta_z) in
// global axes, rotations right-handed: a 3-D scene's directions 0 to 5 (model/direction.hpp).
//
// Ends: each node plus an optional rigid offset o (global, from the node to the end of the
// flexible part, as OpenSees' jntOffset): the end moves as u_end = u_node + theta_node x o, so
// u_end = R u_node with R = [[I, -[o]x], [0, I]] per node.
// Local axes (OpenSees' geomTransf with vecxz): x' from end i to end j; y' = v x x' / |v x x'|
// with v the orientation vector, which lies in the local x'-z' plane; z' = x' x y'. Lambda has
// the rows x', y', z', the same for translations and rotations at both ends, u' = Lambda R u.
// K = (Lambda R)^T K' (Lambda R) with K' on (u', v', w', theta_x', theta_y', theta_z') per end:
//   axial EA/L [[1, -1], [-1, 1]] on (u'_i, u'_j); torsion GJ/L the same on (theta_x'_i, _j);
//   bending in x'-y' (v', theta_z'), E I_z: EI/L^3 [[12, 6L, -12, 6L], [6L, 4L^2, -6L, 2L^2],
//     [-12, -6L, 12, -6L], [6L, 2L^2, -6L, 4L^2]], as the 2-D beam;
//   bending in x'-z' (w', theta_y'), E I_y: the same with theta_y' = -dw'/dx', so the terms
//     coupling w' and theta_y' change sign.
// Mass per length m = rho A + extra mass:
//   lumped: m L / 2 at each node along x, y and z, no rotary inertia (as the 2-D beam);
//   consistent: Lambda R as above on m L / 6 [[2, 1], [1, 2]] axially, rho I_p L / 6
//   [[2, 1], [1, 2]] in torsion (I_p = I_y + I_z, the polar moment of the section), and the
//   cubic Hermitian m L / 420 block of the 2-D beam in each bending plane (signs as K').
// End forces f' = K' Lambda R u: what the ends apply to the element, local axes, (N, V_y, V_z,
// T, M_y, M_z) at i then at j; a bar in tension has N_j = -N_i > 0.
// Geometric stiffness under the axial force N = N_j: chord P-Delta N / L on the ends' relative
// v' and w', or the consistent Hermitian form of the 2-D beam in each bending plane.
//
// Units: E, G [F/L^2], A [L^2], I_y, I_z, J [L^4], rho [M/L^3], extra mass [M/L]; forces [F],
// moments [F L]. Sources: Przemieniecki, "Theory of Matrix Structural Analysis" (1968), chapters
// 5 and 11 (the 12 x 12 stiffness and consistent mass); McKenna et al., OpenSees'
// LinearCrdTransf3d (the vecxz convention and rigid joint offsets).
#include <Eigen/Dense>
#include <array>
#include <optional>
#include <string>

#include "model/element.hpp"

namespace pound::assembly {

using Point3 = Eigen::Vector3d;

class Beam3d final : public model::Element {
 public:
  struct Section {
    double youngs_modulus = 0.0;  // E [F/L^2]
    double shear_modulus = 0.0;   // G [F/L^2]
    double area = 0.0;            // A [L^2]
    double inertia_y = 0.0;       // I_y [L^4], bending about y' (in the x'-z' plane)
    double inertia_z = 0.0;       // I_z [L^4], bending about z' (in the x'-y' plane)
    double torsion = 0.0;         // J [L^4], Saint-Venant torsion constant
    double density = 0.0;         // rho [M/L^3]
    double extra_mass = 0.0;      // [M/L]
  };
  struct End {
    Index node = 0;
    Point3 position = Point3::Zero();  // of the node
    Point3 offset = Point3::Zero();    // rigid, from the node to the flexible part's end
  };
  // Throws std::invalid_argument when the flexible part has no length or an infinite one, or when
  // `orientation` is zero or parallel to it (it must fix the x'-z' plane).
  Beam3d(std::string id, const std::array<End, 2>& ends, const Point3& orientation,
         const Section& section, bool consistent_mass,
         std::optional<model::RayleighDamping> damping);

  std::span<const int> directions() const override;
  Matrix stiffness() const override;
  model::ElementMass mass() const override;
  std::span<const model::EndForce> end_force_names() const override;
  Vector end_forces(const Vector& u) const override;
  Matrix geometric_stiffness(const Vector& u, model::GeometricStiffness kind) const override;

  double length() const { return length_; }
  // The local axes x', y', z' as the rows.
  const Eigen::Matrix3d& axes() const { return axes_; }

 private:
  using Matrix12 = Eigen::Matrix<double, 12, 12>;
  Matrix12 make_local_stiffness() const;
  Matrix12 local_consistent_mass() const;
  Matrix12 make_transformation(const std::array<End, 2>& ends) const;  // Lambda R
  double mass_per_length() const { return section_.density * section_.area + section_.extra_mass; }

  Section section_;
  bool consistent_mass_;
  double length_ = 0.0;
  Eigen::Matrix3d axes_;
  // Kept: recorders and monitors ask for end forces at every step.
  Matrix12 local_stiffness_, transformation_;
};

}  // namespace pound::assembly
