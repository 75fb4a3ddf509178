// Master–slave constraints from model files (rigid diaphragms, rigid beams and bars, equal DOFs),
// through the whole chain (JSON -> builder -> DOF map -> assembly): a floor of several nodes
// against its plan model's closed form, rigid links against statics, equal DOFs against a
// portal's sway, and ties that mean nothing refused with their paths.
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

BuiltModel built_from(const json& model) {
  return build(io::parse_model(model.dump(), "constraints.json"));
}

// The plan model of a one-storey floor (Chopra, "Dynamics of Structures", 9.5): K_x = K_y = sum
// k, K_y0 = sum k x_i, K_00 = sum k (x_i^2 + y_i^2) + sum G J / h; w_x^2 = K_x / m and, for y and
// the twist, w^2 = (K_y / m + K_00 / J) / 2 -/+ sqrt((K_y / m - K_00 / J)^2 / 4 + K_y0^2 / (m J)).
struct PlanModel {
  double k_sum = 0.0, k_x = 0.0, k_polar = 0.0, mass = 0.0, polar = 0.0;
  std::array<double, 3> omega_squared() const {
    const double mean = (k_sum / mass + k_polar / polar) / 2.0;
    const double split =
        std::sqrt(std::pow((k_sum / mass - k_polar / polar) / 2.0, 2) + k_x * k_x / (mass * polar));
    std::array<double, 3> values{k_sum / mass, mean - split, mean + split};
    std::sort(values.begin(), values.end());
    return values;
  }
};

struct Storey {
  json model;
  PlanModel plan;
};

// An eccentric one-storey building (the stiffer columns on the right) whose floor is its four
// column tops, tied by a rigid diaphragm to the centre-of-mass node, which carries the mass and
// the polar inertia and holds z, rx, ry. With `held_tops` the tops hold z, rx and ry too: each
// column is fixed at both ends (k = 12 E I / h^3), as a floor reached through rigid offsets; else
// the tops turn freely (cantilevers, k = 3 E I / h^3) and keep their own vertical DOF.
Storey diaphragm_storey(bool held_tops) {
  const double height = 3.5, half_length = 6.0, half_width = 4.0;
  Storey storey;
  PlanModel& plan = storey.plan;
  plan.mass = 4.0e5;
  plan.polar = plan.mass * (4 * half_length * half_length + 4 * half_width * half_width) / 12.0;
  json& model = storey.model;
  model = {{"dimension", 3},
           {"materials",
            {{{"id", "c"}, {"youngs_modulus", kE}, {"density", 0.0}, {"poisson_ratio", kNu}}}},
           {"nodes", {{{"id", "floor"}, {"x", 0.0}, {"y", 0.0}, {"z", height}}}},
           {"masses",
            {{{"node", "floor"}, {"mass", plan.mass}, {"rotary_inertia", {0.0, 0.0, plan.polar}}}}},
           {"supports", {{{"node", "floor"}, {"fix", {"z", "rx", "ry"}}}}},
           {"constraints",
            {{{"type", "rigid_diaphragm"}, {"master", "floor"}, {"slaves", json::array()}}}},
           {"analysis", {{"time_step", 0.01}, {"duration", 0.1}}}};
  for (int c = 0; c < 4; ++c) {
    const double x = c < 2 ? -half_length : half_length, y = c % 2 == 0 ? -half_width : half_width;
    const double inertia = c < 2 ? 2.0e-3 : 6.0e-3, torsion = 2.0 * inertia;
    const std::string base = fmt::format("base{}", c), top = fmt::format("top{}", c);
    model["nodes"].push_back({{"id", base}, {"x", x}, {"y", y}, {"z", 0.0}});
    model["nodes"].push_back({{"id", top}, {"x", x}, {"y", y}, {"z", height}});
    model["supports"].push_back({{"node", base}, {"fix", {"x", "y", "z", "rx", "ry", "rz"}}});
    if (held_tops) model["supports"].push_back({{"node", top}, {"fix", {"z", "rx", "ry"}}});
    model["constraints"][0]["slaves"].push_back(top);
    model["elements"].push_back({{"id", fmt::format("column{}", c)},
                                 {"type", "beam"},
                                 {"nodes", {base, top}},
                                 {"material", "c"},
                                 {"area", 0.16},
                                 {"inertia_y", inertia},
                                 {"inertia_z", inertia},
                                 {"torsion", torsion},
                                 {"orientation", {1.0, 0.0, 0.0}}});
    const double k = (held_tops ? 12.0 : 3.0) * kE * inertia / (height * height * height);
    plan.k_sum += k;
    plan.k_x += k * x;
    plan.k_polar += k * (x * x + y * y) + kG * torsion / height;
  }
  return storey;
}

double worst_mode_error(const assembly::StructuralSystem& system, const PlanModel& plan) {
  const Vector omega_squared = assembly::modal_analysis(system).omega_squared;
  const std::array<double, 3> expected = plan.omega_squared();
  EXPECT_EQ(omega_squared.size(), 3);
  double worst = 0.0;
  for (int k = 0; k < std::min<int>(3, static_cast<int>(omega_squared.size())); ++k)
    worst = std::max(worst, std::abs(omega_squared[k] / expected[static_cast<std::size_t>(k)] - 1));
  return worst;
}

// Four column tops tied by a rigid diaphragm move as the plan model's floor: x sways alone, y and
// the twist couple through the eccentricity, each to the closed form. Held tops leave only the
// floor's three DOFs; free ones keep each top's z, rx and ry (massless, condensed by the modes).
TEST(Constraints, AFloorOfFourNodesTiedByARigidDiaphragmHasThePlanModelsModes) {
  for (const bool held_tops : {true, false}) {
    const Storey storey = diaphragm_storey(held_tops);
    const BuiltModel built = built_from(storey.model);
    const assembly::StructuralSystem system(built.model);
    EXPECT_EQ(system.size(), held_tops ? 3 : 15);
    EXPECT_TRUE(system.dofs().has_ties());
    const double worst = worst_mode_error(system, storey.plan);
    std::printf("  %s tops: eccentricity %.3f m, largest error of w^2 %.2e\n",
                held_tops ? "held" : "free", storey.plan.k_x / storey.plan.k_sum, worst);
    EXPECT_LT(worst, 1e-10);
  }
}

// A slave's masses join its master's through the lever arm: four quarter masses at the corners
// of an a x b floor are the floor's mass m and polar inertia m (a^2 + b^2) / 4 about its centre
// (the corners' own), coupled to x and y where the centre is off the master.
TEST(Constraints, MassesOnTiedCornersAreTheFloorsMassAndPolarInertia) {
  Storey storey = diaphragm_storey(true);
  json& model = storey.model;
  const double quarter = storey.plan.mass / 4.0;
  model["masses"] = json::array();
  for (int c = 0; c < 4; ++c)
    model["masses"].push_back({{"node", fmt::format("top{}", c)}, {"mass", quarter}});
  // The master 1 m off the centre along x: M gains the coupling m e between y and the twist.
  model["nodes"][0]["x"] = 1.0;
  const BuiltModel built = built_from(model);
  const assembly::StructuralSystem system(built.model);
  EXPECT_EQ(system.lumped_mass(), nullptr);  // coupled: the consistent path
  const Matrix mass(system.mass_matrix());
  const model::DofMap& dofs = system.dofs();
  const Index x = dofs.own_equation(0, 0), y = dofs.own_equation(0, 1),
              turn = dofs.own_equation(0, 5);
  const double m = storey.plan.mass, e = -1.0;  // the centre from the master
  const double polar = m * (6.0 * 6.0 + 4.0 * 4.0) + m * e * e;
  const double errors[] = {mass(x, x) / m - 1, mass(y, y) / m - 1, mass(turn, turn) / polar - 1,
                           mass(y, turn) / (m * e) - 1, mass(x, turn) / m};
  double worst = 0.0;
  for (double error : errors) worst = std::max(worst, std::abs(error));
  std::printf("  M of the tied floor against m, m e, m (a^2 + b^2) / 4 + m e^2: largest %.2e\n",
              worst);
  EXPECT_LT(worst, 1e-14);
}

// A cantilever along x (length L) with a point n2 a from its tip along y, tied to the tip:
// pushed at n2 along z, a rigid beam twists the cantilever by the torque a F (n2 rises by
// F L^3 / (3 E I_y) + a^2 F L / (G J)); a rigid bar passes the force alone (no twist).
TEST(Constraints, RigidBeamsAndBarsCarryAnOffsetLoadAsStaticsSays) {
  const double length = 2.0, arm = 0.5, force = 1.0e3, area = 0.01, iy = 2.0e-5, iz = 5.0e-5,
               torsion = 3.0e-5;
  for (const std::string type : {"rigid_beam", "rigid_bar"}) {
    const json model = {
        {"dimension", 3},
        {"materials",
         {{{"id", "s"}, {"youngs_modulus", kE}, {"density", 0.0}, {"poisson_ratio", kNu}}}},
        {"nodes",
         {{{"id", "n0"}, {"x", 0.0}, {"y", 0.0}, {"z", 0.0}},
          {{"id", "n1"}, {"x", length}, {"y", 0.0}, {"z", 0.0}},
          {{"id", "n2"}, {"x", length}, {"y", arm}, {"z", 0.0}}}},
        {"elements",
         {{{"id", "e"},
           {"type", "beam"},
           {"nodes", {"n0", "n1"}},
           {"material", "s"},
           {"area", area},
           {"inertia_y", iy},
           {"inertia_z", iz},
           {"torsion", torsion},
           {"orientation", {0.0, 0.0, 1.0}}}}},
        {"supports", {{{"node", "n0"}, {"fix", {"x", "y", "z", "rx", "ry", "rz"}}}}},
        {"constraints", {{{"type", type}, {"master", "n1"}, {"slaves", {"n2"}}}}},
        {"loads", {{{"node", "n2"}, {"z", force}}}},
        {"analysis", {{"time_step", 0.01}, {"duration", 0.1}}}};
    const BuiltModel built = built_from(model);
    const assembly::StructuralSystem system(built.model);
    EXPECT_EQ(system.size(), 6);  // the tip's: n2 adds nothing
    Vector load;
    system.external_force(0.0, load);
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system.stiffness());
    const Vector u = solver.solve(load);
    const double bending = force * std::pow(length, 3) / (3.0 * kE * iy);
    const double twist = type == "rigid_beam" ? arm * force * length / (kG * torsion) : 0.0;
    const double rise = model::value_of(system.dofs().terms(2, 2), u);
    const double tip_twist = model::value_of(system.dofs().terms(1, 3), u);
    const double rise_error = std::abs(rise / (bending + arm * twist) - 1);
    const double twist_error = std::abs(tip_twist - twist) / std::max(twist, 1e-300);
    std::printf("  %s: n2 rises %.6e (error %.1e), the tip twists %.6e (error %.1e)\n",
                type.c_str(), rise, rise_error, tip_twist,
                type == "rigid_beam" ? twist_error : 0.0);
    EXPECT_LT(rise_error, 1e-12);
    if (type == "rigid_beam")
      EXPECT_LT(twist_error, 1e-12);
    else
      EXPECT_EQ(tip_twist, 0.0);
  }
}

// Equal DOFs along x tie a plane portal's two column tops (cantilevers of different stiffness and
// top mass): they sway together at w^2 = (k_1 + k_2) / (m_1 + m_2), k = 3 E I / h^3, and the mass
// stays diagonal, so central difference takes the model (once the tops' rotations have inertia).
TEST(Constraints, EqualDofsTieAPortalsColumnTopsIntoOneSway) {
  const double height = 3.0, i1 = 1.0e-4, i2 = 3.0e-4, m1 = 2.0e4, m2 = 5.0e4;
  const json model = {
      {"dimension", 2},
      {"materials", {{{"id", "s"}, {"youngs_modulus", kE}, {"density", 0.0}}}},
      {"nodes",
       {{{"id", "b1"}, {"x", 0.0}, {"y", 0.0}},
        {{"id", "t1"}, {"x", 0.0}, {"y", height}},
        {{"id", "b2"}, {"x", 6.0}, {"y", 0.0}},
        {{"id", "t2"}, {"x", 6.0}, {"y", height}}}},
      {"elements",
       {{{"id", "c1"},
         {"type", "beam"},
         {"nodes", {"b1", "t1"}},
         {"material", "s"},
         {"area", 0.02},
         {"inertia", i1}},
        {{"id", "c2"},
         {"type", "beam"},
         {"nodes", {"b2", "t2"}},
         {"material", "s"},
         {"area", 0.02},
         {"inertia", i2}}}},
      {"masses", {{{"node", "t1"}, {"mass", m1}}, {{"node", "t2"}, {"mass", m2}}}},
      {"supports",
       {{{"node", "b1"}, {"fix", {"x", "y", "rz"}}}, {{"node", "b2"}, {"fix", {"x", "y", "rz"}}}}},
      {"constraints",
       {{{"type", "equal_dofs"}, {"master", "t1"}, {"slaves", {"t2"}}, {"dofs", {"x"}}}}},
      {"analysis", {{"time_step", 0.01}, {"duration", 0.1}}}};
  const BuiltModel built = built_from(model);
  const assembly::StructuralSystem system(built.model);
  EXPECT_NE(system.lumped_mass(), nullptr);
  const Vector omega_squared = assembly::modal_analysis(system).omega_squared;
  const double expected = 3.0 * kE * (i1 + i2) / std::pow(height, 3) / (m1 + m2);
  const double error = std::abs(omega_squared[0] / expected - 1);
  std::printf("  sway w^2 %.6e against %.6e: error %.1e\n", omega_squared[0], expected, error);
  EXPECT_LT(error, 1e-12);

  json explicit_model = model;
  explicit_model["analysis"] = {
      {"integrator", "central_difference"}, {"time_step", "auto"}, {"duration", 0.1}};
  for (json& mass : explicit_model["masses"]) mass["rotary_inertia"] = 1.0;
  BuiltModel explicit_built = built_from(explicit_model);
  assembly::StructuralSystem explicit_system(explicit_built.model);
  EXPECT_NO_THROW(settle_time_step(explicit_built.analysis, explicit_built.model, explicit_system,
                                   "constraints.json"));
}

void expect_refused(const json& model, const std::string& where, const std::string& phrase) {
  testing::expect_input_error([&] { (void)built_from(model); }, where, phrase);
}

// Ties that mean nothing are refused where they stand.
TEST(Constraints, TiesThatMeanNothingAreRefusedWithTheirPaths) {
  const json good = diaphragm_storey(true).model;
  ASSERT_NO_THROW(built_from(good));
  json unknown = good;
  unknown["constraints"][0]["slaves"][1] = "top9";
  expect_refused(unknown, "/constraints/0/slaves/1", "'top9'");
  json itself = good;
  itself["constraints"][0]["slaves"][0] = "floor";
  expect_refused(itself, "/constraints/0/slaves/0", "is the master");
  json twice = good;
  twice["constraints"].push_back(
      {{"type", "rigid_beam"}, {"master", "base0"}, {"slaves", {"top2"}}});
  expect_refused(twice, "/constraints/1/slaves/0", "already tied at /constraints/0/slaves/2");
  json chain = good;
  chain["constraints"].push_back(
      {{"type", "equal_dofs"}, {"master", "top1"}, {"slaves", {"base3"}}, {"dofs", {"x"}}});
  expect_refused(chain, "/constraints/0/slaves/1", "is the master of /constraints/1");
  json held_slave = good;
  held_slave["supports"][2]["fix"] = {"x", "z"};  // top0 along x, which the floor ties
  expect_refused(held_slave, "/supports/2/fix", "moves with its master");
  json held_master = good;
  held_master["supports"][0]["fix"] = {"z", "rz"};
  expect_refused(held_master, "/supports/0/fix", "is the master of /constraints/0");
  json off_plane = good;
  off_plane["nodes"][2]["z"] = 3.6;  // top0
  expect_refused(off_plane, "/constraints/0/slaves/0", "off the diaphragm's plane");
  json far = good;
  far["nodes"][0]["x"] = -1e308;  // the floor node, and column0 (base0, top0) at the other end
  far["nodes"][1]["x"] = 1e308;
  far["nodes"][2]["x"] = 1e308;
  expect_refused(far, "/constraints/0/slaves/0", "lever arm overflows");
  json moving = good;
  moving["initial_velocities"] = {{{"node", "top1"}, {"y", 0.1}}};
  expect_refused(moving, "/constraints/0", "give the master's velocity");
  json no_dofs = good;
  no_dofs["constraints"][0]["type"] = "equal_dofs";
  expect_refused(no_dofs, "/constraints/0/dofs", "required");
  json normal_of_beam = good;
  normal_of_beam["constraints"][0]["type"] = "rigid_beam";
  normal_of_beam["constraints"][0]["normal"] = "z";
  expect_refused(normal_of_beam, "/constraints/0/normal", "unknown field");

  json plane = {
      {"dimension", 2},
      {"nodes", {{{"id", "a"}, {"x", 0.0}}, {{"id", "b"}, {"x", 1.0}}}},
      {"masses", {{{"node", "a"}, {"mass", 1.0}}, {{"node", "b"}, {"mass", 1.0}}}},
      {"constraints", {{{"type", "rigid_diaphragm"}, {"master", "a"}, {"slaves", {"b"}}}}},
      {"analysis", {{"time_step", 0.01}, {"duration", 0.1}}}};
  expect_refused(plane, "/constraints/0/type", "needs a 3-D scene");
  json line = plane;
  line["dimension"] = 1;
  line["constraints"][0]["type"] = "rigid_beam";
  expect_refused(line, "/constraints/0/type", "needs a 2-D or 3-D scene");
}

// Central difference divides by each DOF's own mass; a tie with a lever arm couples the masses,
// and the model is refused with a way out.
TEST(Constraints, CentralDifferenceRefusesMassesCoupledByALeverArm) {
  json model = diaphragm_storey(true).model;
  model["analysis"] = {
      {"integrator", "central_difference"}, {"time_step", 1e-4}, {"duration", 0.1}};
  for (int c = 0; c < 4; ++c)
    model["masses"].push_back({{"node", fmt::format("top{}", c)}, {"mass", 10.0}});
  BuiltModel built = built_from(model);
  assembly::StructuralSystem system(built.model);
  testing::expect_input_error(
      [&] { settle_time_step(built.analysis, built.model, system, "constraints.json"); },
      "/analysis/integrator", "constraints couple it");
}

}  // namespace
}  // namespace pound::builder
