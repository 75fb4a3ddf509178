// 3-D scenes ("dimension": 3) from model files: 3-D beams and trusses, six-direction supports,
// masses and loads, checked through the whole chain (JSON -> builder -> assembly) against beam
// theory and statics; and 3-D input refused where it means nothing, with its JSON path.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "assembly/modal_analysis.hpp"
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "core/errors.hpp"
#include "io/model_reader.hpp"
#include "support/input_error.hpp"

namespace pound::builder {
namespace {

using nlohmann::json;

constexpr double kE = 2.0e11, kNu = 0.3, kG = kE / (2.0 * (1.0 + kNu));
constexpr double kArea = 0.01, kIy = 2.0e-5, kIz = 5.0e-5, kJ = 3.0e-5;

// A cantilever of `elements` beams from the origin along unit `axis` (length `length`),
// oriented by `orientation`, fixed at the origin, loaded at the tip.
json cantilever(const Eigen::Vector3d& axis, double length, int elements,
                const Eigen::Vector3d& orientation, const Eigen::Vector3d& force) {
  json model = {
      {"dimension", 3},
      {"materials",
       {{{"id", "steel"}, {"youngs_modulus", kE}, {"density", 7850.0}, {"poisson_ratio", kNu}}}},
      {"supports", {{{"node", "n0"}, {"fix", {"x", "y", "z", "rx", "ry", "rz"}}}}},
      {"analysis", {{"time_step", 0.001}, {"duration", 0.01}}}};
  for (int k = 0; k <= elements; ++k) {
    const Eigen::Vector3d at = axis * length * k / elements;
    model["nodes"].push_back(
        {{"id", fmt::format("n{}", k)}, {"x", at.x()}, {"y", at.y()}, {"z", at.z()}});
  }
  for (int k = 0; k < elements; ++k)
    model["elements"].push_back(
        {{"id", fmt::format("e{}", k)},
         {"type", "beam"},
         {"nodes", {fmt::format("n{}", k), fmt::format("n{}", k + 1)}},
         {"material", "steel"},
         {"area", kArea},
         {"inertia_y", kIy},
         {"inertia_z", kIz},
         {"torsion", kJ},
         {"orientation", {orientation.x(), orientation.y(), orientation.z()}}});
  model["loads"] = {{{"node", fmt::format("n{}", elements)},
                     {"x", force.x()},
                     {"y", force.y()},
                     {"z", force.z()}}};
  return model;
}

struct StaticSolution {
  model::DofMap dofs;
  Vector displacement;
};

// K u = f of the model's elements under its loads, plus `tip_moment` on the last node's rotations
// (model files have no nodal moments).
StaticSolution solve_static(const json& model, const Eigen::Vector3d& tip_moment = {0, 0, 0}) {
  const BuiltModel built = build(io::parse_model(model.dump(), "space.json"));
  const assembly::StructuralSystem system(built.model);
  Vector force = Vector::Zero(system.size());
  system.external_force(0.0, force);
  const Index tip = static_cast<Index>(built.model.nodes.size()) - 1;
  if (system.dofs().dofs_per_node() == 6)
    for (int axis = 0; axis < 3; ++axis)
      if (const Index row = system.dofs().own_equation(tip, 3 + axis); row >= 0)
        force[row] += tip_moment[axis];
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system.stiffness());
  return {system.dofs(), solver.solve(force)};
}

Eigen::Vector3d at_node(const StaticSolution& solution, Index node, int first_direction) {
  Eigen::Vector3d value;
  for (int k = 0; k < 3; ++k)
    value[k] = solution.displacement[solution.dofs.own_equation(node, first_direction + k)];
  return value;
}

// The local axes of a beam along `axis` with orientation vector v (OpenSees' vecxz).
struct LocalAxes {
  Eigen::Vector3d x, y, z;
};
LocalAxes local_axes(const Eigen::Vector3d& axis, const Eigen::Vector3d& orientation) {
  const Eigen::Vector3d y = orientation.cross(axis).normalized();
  return {axis, y, axis.cross(y)};
}

// A skew cantilever (its axis along (1, 2, 2) / 3, 4 elements) under a tip force along each local
// axis and a torque: the tip moves as beam theory says, P L^3 / (3 E I) across (cubic elements
// are exact at the nodes), P L / (E A) along, and twists T L / (G J).
TEST(SpaceScene, SkewCantileverDeflectsAndTwistsAsBeamTheorySays) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0;
  const Eigen::Vector3d orientation(0.0, 0.0, 1.0);
  const LocalAxes local = local_axes(axis, orientation);
  const double length = 6.0, load = 1000.0, torque = 500.0;
  struct Case {
    const char* name;
    Eigen::Vector3d force, moment;
    double expected_along_y, expected_along_z, expected_axial, expected_twist;
  };
  const double l3 = length * length * length;
  const Case cases[] = {
      {"force along y'", load * local.y, {0, 0, 0}, load * l3 / (3 * kE * kIz), 0, 0, 0},
      {"force along z'", load * local.z, {0, 0, 0}, 0, load * l3 / (3 * kE * kIy), 0, 0},
      {"force along x'", load * local.x, {0, 0, 0}, 0, 0, load * length / (kE * kArea), 0},
      {"torque about x'", {0, 0, 0}, torque * local.x, 0, 0, 0, torque * length / (kG * kJ)},
  };
  for (const Case& c : cases) {
    const StaticSolution solution =
        solve_static(cantilever(axis, length, 4, orientation, c.force), c.moment);
    const Eigen::Vector3d u = at_node(solution, 4, 0), theta = at_node(solution, 4, 3);
    const double scale = std::max({std::abs(c.expected_along_y), std::abs(c.expected_along_z),
                                   std::abs(c.expected_axial), std::abs(c.expected_twist)});
    const double error = std::max({std::abs(u.dot(local.y) - c.expected_along_y),
                                   std::abs(u.dot(local.z) - c.expected_along_z),
                                   std::abs(u.dot(local.x) - c.expected_axial),
                                   std::abs(theta.dot(local.x) - c.expected_twist)}) /
                         scale;
    std::printf("  %-16s tip error %.2e of %.4g\n", c.name, error, scale);
    EXPECT_LT(error, 1e-9) << c.name;
  }
  // The tip rotation under the force along y' turns about z' by P L^2 / (2 E I_z).
  const StaticSolution bent =
      solve_static(cantilever(axis, length, 4, orientation, load * local.y));
  const double rotation = at_node(bent, 4, 3).dot(local.z);
  const double expected = load * length * length / (2 * kE * kIz);
  std::printf("  tip rotation about z' error %.2e\n", std::abs(rotation / expected - 1.0));
  EXPECT_NEAR(rotation / expected, 1.0, 1e-9);
}

// A rigid offset at the fixed end: only the flexible part bends, P (L - o)^3 / (3 E I_z).
TEST(SpaceScene, RigidEndOffsetShortensTheFlexibleLength) {
  const double length = 5.0, offset = 1.0, load = 2000.0;
  json model = cantilever({1, 0, 0}, length, 1, {0, 0, 1}, {0, load, 0});
  model["elements"][0]["rigid_offsets"] = {{offset, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  const StaticSolution solution = solve_static(model);
  const double flexible = length - offset;
  const double expected = load * flexible * flexible * flexible / (3 * kE * kIz);
  const double tip = at_node(solution, 1, 0).y();
  std::printf("  offset cantilever tip error %.2e\n", std::abs(tip / expected - 1.0));
  EXPECT_NEAR(tip / expected, 1.0, 1e-12);
}

// A tripod of three bars meeting above the ground carries a vertical load P equally: each bar's
// force is P / (3 cos a) (a its angle from the vertical), and the apex sinks P / (3 k cos^2 a)
// with k = E A / L. Checks the 3-D truss and the three-direction supports.
TEST(SpaceScene, TripodSharesAVerticalLoadAsStaticsSays) {
  const double height = 4.0, radius = 3.0, load = 1.0e5;
  json model = {{"dimension", 3},
                {"materials", {{{"id", "steel"}, {"youngs_modulus", kE}, {"density", 0.0}}}},
                {"nodes", {{{"id", "apex"}, {"x", 0.0}, {"y", 0.0}, {"z", height}}}},
                {"loads", {{{"node", "apex"}, {"z", -load}}}},
                {"analysis", {{"time_step", 0.001}, {"duration", 0.01}}}};
  // The apex must come last (solve_static reads the last node).
  json feet = json::array();
  for (int k = 0; k < 3; ++k) {
    const double angle = 2.0 * M_PI * k / 3.0;
    const std::string id = fmt::format("foot{}", k);
    feet.push_back(
        {{"id", id}, {"x", radius * std::cos(angle)}, {"y", radius * std::sin(angle)}, {"z", 0.0}});
    model["elements"].push_back({{"id", fmt::format("bar{}", k)},
                                 {"type", "truss"},
                                 {"nodes", {id, "apex"}},
                                 {"material", "steel"},
                                 {"area", kArea}});
    model["supports"].push_back({{"node", id}, {"fix", {"x", "y", "z"}}});
  }
  feet.push_back(model["nodes"][0]);
  model["nodes"] = feet;
  const BuiltModel built = build(io::parse_model(model.dump(), "tripod.json"));
  EXPECT_EQ(built.model.dofs_per_node(), 3);
  const StaticSolution solution = solve_static(model);
  const double bar = std::hypot(height, radius), cosine = height / bar;
  const double expected = load / (3.0 * (kE * kArea / bar) * cosine * cosine);
  const Eigen::Vector3d apex = at_node(solution, 3, 0);
  std::printf("  tripod apex error %.2e, sideways %.1e\n", std::abs(-apex.z() / expected - 1.0),
              apex.head<2>().norm());
  EXPECT_NEAR(-apex.z() / expected, 1.0, 1e-12);
  EXPECT_LT(apex.head<2>().norm(), 1e-12 * expected);
}

// A nodal mass acts along x, y and z; its rotary inertia [I_x, I_y, I_z] on the three rotations.
TEST(SpaceScene, NodalMassAndRotaryInertiaFillTheirDirections) {
  json model = cantilever({1, 0, 0}, 2.0, 1, {0, 0, 1}, {0, 0, 0});
  model["materials"][0]["density"] = 0.0;
  model["masses"] = {{{"node", "n1"}, {"mass", 7.0}, {"rotary_inertia", {1.0, 2.0, 3.0}}}};
  const BuiltModel built = build(io::parse_model(model.dump(), "mass.json"));
  const assembly::StructuralSystem system(built.model);
  const Vector& mass = *system.lumped_mass();
  const double expected[6] = {7.0, 7.0, 7.0, 1.0, 2.0, 3.0};
  for (int d = 0; d < 6; ++d) EXPECT_EQ(mass[system.dofs().own_equation(1, d)], expected[d]) << d;
  // One number is the same about every axis.
  model["masses"][0]["rotary_inertia"] = 4.0;
  const BuiltModel same = build(io::parse_model(model.dump(), "mass.json"));
  EXPECT_EQ(same.model.masses[0].rotary_inertia, (model::Coordinates{4.0, 4.0, 4.0}));
}

// A one-storey building whose floor is rigid in its plane: one node at the centre of mass (mass
// m, rotary inertia J about z) with z, rx and ry held, so it carries three DOFs, and four columns
// reaching it through rigid offsets from the centre to their tops (a rigid diaphragm, as SAP2000
// users model one with rigid links). The columns on the right are stiffer, so the stiffness
// centre sits e_x from the centre of mass: x sways alone, y and the twist couple. The plan model's
// closed form (Chopra, "Dynamics of Structures", 9.5): K_x = K_y = sum k, K_y0 = sum k x_i,
// K_00 = sum k (x_i^2 + y_i^2) + sum G J / h, with k = 12 E I / h^3 of a column fixed at both
// ends; w_x^2 = K_x / m and, for y and the twist,
// w^2 = (K_y / m + K_00 / J) / 2 -/+ sqrt((K_y / m - K_00 / J)^2 / 4 + K_y0^2 / (m J)).
TEST(SpaceScene, EccentricOneStoreyFloorHasThePlanModelsModes) {
  const double height = 3.5, half_length = 6.0, half_width = 4.0;
  const double mass = 4.0e5, inertia_left = 2.0e-3, inertia_right = 6.0e-3;
  const double polar = mass * (4 * half_length * half_length + 4 * half_width * half_width) / 12.0;
  json model = {
      {"dimension", 3},
      {"materials",
       {{{"id", "c"}, {"youngs_modulus", kE}, {"density", 0.0}, {"poisson_ratio", kNu}}}},
      {"nodes", {{{"id", "floor"}, {"x", 0.0}, {"y", 0.0}, {"z", height}}}},
      {"masses", {{{"node", "floor"}, {"mass", mass}, {"rotary_inertia", {0.0, 0.0, polar}}}}},
      {"supports", {{{"node", "floor"}, {"fix", {"z", "rx", "ry"}}}}},
      {"analysis", {{"time_step", 0.01}, {"duration", 0.1}}}};
  double k_sum = 0.0, k_x = 0.0, k_polar = 0.0;
  for (int c = 0; c < 4; ++c) {
    const double x = c < 2 ? -half_length : half_length, y = c % 2 == 0 ? -half_width : half_width;
    const double inertia = c < 2 ? inertia_left : inertia_right, torsion = 2.0 * inertia;
    const std::string base = fmt::format("base{}", c);
    model["nodes"].push_back({{"id", base}, {"x", x}, {"y", y}, {"z", 0.0}});
    model["supports"].push_back({{"node", base}, {"fix", {"x", "y", "z", "rx", "ry", "rz"}}});
    model["elements"].push_back({{"id", fmt::format("column{}", c)},
                                 {"type", "beam"},
                                 {"nodes", {base, "floor"}},
                                 {"material", "c"},
                                 {"area", 0.16},
                                 {"inertia_y", inertia},
                                 {"inertia_z", inertia},
                                 {"torsion", torsion},
                                 {"orientation", {1.0, 0.0, 0.0}},
                                 {"rigid_offsets", {{0.0, 0.0, 0.0}, {x, y, 0.0}}}});
    const double k = 12.0 * kE * inertia / (height * height * height);
    k_sum += k;
    k_x += k * x;
    k_polar += k * (x * x + y * y) + kG * torsion / height;
  }
  const BuiltModel built = build(io::parse_model(model.dump(), "storey.json"));
  const assembly::StructuralSystem system(built.model);
  EXPECT_EQ(system.size(), 3);  // x, y and the twist of the floor
  const Vector omega_squared = assembly::modal_analysis(system).omega_squared;
  const double mean = (k_sum / mass + k_polar / polar) / 2.0;
  const double split =
      std::sqrt(std::pow((k_sum / mass - k_polar / polar) / 2.0, 2) + k_x * k_x / (mass * polar));
  std::array<double, 3> expected{k_sum / mass, mean - split, mean + split};
  std::sort(expected.begin(), expected.end());
  double worst = 0.0;
  for (int k = 0; k < 3; ++k)
    worst = std::max(worst, std::abs(omega_squared[k] / expected[static_cast<std::size_t>(k)] - 1));
  std::printf("  periods %.5f %.5f %.5f s (eccentricity %.3f m): largest error %.2e\n",
              2 * M_PI / std::sqrt(expected[2]), 2 * M_PI / std::sqrt(expected[1]),
              2 * M_PI / std::sqrt(expected[0]), k_x / k_sum, worst);
  EXPECT_LT(worst, 1e-10);
}

std::optional<InputError> error_of(const json& model) {
  try {
    (void)build(io::parse_model(model.dump(), "space.json"));
  } catch (const InputError& error) {
    return error;
  }
  return std::nullopt;
}

void expect_refused(const json& model, const std::string& where, const std::string& phrase) {
  testing::expect_input_error([&] { (void)build(io::parse_model(model.dump(), "space.json")); },
                              where, phrase);
}

// 3-D input that means nothing is refused where it stands.
TEST(SpaceScene, MeaninglessSpaceInputIsRefusedWithItsPath) {
  const json good = cantilever({1, 0, 0}, 2.0, 1, {0, 0, 1}, {0, 1, 0});
  ASSERT_FALSE(error_of(good));

  json parallel = good;
  parallel["elements"][0]["orientation"] = {2.0, 0.0, 0.0};
  expect_refused(parallel, "/elements/0/orientation", "parallel to the beam");
  json huge_orientation = good;  // only its direction counts: no overflow
  huge_orientation["elements"][0]["orientation"] = {0.0, 1e308, 1e308};
  EXPECT_FALSE(error_of(huge_orientation));
  json zero = good;
  zero["elements"][0]["orientation"] = {0.0, 0.0, 0.0};
  expect_refused(zero, "/elements/0/orientation", "must not be the zero vector");
  json no_orientation = good;
  no_orientation["elements"][0].erase("orientation");
  expect_refused(no_orientation, "/elements/0/orientation", "required");
  // A missing section constant is missing, not a typo of its sibling (inertia_z is a field too).
  json no_inertia_y = good;
  no_inertia_y["elements"][0].erase("inertia_y");
  expect_refused(no_inertia_y, "/elements/0/inertia_y", "required field is missing");
  json plane_inertia = good;
  plane_inertia["elements"][0]["inertia"] = 1e-5;
  expect_refused(plane_inertia, "/elements/0/inertia", "only allowed when dimension is 2");
  json no_shear = good;
  no_shear["materials"][0].erase("poisson_ratio");
  expect_refused(no_shear, "/elements/0/material", "'shear_modulus'");
  json meeting_ends = good;
  meeting_ends["elements"][0]["rigid_offsets"] = {{1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}};
  expect_refused(meeting_ends, "/elements/0/rigid_offsets", "coincide");

  json plane = good;
  plane["dimension"] = 2;
  for (json& node : plane["nodes"]) node.erase("z");
  plane["elements"][0] = {{"id", "e0"},          {"type", "beam"}, {"nodes", {"n0", "n1"}},
                          {"material", "steel"}, {"area", kArea},  {"inertia", kIz}};
  plane["supports"][0]["fix"] = {"x", "y", "rz"};
  plane["loads"][0].erase("z");
  ASSERT_FALSE(error_of(plane));
  json plane_z = plane;
  plane_z["nodes"][1]["z"] = 1.0;
  expect_refused(plane_z, "/nodes/1/z", "only allowed when dimension is 3");
  json plane_rx = plane;
  plane_rx["supports"][0]["fix"] = {"x", "rx"};
  expect_refused(plane_rx, "/supports/0/fix/1", "only allowed when dimension is 3");
  json plane_orientation = plane;
  plane_orientation["elements"][0]["orientation"] = {0.0, 0.0, 1.0};
  expect_refused(plane_orientation, "/elements/0/orientation", "only allowed when dimension is 3");

  json link = good;
  link["masses"] = {{{"node", "n1"}, {"mass", 1.0}}};
  link["nodes"].push_back({{"id", "wall"}, {"x", 2.1}, {"y", 0.0}, {"z", 0.0}});
  link["supports"].push_back({{"node", "wall"}, {"fix", {"x", "y", "z"}}});
  link["links"] = {{{"id", "hit"},
                    {"nodes", {"n1", "wall"}},
                    {"gap", 0.1},
                    {"law", {{"type", "gap_spring"}, {"stiffness", 1e9}}}}};
  ASSERT_FALSE(error_of(link));
  json friction = link;
  friction["links"][0]["friction"] = {{"coefficient", 0.3}};
  ASSERT_FALSE(error_of(friction));  // a penalty law rubs in the contact plane
  json hard_friction = friction;
  hard_friction["links"][0]["law"] = {{"type", "hard_contact"}, {"restitution", 0.5}};
  ASSERT_FALSE(error_of(hard_friction));  // a constraint in the contact plane (issue 17)
  hard_friction["links"][0]["friction"]["stick_stiffness"] = 1e6;
  expect_refused(hard_friction, "/links/0/friction/stick_stiffness", "no stick penalty");
  json hinge = link;
  hinge["links"][0] = {{"id", "hinge"},
                       {"nodes", {"n0", "n1"}},
                       {"dof", "rotation"},
                       {"law", {{"type", "elastic_spring"}, {"stiffness", 1e6}}}};
  expect_refused(hinge, "/links/0/dof", "needs the \"axis\" it turns about");
  hinge["links"][0]["axis"] = {0.0, 0.0, 1.0};
  EXPECT_FALSE(error_of(hinge));
  json turning_friction = hinge;
  turning_friction["links"][0]["law"] = {{"type", "gap_spring"}, {"stiffness", 1e6}};
  turning_friction["links"][0]["friction"] = {{"coefficient", 0.3}};
  expect_refused(turning_friction, "/links/0/friction", "no contact plane");
  json offset = link;
  offset["links"][0]["rigid_offsets"] = {{0.0, 0.5, 0.0}, {0.0, 0.5, 0.0}};
  ASSERT_FALSE(error_of(offset));
  offset["links"][0]["rigid_offsets"][1] = {0.0, 0.5};
  expect_refused(offset, "/links/0/rigid_offsets/1", "expected exactly 3 elements");
  json turning_offset = hinge;
  turning_offset["links"][0]["rigid_offsets"] = {{0.0, 0.5, 0.0}, {0.0, 0.0, 0.0}};
  expect_refused(turning_offset, "/links/0/rigid_offsets", "rotational link");
}

}  // namespace
}  // namespace pound::builder
