#pragma once
// What the model and its assembly need of an element, whatever its kind (dependency
// inversion: the model holds elements through this interface, the kinds live in assembly/, the
// builder makes them). An element keeps what its matrices need (node indices and coordinates,
// section, material, mass option) from its construction, so none of them needs the Model.
//
// DOFs: an element names the directions it needs at each of its nodes (numbered by its scene,
// model/direction.hpp: in a plane 0 x, 1 y, 2 rotation theta_z), the same at every node; its blocks
// are over its DOFs node by node, each node's directions in that order, in global axes. A scene
// carries at each node as many DOFs as its elements ask for (Model::dofs_per_node).
#include <algorithm>
#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "core/units.hpp"

namespace pound::model {

// (x, y, z): a scene uses its first `dimension` entries; the others stay 0.
using Coordinates = std::array<double, 3>;
// A vector of a scene's dimension ([x], [x, y] or [x, y, z], as model files give them) as
// Coordinates; the entries it lacks are 0.
Coordinates to_coordinates(std::span<const double> components);

// Rayleigh damping C = a0 M + a1 K of the linear elements (links are never part of it).
struct RayleighDamping {
  double mass_coefficient = 0.0;       // a0 [1/T]
  double stiffness_coefficient = 0.0;  // a1 [T]
};

// The geometric stiffness of second-order (P-Delta) analysis, from an element's axial force N
// (tension positive: tension stiffens, compression softens):
//   chord       P-Delta: N / L on the relative transverse displacement of the ends (the axial
//               force times the chord rotation; OpenSees' PDelta transformation, SAP2000's P-Delta)
//   consistent  P-Delta and P-delta: the cubic Hermitian shapes' geometric stiffness, which also
//               softens the member along its length and converges to the Euler buckling loads.
enum class GeometricStiffness { chord, consistent };

// A node of an element: its index in Model::nodes and where it is.
struct ElementNode {
  Index index = 0;
  Coordinates position{};
};

// One DOF of an element: a node (index in Model::nodes) and a direction (model/direction.hpp).
struct ElementDof {
  Index node = 0;
  int direction = 0;
};

// An element's mass over its DOFs: lumped (one value per DOF) or a consistent block.
struct ElementMass {
  Vector lumped;      // empty when consistent
  Matrix consistent;  // empty when lumped
  bool is_consistent() const { return consistent.size() > 0; }
};

// An end force's name (N_i, M_j, ...) and whether it is a force or a moment.
struct EndForce {
  std::string_view name;
  Dimension dimension = Dimension::force;
};

class Element {
 public:
  virtual ~Element() = default;

  const std::string& id() const { return id_; }
  const std::vector<Index>& nodes() const { return nodes_; }
  // Its own Rayleigh coefficients, or none (then the model's apply):
  // C = sum over elements of a0_e M_e + a1_e K_e.
  const std::optional<RayleighDamping>& damping() const { return damping_; }

  // Directions it needs at each node (model/direction.hpp), increasing.
  virtual std::span<const int> directions() const = 0;
  // Its DOFs, the rows and columns of its blocks: each node's directions, node by node.
  std::vector<ElementDof> dofs() const;
  // Stiffness K_e over dofs() in global axes, symmetric.
  virtual Matrix stiffness() const = 0;
  virtual ElementMass mass() const = 0;

  // Its end forces (none when it reports none), and their values for displacements u over
  // dofs(): in the element's local axes, units of force (moments force x length). Linear in u,
  // as the element is elastic (end_force_map).
  virtual std::span<const EndForce> end_force_names() const = 0;
  virtual Vector end_forces(const Vector& u) const = 0;

  // Its geometric stiffness over dofs() in global axes under the axial force it carries at
  // displacements u (over dofs()); empty for an element without one (a quad: plane continua
  // take no second-order effects here).
  virtual Matrix geometric_stiffness(const Vector& u, GeometricStiffness kind) const;

 protected:
  Element(std::string id, std::vector<Index> nodes, std::optional<RayleighDamping> damping)
      : id_(std::move(id)), nodes_(std::move(nodes)), damping_(damping) {}

 private:
  std::string id_;
  std::vector<Index> nodes_;
  std::optional<RayleighDamping> damping_;
};

// E with end_forces(u) = E u, (end forces) x dofs(): column j the end forces of a unit
// displacement of DOF j, so each entry is what end_forces forms for it. The recorders read end
// forces at every step as rows of E (only the ones asked for) over the DOFs.
Matrix end_force_map(const Element& element);

// Distance between two points of a scene of `dimension` 1 (along x only), 2 or 3.
double distance(const Coordinates& a, const Coordinates& b, int dimension);
// The cross product a x b.
Coordinates cross(const Coordinates& a, const Coordinates& b);

// The axis of a two-node element from end i to end j in a scene of `dimension` 1, 2 or 3: its
// length L and direction cosines ((x_j - x_i) / L, (y_j - y_i) / L, (z_j - z_i) / L).
struct ElementAxis {
  double length = 0.0;
  Coordinates cosines{};
};
ElementAxis element_axis(const std::array<ElementNode, 2>& ends, int dimension);

}  // namespace pound::model
