#pragma once
// The physical model: nodes, elements, masses, supports, links, initial velocities. Indices
// refer to `nodes`; the builder has already checked every reference and value.
//
// Degrees of freedom follow the scene: a 1-D (axial) scene carries 1 DOF per node (u_x); a
// plane truss scene carries 2 (u_x, u_y); a plane frame scene (any beam-column) carries 3
// (u_x, u_y, theta_z); a plane continuum scene (quads, no beams) carries 2; a 3-D truss scene 3
// (u_x, u_y, u_z) and a 3-D frame scene 6 (and the three rotations). Nothing is padded: each
// element says which directions it needs (model/element.hpp, numbered as model/direction.hpp).
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "links/coupled_shear.hpp"
#include "links/law_registry.hpp"
#include "links/link_context.hpp"
#include "model/direction.hpp"
#include "model/dof_term.hpp"
#include "model/element.hpp"
#include "model/ground_motion.hpp"

namespace pound::model {

struct Node {
  std::string id;
  Coordinates position{};
};

struct NodalMass {
  Index node = 0;
  double mass = 0.0;                       // [M], in every translational direction
  Coordinates rotary_inertia{};            // [M L^2] about x, y, z (plane frames: z only)
  std::optional<RayleighDamping> damping;  // its own mass-proportional part, instead of the model's
};

struct NodalLoad {
  Index node = 0;
  Coordinates force{};  // constant from t = 0 [F]
};

struct Support {
  Index node = 0;
  std::array<bool, 6> fixed{};  // per direction of its scene (model/direction.hpp)
};

// Uniform support excitation: every support moves with the record along `direction`; the
// equations are in displacements relative to the ground, with loads -M iota a_g(t).
struct UniformExcitation {
  GroundMotion motion;
  Coordinates direction{1.0, 0.0};  // unit vector
};

// Multi-support excitation: the listed supports move along `direction` with the record, each
// after its delay; the others stand still. Solved as u = u_dyn + R u_s (R = -K_ff^-1 K_fs, the
// quasi-static influence of the supports): loads -M R a_s(t), and links see R u_s + u_s directly.
struct SupportExcitation {
  GroundMotion motion;
  Coordinates direction{1.0, 0.0};
  std::vector<std::pair<Index, double>> supports;  // node, delay [T]
};

// Contact link between node i and node j along the unit axis n (from i towards j):
// penetration delta = (u_i - u_j) . n - gap.
// Coulomb friction in the contact plane: along the tangent t = n rotated by +90 degrees in a
// plane scene; along t_1 and t_2 (contact_tangents) in 3-D.
// With rigid offsets r_i, r_j the points that touch are node + r, moving as u + theta x r.
// Node-to-segment: the j side is the point (1 - w) u_j + w u_k of the segment j-k, w fixed at
// t = 0 (small sliding). A rigid moving surface (a belt) is a fixed node j whose side of the
// link moves at a constant velocity: u_j + velocity_j t.
// With a radius of curvature the friction is a friction pendulum bearing's
// (links/coulomb_friction.hpp): a restoring force R_n s / R on top of the Coulomb part.
struct LinkFriction {
  double coefficient = 0.0;
  std::optional<double> stick_stiffness, stick_damping, stick_mass;  // default: the normal law's
  std::optional<double> radius;                                      // [L] > 0; none: a flat slider
};

// A bearing's shear across the link's axis (a hinge's bending across it), its directions coupled
// (links/coupled_shear.hpp), from the numbers of a uniaxial law along each tangent (`law`, the
// type, for messages and summaries).
struct LinkShear {
  std::string law;
  links::ShearDirections numbers;
  std::optional<links::ShearDamping> damping;  // the link's `rayleigh`
  bool circular() const { return numbers[0] == numbers[1]; }
};

// The tangents of a contact plane with unit normal n: t = z x n in a plane scene (n turned by
// +90 degrees); in 3-D t_1 = z x n / |z x n| (horizontal, the plane scene's t when n lies in
// the x-y plane) and t_2 = n x t_1 (z for a horizontal n); for a vertical n, t_1 = x, t_2 = y.
std::vector<Coordinates> contact_tangents(const Coordinates& normal, int dimension);

struct Link {
  std::string id;
  Index node_i = 0;
  Index node_j = 0;
  Coordinates axis{1.0, 0.0};
  // Acts on theta_i - theta_j (frame scenes), e.g. a plastic hinge: about z in a plane, about
  // `axis` in 3-D.
  bool rotational = false;
  double gap = 0.0;                      // initial clear distance [L], >= 0
  const links::LawEntry* law = nullptr;  // its law's registry entry (role, traits); none in code
  links::LawFactory make_law;
  // The spec make_law makes its law from, when that is all it is made from (none: a law made in
  // code, or wrapped in the link's own Rayleigh damping): equal specs make equal laws.
  std::optional<links::LawSpec> law_spec;
  std::optional<LinkFriction> friction;
  std::optional<LinkShear> shear;  // on the tangential rows, as friction (never both)
  // 3-D: t_1 of the tangential rows, a unit vector across the axis (t_2 = axis x t_1); none:
  // contact_tangents'.
  std::optional<Coordinates> tangent;
  // Rigid offsets from node i and node j to the points that touch: the row follows
  // u + theta x r at each end (small rotations), so the nodes turn with the link.
  std::array<Coordinates, 2> offsets{};
  bool has_offsets() const { return offsets != std::array<Coordinates, 2>{}; }
  std::optional<Index> segment_end;  // node k
  double segment_weight = 0.0;       // w in [0, 1]
  Coordinates velocity_j{0.0, 0.0};  // [L/T]

  // What the link is for; a law made in code (no registry entry) counts as a contact.
  links::LinkRole role() const { return law ? law->traits.role : links::LinkRole::contact; }
};

// Gravity (2-D scenes): every mass weighs m g along `direction`, constant loads M iota g from
// t = 0 beside the nodal loads, and the run starts from static equilibrium under them. With
// `p_delta`, the elements' geometric stiffness under the axial forces of a linear gravity
// analysis (links at their initial stiffness) joins K, held constant through the record: the
// linearised second-order analysis of design codes (SAP2000's P-Delta from an initial case).
struct Gravity {
  Coordinates direction{0.0, -1.0};  // unit vector
  double acceleration = 0.0;         // g [L/T^2]
  std::optional<GeometricStiffness> p_delta;
};

// Master–slave constraints (OpenSees' equalDOF, rigidDiaphragm, rigidLink): the tied DOFs of
// each slave follow its master's and leave the equations (DofMap). With r = x_slave - x_master
// and small rotations:
// - rigid_beam: a rigid body, u_s = u_m + theta_m x r and theta_s = theta_m (plane scenes: about
//   z only);
// - rigid_diaphragm: a floor rigid in its plane (3-D), the plane perpendicular to axis `normal`:
//   the translations in the plane as the rigid body's, with theta_m about the normal only, and
//   the rotation about the normal; the other DOFs (vertical, rocking) stay the slave's own;
// - rigid_bar: the translations alone, u_s = u_m (pinned ends);
// - equal_dofs: each direction in `tied` equal to the master's, with no lever arm.
enum class ConstraintKind { equal_dofs, rigid_diaphragm, rigid_beam, rigid_bar };
struct Constraint {
  ConstraintKind kind = ConstraintKind::equal_dofs;
  Index master = 0;
  std::vector<Index> slaves;
  std::array<bool, 6> tied{};  // equal_dofs: the directions (model/direction.hpp)
  int normal = 2;              // rigid_diaphragm: 0 x, 1 y, 2 z
};

// The directions a constraint ties in a scene of `dimension` (model/direction.hpp).
std::array<bool, 6> tied_directions(const Constraint& constraint, int dimension);
// A tied slave DOF as its master's: (master's direction, weight) pairs, nonzero weights only;
// empty where the constraint leaves `direction` free. r = x_slave - x_master.
std::vector<std::pair<int, double>> tie_terms(const Constraint& constraint, int direction,
                                              const Coordinates& r, int dimension);

struct Model {
  int dimension = 1;  // 1, 2 or 3
  std::vector<Node> nodes;
  // Shared, so that a Model stays copyable: an element never changes once made.
  std::vector<std::shared_ptr<const Element>> elements;
  std::vector<NodalMass> masses;
  std::vector<Support> supports;
  std::vector<NodalLoad> loads;
  std::vector<Link> links;
  std::vector<Coordinates> initial_velocity;  // per node (empty: at rest)
  std::optional<RayleighDamping> damping;
  std::vector<UniformExcitation> excitations;
  std::vector<SupportExcitation> support_excitations;
  std::optional<Gravity> gravity;
  std::vector<Constraint> constraints;

  // The scene's translations, or more where an element needs more (a beam's rotation).
  int dofs_per_node() const;
};

// Equation numbers of the free DOFs, in node order (a chain of nodes gives a banded matrix). A
// DOF is free (its own equation), fixed (none) or tied by a constraint (a combination of its
// master's equations, which it has no equation of its own beside).
class DofMap {
 public:
  explicit DofMap(const Model& model);
  Index size() const { return size_; }
  int dofs_per_node() const { return dofs_per_node_; }
  int dimension() const { return dimension_; }  // the scene's, for model::direction
  bool has_ties() const { return has_ties_; }
  // The DOF's own equation: -1 where it is fixed or tied (its value is then not an unknown).
  Index own_equation(Index node, int direction) const {
    const Index equation = equations_[place(node, direction)];
    return equation >= 0 ? equation : -1;
  }
  bool tied(Index node, int direction) const { return equations_[place(node, direction)] < -1; }
  // The DOF as a combination of equations: one term of coefficient 1 where it is free, none
  // where it is fixed, its master's where it is tied. Read and scatter every DOF through these.
  std::span<const DofTerm> terms(Index node, int direction) const {
    const std::size_t at = place(node, direction);
    return {terms_.data() + first_term_[at], terms_.data() + first_term_[at + 1]};
  }

 private:
  void build_terms(const Model& model);
  std::size_t place(Index node, int direction) const {
    return static_cast<std::size_t>(node * dofs_per_node_ + direction);
  }
  int dofs_per_node_;
  int dimension_;
  Index size_ = 0;
  bool has_ties_ = false;
  std::vector<Index> equations_;  // >= 0 free, -1 fixed, -2 tied
  std::vector<std::size_t> first_term_;
  std::vector<DofTerm> terms_;
};

}  // namespace pound::model
