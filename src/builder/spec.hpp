#pragma once
// What a model file says, as plain data: the io/ reader fills these from JSON (checking types,
// required fields, unknown fields and value ranges, each with its JSON path), the builder
// checks references between them and turns them into a model::Model.
//
// Every vector here mirrors an array of the file, so an index k of `links` is the JSON path
// "/links/k"; the builder names errors that way.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/units.hpp"
#include "integrators/integrator_catalog.hpp"
#include "integrators/transient_analysis.hpp"
#include "links/law_registry.hpp"
#include "links/stiffness_damping.hpp"

namespace pound::builder {

// A link law, by name with its parameters (links/law_registry.hpp describes each; the reader has
// checked names, ranges and combinations against it).
using LawSpec = links::LawSpec;

struct NodeSpec {
  std::string id;
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;  // 3-D scenes
};

struct MaterialSpec {
  std::string id;
  double youngs_modulus = 0.0;          // E [F/L^2], > 0
  double density = 0.0;                 // rho [M/L^3], >= 0
  std::optional<double> poisson_ratio;  // nu in [0, 0.5), needed by plane continua (quads)
  std::optional<double> shear_modulus;  // G [F/L^2] of 3-D beams' torsion; default E / (2 (1 + nu))
};

// "truss", "beam" (elastic beam-column of a plane or 3-D frame scene), "quad" (plane continuum).
enum class ElementKind { truss, beam, quad };

struct ElementSpec {
  std::string id;
  ElementKind type = ElementKind::truss;
  std::string node_i;
  std::string node_j;
  std::string material;
  double area = 0.0;     // [L^2], > 0
  double inertia = 0.0;  // plane beam: second moment of area [L^4], > 0
  // 3-D beam: I_y, I_z about its local y', z' axes and the torsion constant J [L^4], > 0; the
  // orientation vector in its local x'-z' plane (OpenSees' vecxz); rigid end offsets [L] from
  // nodes i and j to the ends of the flexible part, global axes.
  double inertia_y = 0.0, inertia_z = 0.0, torsion = 0.0;
  std::array<double, 3> orientation{0.0, 0.0, 0.0};
  std::array<std::array<double, 3>, 2> offsets{};
  double extra_mass = 0.0;       // beam: added mass per length [M/L] (deck, barriers, floor)
  bool consistent_mass = false;  // beam, quad: "mass": "consistent" (default "lumped")
  // Its own Rayleigh coefficients {a0, a1} instead of the model's ("damping" object).
  std::optional<std::array<double, 2>> rayleigh;
  std::vector<std::string> more_nodes;  // quad: the third and fourth (counter-clockwise)
  double thickness = 0.0;               // quad [L], > 0
  bool plane_strain = false;            // quad: "plane": "strain" (default "stress")
  // truss: the axial force [F] (tension +) of its geometric stiffness, in place of the gravity
  // analysis's: a leaning column whose ends the model holds vertically (adjacent_buildings).
  std::optional<double> axial_force;
};

struct MassSpec {
  std::string node;
  double mass = 0.0;                       // [M], > 0
  std::array<double, 3> rotary_inertia{};  // [M L^2] about x, y, z; plane frames: z only
  std::optional<double> mass_damping;      // its own a0 instead of the model's
};

struct SupportSpec {
  std::string node;
  std::array<bool, 6> fixed{};  // per direction of its scene (model/direction.hpp): x, y, rz in a
                                // plane; x, y, z, rx, ry, rz in 3-D
};

// A master–slave constraint (model/model.hpp, Constraint): the slaves' tied DOFs follow the
// master's and leave the equations.
enum class ConstraintKind { rigid_diaphragm, rigid_beam, rigid_bar, equal_dofs };
struct ConstraintSpec {
  ConstraintKind type = ConstraintKind::rigid_diaphragm;
  std::string master;
  std::vector<std::string> slaves;
  std::array<bool, 6> dofs{};  // equal_dofs: per direction of its scene (model/direction.hpp)
  int normal = 2;              // rigid_diaphragm: the axis its plane is perpendicular to
};

// A vector at a node, in global axes.
struct NodalVectorSpec {
  std::string node;
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;  // 3-D scenes
};

// An initial velocity [L/T].
using InitialVelocitySpec = NodalVectorSpec;
// A constant nodal force (dead load, gravity on a lumped mass) acting from t = 0 [F].
using LoadSpec = NodalVectorSpec;

// Coulomb friction on a 2-D link (links/coulomb_friction.hpp). The stick penalty defaults to
// the normal law's own tangent (k, c, m of a linear law; alpha0..2 of the extended penalty).
struct FrictionSpec {
  double coefficient = 0.0;  // mu >= 0, static = kinetic
  std::optional<double> stick_stiffness, stick_damping, stick_mass;
  std::optional<double> radius;  // a friction pendulum's radius of curvature [L] > 0 (links only)
};

// Stiffness-proportional damping added to a structural spring or hinge
// (links/stiffness_damping.hpp).
struct LinkRayleighSpec {
  links::DampingStiffness stiffness = links::DampingStiffness::initial;
  std::optional<double> stiffness_coefficient;  // a1 [T]; default the model's Rayleigh a1
};

struct LinkSpec {
  std::string id;
  std::string node_i;
  std::string node_j;
  double gap = 0.0;                         // [L], >= 0; never negative, never flipped
  std::optional<std::vector<double>> axis;  // unit vector from i to j; default from coordinates
  LawSpec law;
  std::optional<FrictionSpec> friction;
  // A bearing's shear across the axis, its two directions coupled (links/coupled_shear.hpp); the
  // link's law is then its axial law. Never with friction. With shear_2 (3-D): the law along the
  // second tangent (an elliptic surface), shear's along the first.
  std::optional<LawSpec> shear, shear_2;
  // 3-D: the first tangent t_1 of the friction's or the shear's plane, projected across the axis
  // (a bearing's or a hinge's local axes); none: contact_tangents'.
  std::optional<std::vector<double>> tangent;
  // Rigid offsets [L] from node i and node j to the points that touch (global axes; z = 0 in a
  // plane): a deck corner or a floor corner rigidly tied to the node at its centre.
  std::optional<std::array<std::array<double, 3>, 2>> offsets;
  bool rotational = false;  // "dof": "rotation": acts on theta_i - theta_j (hinge springs)
  // Node-to-segment: the j side is the point of segment node_j - segment_end nearest node i.
  std::optional<std::string> segment_end;
  std::array<double, 2> velocity_j{0.0, 0.0};  // a rigid surface's own motion (generated)
  std::optional<LinkRayleighSpec> rayleigh;
};

// A rectangular plane body of quads ("block" generator): nodes "<id>.<column>.<row>" from the
// lower left corner, elements "<id>.e<column>.<row>", node sets "<id>.bottom", ".top", ".left",
// ".right" for surfaces, contacts and loads.
struct BlockSpec {
  std::string id;
  std::array<double, 2> origin{0.0, 0.0};  // lower left corner
  double width = 0.0, height = 0.0;        // [L] > 0
  int columns = 0, rows = 0;               // elements along x and y
  std::string material;
  double thickness = 0.0;
  bool plane_strain = false;
  bool consistent_mass = false;
  std::array<double, 2> initial_velocity{0.0, 0.0};
  std::array<double, 4> pressure{0.0, 0.0, 0.0, 0.0};  // on bottom, right, top, left [F/L^2]
  std::vector<std::string> fixed_edges;                // "bottom", "left", ...: all DOFs fixed
  int generator_index = 0;
};

// A rigid flat surface (a floor, a belt) touching a set of nodes: one contact link per node to
// a generated fixed node "<id>", along -normal, with gap = the node's clear distance.
struct SurfaceSpec {
  std::string id;
  std::array<double, 2> point{0.0, 0.0};
  std::array<double, 2> normal{0.0, 1.0};  // unit, pointing out of the surface to the nodes
  std::array<double, 2> velocity{0.0, 0.0};
  std::vector<std::string> nodes;  // node ids or node-set names
  LawSpec law;
  std::optional<FrictionSpec> friction;
  int index = 0;
};

// Contact between two bodies' boundaries: each node of `nodes` against the segments of
// `segments` (a chain of nodes in order), node-to-node where a node faces a segment end,
// node-to-segment elsewhere; links "<id>.<node>".
struct ContactSpec {
  std::string id;
  std::vector<std::string> nodes;     // contacting nodes (ids or node sets)
  std::vector<std::string> segments;  // the facing boundary, a chain of nodes
  LawSpec law;
  std::optional<FrictionSpec> friction;
  int index = 0;
};

// The model's units, for converting records: only length and time matter.
struct UnitsSpec {
  std::string length = "m";         // m, cm, mm, km, in, ft
  std::string time = "s";           // s, ms
  std::optional<std::string> mass;  // kg, t: with it, forces have a unit too
  // The acceleration of gravity (9.80665 m/s^2) in these units.
  double gravity() const;
  double second() const;  // one second in these units of time
  // The force unit mass x length / time^2 ("N", "kN", "MN", "mN", else the product written out);
  // none without a mass unit.
  std::optional<std::string> force() const;
  // The unit of each dimension in these units (forces and moments "" without a mass unit).
  UnitNames names() const;
};

// Rayleigh damping C = a0 M + a1 K of the linear elements: `ratio` at two periods (or at the
// periods of two modes, counted from 1), or the coefficients themselves.
struct DampingSpec {
  double ratio = 0.0;
  std::optional<std::array<double, 2>> periods;
  std::optional<std::array<int, 2>> modes;
  std::optional<double> mass_coefficient, stiffness_coefficient;
};

// Uniform support excitation by a record (read by io/, scaled by the builder).
// The second horizontal component of a station's record (3-D scenes): another file, or another
// column of the first's, read as the first is (format, units, time step). The first component acts
// along (cos a, sin a, 0), the second along (-sin a, cos a, 0): the pair turned by `angle` a.
struct PairSpec {
  std::optional<std::string> record;  // default: the first component's file
  std::optional<int> column;          // default: the first component's
  double angle = 0.0;                 // [degrees], counter-clockwise about +z
};

struct ExcitationSpec {
  std::string record;           // path, relative to the model file
  std::string format = "auto";  // "at2", "columns", "auto"
  int column = 1;
  std::optional<double> time_step;
  bool time_column = false;
  std::string units = "g";  // of the file's values: "g", "m/s2", "cm/s2", "model"
  std::optional<double> scale_factor;
  std::optional<double> target_pga;  // [g]
  std::optional<double> target_sa;   // [g] at sa_period
  double sa_period = 0.0;
  double sa_damping = 0.05;
  // Applied after the scale above: a batch's incremental-dynamic-analysis factor.
  double extra_factor = 1.0;
  std::vector<double> direction{1.0};  // unit vector (1-D: [1] or [-1])
  // With a pair, the record is the first of two horizontal components (scaled together: a
  // target is the pair's RotD50) and `direction` is not used.
  std::optional<PairSpec> pair;
  // Multi-support excitation: the supports this record moves (empty: every support, uniform),
  // optionally reached by a wave at apparent_velocity from `wave_origin` (delay |x - x0| / c).
  std::vector<std::string> supports;
  std::optional<double> apparent_velocity;
  double wave_origin = 0.0;
};

// One rod of a rod_pair generator.
struct RodSpec {
  double youngs_modulus = 0.0;
  double density = 0.0;
  double area = 0.0;
  double length = 0.0;
  int elements = 0;               // n >= 1
  double initial_velocity = 0.0;  // along +x
  bool far_end_fixed = false;     // "far_end": "free" | "fixed"
};

// Two collinear rods joined by a contact link: the left rod on [-L1, 0], the right rod's nodes
// on [0, L2] (both facing nodes at x = 0; the clear distance is the link's gap). The exact
// solution places the right rod at [gap, gap + L2], which is the same physics. With right_wall
// the left rod strikes a fixed rigid wall (node "<id>.wall" at x = 0) across the gap instead.
struct RodPairSpec {
  std::string id;  // prefix of generated ids: "<id>.left.0" ... , link "<id>.contact"
  RodSpec left;
  RodSpec right;  // unused with right_wall
  bool right_wall = false;
  double gap = 0.0;
  LawSpec law;
};

// Adjacent buildings as storey-stick (shear building) models (2-D scene): rigid floors
// (floor nodes move in x only), storey stiffness k as a column with E I = k h^3 / 12 between
// floors whose rotations are fixed. Pounding links join the buildings at every height where a
// floor of either meets the other (floor to floor, or floor to column mid-height).
// A yielding storey: `law` is its storey shear-drift law (a spring law whose `stiffness` the
// storey's own sets), a shear link between its floors in place of its column. The floors of the
// other building must meet it at its own floors (a link has no column to hit mid-height).
// In a 3-D scene (x toward the other building, y along the facades, z up) each floor is a rigid
// diaphragm with three DOFs (u_x, u_y, theta_z) at its mass centre, and each storey a column
// stick at its stiffness centre reaching the floors through rigid offsets.
struct StoreySpec {
  double height = 0.0;     // [L]
  double mass = 0.0;       // floor mass [M]
  double stiffness = 0.0;  // lateral storey stiffness [F/L] (along x in 3-D)
  std::optional<LawSpec> law;
  // 3-D: the stiffness along y (default `stiffness`), the torsional stiffness about the
  // stiffness centre [F L / rad] (default: the lateral stiffness spread evenly over the plan
  // a x b, (k_x b^2 + k_y a^2) / 12), and the floor's polar moment of inertia about its mass
  // centre [M L^2] (default a uniform slab's, m (a^2 + b^2) / 12).
  std::optional<double> stiffness_y, torsional_stiffness, rotary_inertia;
  // Whether `law` has a coupled form (links/coupled_shear.hpp) once the storey sets its
  // stiffness.
  bool law_couples(const links::LawSource& where) const;
};
// What a yielding storey's link adds to the building's stiffness-proportional damping a1 K:
// initial, a linear dashpot a1 k0 beside it (the elastic building's damping, whatever the
// law's state); none.
enum class StoreyDamping { initial, committed, none };
struct BuildingSpec {
  std::vector<StoreySpec> storeys;  // from the ground up
  double damping_ratio = 0.0;       // Rayleigh on the building's own modes 1 and 2 (0: none)
  StoreyDamping storey_damping = StoreyDamping::initial;
  // 3-D: each yielding storey one link whose x and y shears yield together on an ellipse
  // (true), or one link per direction (false); none: coupled where the storey's law has the
  // coupled form.
  std::optional<bool> storeys_coupled;
  // 3-D: plan dimensions a along x (toward the other building) and b along y [L], and where the
  // mass centre and the stiffness centre lie from the plan's centre (at every floor) [L].
  std::array<double, 2> plan{0.0, 0.0};
  std::array<double, 2> mass_centre{0.0, 0.0}, stiffness_centre{0.0, 0.0};
};
struct AdjacentBuildingsSpec {
  std::string id;
  int generator_index = 0;
  BuildingSpec left, right;
  double separation = 0.0;  // clear gap between the facades [L]
  LawSpec law;              // pounding law of every link
  // 3-D: the right building's plan centre from the left's along y [L], and the pounding points
  // at each contact height, spread along the stretch where the facades face each other (2: its
  // ends, the corners that meet; 1: its middle), each with the whole law.
  double offset = 0.0;
  int contact_points = 2;
};
// Floors of the two buildings closer in height than this are level: they meet floor to floor.
// 5 % of the lowest storey of either, about a slab's depth for storeys of 3-4 m: a floor a hair
// off the other building's would otherwise strike its column a hair below that floor (a column
// stub far stiffer than anything else in the model), beside a second link to the floor itself.
double level_tolerance(const AdjacentBuildingsSpec& pair);
// The stretch of y where the two facades face each other, [low, high] (3-D; empty when
// high <= low).
inline std::array<double, 2> facing_stretch(const AdjacentBuildingsSpec& pair) {
  return {std::max(-0.5 * pair.left.plan[1], pair.offset - 0.5 * pair.right.plan[1]),
          std::min(0.5 * pair.left.plan[1], pair.offset + 0.5 * pair.right.plan[1])};
}

// A multi-span girder bridge in a 2-D scene (x along the bridge, y up): girders as beams on
// bearings (a horizontal law and a stiff vertical spring) on piers (beams fixed at the base) and
// abutments; expansion joints at chosen piers and at both abutments with a gap, a pounding law,
// optionally a restrainer, and a seat width; abutment backfill behind the backwalls.
struct SectionSpec {
  double youngs_modulus = 0.0, area = 0.0, inertia = 0.0, density = 0.0;
  double extra_mass = 0.0;  // per length [M/L]
  int elements = 2;         // per span (girder) or per pier
  // 3-D scenes: `inertia` bends in the vertical plane along the bridge; `inertia_lateral` across
  // it (a girder's about the vertical, a pier's across the bridge), `torsion` J [L^4], and the
  // material's Poisson ratio for G = E / (2 (1 + nu)).
  double inertia_lateral = 0.0, torsion = 0.0, poisson_ratio = 0.2;
};
// Shear keys: transverse stops on each abutment seat, either side of the deck end, that a deck
// sliding across the bridge strikes after `gap` (compression-only links).
struct ShearKeySpec {
  double gap = 0.0;
  LawSpec law;
};
struct JointSpec {
  double gap = 0.0;
  LawSpec law;
  std::optional<LawSpec> restrainer;  // a tension law (restrainer / hook)
  double seat_width = 0.0;            // [L]; 0: not checked
};
// Plastic hinges at the piers' bases: a zero-length rotational link between the base support
// and the pier (concentrated plasticity), whose moment-rotation law is the user's with
//   M_y = yield_moment, or E I phi_y from the section's yield curvature phi_y,
//   k_h = (n + 1) 3 E I / h elastic stiffness, the piers' E I raised to (n + 1) / n E I,
// so that the pier's elastic lateral stiffness 3 E I / h^3 is unchanged (Ibarra & Krawinkler
// 2005, for a member in single curvature: the girders sit on bearings, so a pier is a
// cantilever). The pier then yields at the top displacement Delta_y = M_y h^2 / (3 E I), its
// drift monitor's yield drift; with a plastic-hinge length L_p the curvature ductility is
// 1 + theta_p / (phi_y L_p) (Priestley, Seible & Calvi 1996). In a 3-D bridge each pier base
// bends about both axes, across the bridge with E I_lateral and its own M_y or phi_y (default the
// same as along): one hinge whose two directions yield together on the ellipse
// (M_x / M_yx)^2 + (M_y / M_yy)^2 = 1 (a circle for a circular column), or two uniaxial hinges
// (no interaction: up to sqrt(2) stronger at 45 degrees).
struct PierHingeSpec {
  std::optional<double> yield_moment;              // [F L]
  std::optional<double> yield_curvature;           // [1/L]
  std::optional<double> yield_moment_lateral;      // [F L], 3-D: across the bridge
  std::optional<double> yield_curvature_lateral;   // [1/L], 3-D: across the bridge
  std::optional<double> plastic_hinge_length;      // [L]
  double stiffness_factor = 10.0;                  // n
  LawSpec law;                                     // stiffness and yield_force set by the generator
  std::optional<links::DampingStiffness> damping;  // the model's a1 times k_0 or k_t; none
  // 3-D: one hinge bending about x and y on an elliptic yield surface (true), two uniaxial
  // hinges (false); none: coupled where law_couples() and there is no damping.
  std::optional<bool> coupled;
  // Whether the law has a coupled form (links/coupled_shear.hpp) once the generator sets its
  // stiffness and yield force.
  bool law_couples(const links::LawSource& where) const;
};
struct GirderBridgeSpec {
  std::string id;
  int generator_index = 0;
  std::vector<double> spans;  // [L]
  SectionSpec girder{.elements = 4};
  SectionSpec pier;
  double pier_height = 0.0;                 // [L]
  std::optional<double> pier_yield_drift;   // [L], for displacement ductility
  std::optional<PierHingeSpec> pier_hinge;  // yielding piers
  std::optional<LawSpec> bearing;           // horizontal law of every bearing
  double bearing_vertical_stiffness = 0.0;  // [F/L]
  std::vector<int> expansion_joints;        // pier numbers (1 .. spans - 1) where the deck is cut
  JointSpec joint;                          // at the expansion joints
  JointSpec abutment;                       // girder end against the backwall
  std::optional<LawSpec> backfill;          // behind each backwall (compression-only)
  double backwall_mass = 0.0;               // [M], needed with backfill
  // Sliding bearings: the vertical link is then compression-only and carries this friction
  // (a friction pendulum with a radius), in parallel with `bearing` if that is given too.
  std::optional<FrictionSpec> bearing_friction;
  // 3-D: the bearing law's two horizontal directions coupled (a circular yield surface, one link
  // `.bearing`) or each on its own (`.bearing_x`, `.bearing_y`); none: coupled where the law has
  // a coupled form (links/coupled_shear.hpp) and there is no bearing_friction.
  std::optional<bool> bearing_coupled;
  // 3-D scenes: the deck's width and skew (the angle of its ends and of the supports' lines from
  // the transverse axis, positive counter-clockwise in plan) [deg]; pounding at `contact_points`
  // points along each deck end (2: its corners; 1: its centre); shear keys at the abutments.
  double deck_width = 0.0;
  std::optional<double> bearing_spacing;  // [L] across the deck; default half the deck's width
  double skew = 0.0;
  int contact_points = 2;
  std::optional<ShearKeySpec> shear_keys;
  // 3-D: the radius of the deck's centreline in plan [L], positive when it turns toward +y
  // (counter-clockwise seen from above); none: straight along x. Station s lies at
  // (R sin(s / R), R (1 - cos(s / R))), heading s / R from x.
  std::optional<double> plan_radius;
};

// What a run reports beyond links: drift of storeys and piers (peak of |u_top - u_bottom|
// along x, over the height; ductility against a yield drift), and joints (peak opening and
// closing of a link, and the girder's peak movement on its seat against the seat width).
// How the summary groups a drift monitor.
enum class DriftKind { storey, pier };

struct DriftMonitorSpec {
  std::string id;
  DriftKind kind = DriftKind::storey;
  std::string group;  // building or bridge id
  std::string bottom, top;
  double height = 0.0;
  std::optional<double> yield_drift;
  bool yields = true;  // as builder::DriftMonitor::yields
  // A plastic hinge's section, for the curvature ductility 1 + theta_p / (phi_y L_p) of the
  // member: its hinge link (theta_p its peak plastic rotation), phi_y and L_p.
  std::optional<std::string> hinge;
  std::optional<double> yield_curvature;       // [1/L]
  std::optional<double> plastic_hinge_length;  // [L]
  // A hinge that bends about two axes (a rotational link with a coupled `shear`): the tangent
  // t_1 or t_2 (1, 2) about which this drift bends it.
  std::optional<int> hinge_direction;
  // A shear link with a coupled `shear`: the tangent (1, 2) whose force is this drift's shear.
  std::optional<int> shear_link_direction;
  // What carries its shear: the member's lowest element (its end i forces: base shear V_i and,
  // for a beam, base moment M_i), or a link whose force is the storey shear.
  std::optional<std::string> base_element, shear_link;
  // With a base element: the member's elements above it (a storey's column cut where the other
  // building's floor strikes it between floors), whose shears |V_i| the peak shear takes too:
  // across the strike the column's shear changes by its force.
  std::vector<std::string> upper_elements;
  int direction = 0;  // the drift's: 0 x, 1 y (3-D scenes)
  // 3-D: a unit vector the drift is measured along instead (a curved bridge's local tangent).
  std::optional<std::array<double, 3>> axis;
  // 3-D: points of the top floor (from the top node, rigidly tied to it and to the bottom node:
  // a floor's plan corners) whose drift along `direction` the summary reports too, with the
  // storey's twist (theta_z of the top less the bottom's).
  std::vector<std::array<double, 3>> corners;
  // The monitor across this one whose drift yields together with this one's (a pier's two
  // drifts bending one hinge that yields on an ellipse), by id: generators only.
  std::optional<std::string> yields_with;
};
struct JointMonitorSpec {
  std::string id;
  std::string link;          // the pounding link across the joint
  std::string girder, seat;  // nodes: the girder end and what it sits on
  double seat_width = 0.0;   // 0: unseating not checked
  // 3-D: the point whose movement on the seat counts (from the girder node, rigidly tied to it
  // and to the seat: a skewed deck's corner) and the direction the seat's width is measured in
  // (across the support line); default the girder node and x.
  std::optional<std::array<double, 3>> point, direction;
};

// The time integrator and its parameters (integrators/integrator_catalog.hpp lists them).
using IntegratorSpec = integrators::IntegratorChoice;

struct AnalysisSpec {
  IntegratorSpec integrator;
  double time_step = 0.0;  // > 0
  // "time_step": "auto" (central difference): safety_factor times the stable limit, no more
  // than the shortest record step.
  bool time_step_auto = false;
  bool time_step_defaulted = false;       // "auto" because an explicit integrator was given no step
  bool time_step_is_record_step = false;  // "auto" capped at the shortest record step
  double safety_factor = 0.8;
  // Central difference's stable step with the links in contact (settle_time_step); none for
  // implicit integrators.
  std::optional<double> stable_time_step;
  double duration = 0.0;               // > 0; 0 in a file without it: the longest record's duration
  bool duration_from_records = false;  // none given: the records' (fit_analysis_to_records)
  double relative_tolerance = 1e-10;
  double absolute_tolerance = 0.0;
  int max_iterations = 25;
  int max_step_cuts = 10;
  long max_steps = 0;       // 0: no limit
  double time_limit = 0.0;  // wall-clock seconds, 0: no limit; set by `pound run --time-limit`
  std::optional<integrators::AdaptiveStepping> adaptive;  // implicit integrators only
  // "initial_state": "static": the run starts from static equilibrium under the loads at t = 0
  // (with the links), then moves with the initial velocities; default "unloaded" (u = 0).
  bool static_initial_state = false;
  // The steps of a fixed-step run, the last one perhaps shorter (time_step set).
  double step_count() const { return integrators::fixed_step_count(duration, time_step); }
  // The shortest and longest step the run takes (an adaptive run's bounds on its grid), and so
  // the fewest and most steps, at least one.
  double shortest_step() const { return adaptive ? adaptive->shortest(time_step) : time_step; }
  double longest_step() const { return adaptive ? adaptive->longest(time_step) : time_step; }
  double fewest_steps() const {
    return std::max(1.0, integrators::fixed_step_count(duration, longest_step()));
  }
  double most_steps() const {
    return std::max(1.0, integrators::fixed_step_count(duration, shortest_step()));
  }
  // What set the step, in the words of summary.json and `pound check --json`: "given", "auto"
  // (safety_factor x the stable step), "auto_record_step" (the shortest record step, shorter
  // than that) or "adaptive".
  const char* time_step_rule() const {
    if (adaptive) return "adaptive";
    if (!time_step_auto) return "given";
    return time_step_is_record_step ? "auto_record_step" : "auto";
  }
};

// What a run writes of its steps: "link" records force and penetration of the named links (all
// links when `ids` is empty); "node" records displacement, velocity, acceleration of nodes;
// "spectrum" the response spectra of nodes' absolute accelerations (floor spectra); "element"
// the end forces of elements (beams N, V, M at each end; trusses N).
enum class RecorderKind { link, node, spectrum, element };
// A node recorder's accelerations: relative to the ground (what the equations of motion carry),
// absolute (what contents and non-structural parts feel), or both.
enum class AccelerationFrame { both, relative, absolute };

// Which steps a history keeps: every k-th accepted step (counting the start as step 0), or the
// first step at or after each multiple of `interval` [T] (0: none given).
struct OutputSampling {
  int every = 1;
  double interval = 0.0;
};

struct RecorderSpec {
  RecorderKind type = RecorderKind::link;
  AccelerationFrame accelerations = AccelerationFrame::both;
  std::vector<std::string> ids;
  std::string file;  // output file name inside the output folder
  int every = 1;     // histories: OutputSampling
  std::optional<double> interval;
  // Link and node recorders: the envelope (max, min, the time of each, |max|) of each quantity
  // over every step, instead of the history.
  bool envelope = false;
  // Spectrum recorders: the oscillators' damping ratios and periods [T] (empty: 40 log-spaced
  // from 0.02 s to 10 s, model::default_spectrum_periods).
  std::vector<double> damping_ratios{0.05};
  std::vector<double> periods;
};

// "gravity": the weight of every mass as constant loads, and optionally P-Delta
// (model/model.hpp, Gravity).
enum class PDeltaKind { none, chord, consistent };
struct GravitySpec {
  std::vector<double> direction{0.0, -1.0};  // unit vector
  std::optional<double> acceleration;        // [L/T^2]; default: g in the model's units
  PDeltaKind p_delta = PDeltaKind::none;
};

struct ModelSpec {
  std::string source;  // file name, for error messages
  std::string title;
  int dimension = 1;  // 1, 2 or 3
  std::vector<NodeSpec> nodes;
  std::vector<MaterialSpec> materials;
  std::vector<ElementSpec> elements;
  std::vector<MassSpec> masses;
  std::vector<SupportSpec> supports;
  std::vector<ConstraintSpec> constraints;
  std::vector<InitialVelocitySpec> initial_velocities;
  std::vector<LoadSpec> loads;
  std::vector<LinkSpec> links;
  std::vector<RodPairSpec> rod_pairs;         // "generators" entries of type "rod_pair", in order
  std::vector<int> rod_pair_generator_index;  // their index in "/generators"
  std::vector<AdjacentBuildingsSpec> building_pairs;
  std::vector<GirderBridgeSpec> bridges;
  std::vector<BlockSpec> blocks;
  std::vector<SurfaceSpec> surfaces;
  std::vector<ContactSpec> contacts;
  // Named node sets from generators ("<block>.bottom" ...), filled by expand().
  std::map<std::string, std::vector<std::string>> node_sets;
  std::vector<DriftMonitorSpec> drift_monitors;
  std::vector<JointMonitorSpec> joint_monitors;
  UnitsSpec units;
  std::optional<DampingSpec> damping;
  std::optional<GravitySpec> gravity;
  std::vector<ExcitationSpec> excitations;
  AnalysisSpec analysis;
  std::vector<RecorderSpec> recorders;
  // Filled by expand(): for entries a generator, surface or contact appended, its JSON path
  // ("/generators/2", "/surfaces/0"; entry k of an array with u user entries came from
  // generated_from[k - u]).
  struct GeneratedFrom {
    std::vector<std::string> nodes, materials, elements, supports, initial_velocities, links, loads;
  } generated_from;
  // Without a "recorders" field `run` records every link; "recorders": [] records nothing.
  bool recorders_given = false;
};

}  // namespace pound::builder
