// Static equilibrium with a contact link against the hand solution: a mass on a spring k = 100,
// pushed by a load towards a wall 0.05 away behind a gap spring of 300, or a hard contact; a
// block on a rough floor (hard contact with friction) pushed sideways; a block on a belt.
#include "assembly/static_equilibrium.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "builder/build.hpp"
#include "core/errors.hpp"
#include "io/model_reader.hpp"
#include "links/hard_contact.hpp"

namespace pound::assembly {
namespace {

StructuralSystem system_under(
    double load, const std::string& law = R"({"type": "gap_spring", "stiffness": 300})") {
  return StructuralSystem(builder::build(io::parse_model(fmt::format(R"({{
    "nodes": [{{"id": "ground", "x": 0}}, {{"id": "m", "x": 1}}, {{"id": "wall", "x": 2}}],
    "materials": [{{"id": "k", "youngs_modulus": 100, "density": 0}}],
    "elements": [{{"id": "k", "type": "truss", "nodes": ["ground", "m"], "material": "k", "area": 1}}],
    "masses": [{{"node": "m", "mass": 1}}],
    "supports": [{{"node": "ground", "fix": ["x"]}}, {{"node": "wall", "fix": ["x"]}}],
    "loads": [{{"node": "m", "x": {}}}],
    "links": [{{"id": "stop", "nodes": ["m", "wall"], "gap": 0.05,
                "law": {}}}],
    "analysis": {{"time_step": 0.001, "duration": 1}}
  }})",
                                                                     load, law),
                                                         "spring.json"))
                              .model);
}

TEST(StaticEquilibrium, ALoadThatClosesTheGapIsCarriedByTheSpringAndTheLink) {
  // 100 u + 300 (u - 0.05) = 10: u = 25 / 400.
  StructuralSystem system = system_under(10.0);
  const StaticEquilibrium solution = static_equilibrium(system, 0.0);
  ASSERT_EQ(solution.displacement.size(), 1);
  EXPECT_NEAR(solution.displacement[0], 25.0 / 400.0, 1e-12);
  EXPECT_GE(solution.iterations, 1);
  EXPECT_LT(solution.unbalanced_force, 1e-9);
  EXPECT_TRUE(system.links().law(0).in_contact());  // the state at the solution is committed
}

TEST(StaticEquilibrium, ALoadThatLeavesTheGapOpenIsCarriedByTheSpringAlone) {
  StructuralSystem system = system_under(2.0);
  const StaticEquilibrium solution = static_equilibrium(system, 0.0);
  EXPECT_NEAR(solution.displacement[0], 0.02, 1e-14);
  EXPECT_FALSE(system.links().law(0).in_contact());
}

// A link that touches at the start (gap 0) and that no load presses stays exactly at rest: the
// nudge that closes it for the first tangent leaves no round-off in the displacements or in its
// committed state. The bundled bridge's Takeda hinges at the pier bases are such links under
// gravity: with the nudge's force in the residual they kept moments of -8.3e-316 N m, printed
// at t = 0 in hinges.csv. (Its record is left out: the static state is gravity's.)
TEST(StaticEquilibrium, TouchingHingesThatGravityDoesNotBendStayExactlyAtRest) {
  nlohmann::json model = nlohmann::json::parse(
      std::ifstream(std::string(POUND_SOURCE_DIR) + "/models/three_span_bridge_takeda.json"));
  model.erase("excitations");
  model["analysis"]["duration"] = 1.0;
  StructuralSystem system(
      builder::build(io::parse_model(model.dump(), "three_span_bridge_takeda.json")).model);
  static_equilibrium(system, 0.0);
  const integrators::LinkSet& links = system.links();
  int hinges = 0;
  for (Index k = 0; k < links.count(); ++k) {
    if (links.law(k).name() != "takeda") continue;
    const double moment = links.law(k).clone()->set_trial({}).force;
    std::cout << system.link_id(k) << ": committed moment at zero rotation " << moment << "\n";
    EXPECT_EQ(moment, 0.0) << system.link_id(k);
    ++hinges;
  }
  EXPECT_EQ(hinges, 2);
}

// The hard contact's force, as the static solve left it (committed).
double hard_force(StructuralSystem& system, Index link) {
  return system.links().hard_contact(link)->set_trial({}).force;
}

// A hard contact's rows' forces as imposed (its friction's on the row after the normal one).
Vector imposed_forces(StructuralSystem& system) {
  integrators::LinkSet& links = system.links();
  const Vector zero = Vector::Zero(links.size());
  Vector force;
  Matrix tangent;
  links.set_trial(zero, zero, zero, 0.0, 0.0, force, tangent);
  return force;
}

constexpr const char* kHardContact = R"({"type": "hard_contact", "restitution": 0})";

// A hard contact is a constraint in the static solve: the mass stops at the wall (u = 0.05
// exactly) and the contact carries the rest of the load, 10 - 100 x 0.05 = 5.
TEST(StaticEquilibrium, AHardContactStopsTheMassAtTheWallAndCarriesTheRestOfTheLoad) {
  StructuralSystem system = system_under(10.0, kHardContact);
  const StaticEquilibrium solution = static_equilibrium(system, 0.0);
  const double force = hard_force(system, 0);
  std::cout << fmt::format(
      "hard contact at the wall: u - 0.05 = {:.1e}, force - 5 = {:.1e} ({} "
      "iterations)\n",
      solution.displacement[0] - 0.05, force - 5.0, solution.iterations);
  EXPECT_NEAR(solution.displacement[0], 0.05, 1e-15);
  EXPECT_NEAR(force, 5.0, 1e-12);
  EXPECT_TRUE(system.links().law(0).in_contact());
  EXPECT_LT(solution.unbalanced_force, 1e-9);

  StructuralSystem short_of_it = system_under(2.0, kHardContact);
  EXPECT_NEAR(static_equilibrium(short_of_it, 0.0).displacement[0], 0.02, 1e-15);
  EXPECT_FALSE(short_of_it.links().law(0).in_contact());
  EXPECT_EQ(hard_force(short_of_it, 0), 0.0);
}

// A 10 kg block (weight 98.1) on a floor through a hard contact with mu = 0.5, pushed sideways
// by P: below mu W it sticks where it stands, friction carrying P; above, nothing holds it.
// `normal_law`: the floor's law (a hard contact, or a penalty); `extra`: more nodes, masses and
// loads (a loose mass beside the block).
constexpr const char* kHardFloor = R"({"type": "hard_contact", "restitution": 0})";
StructuralSystem block_on_floor(double push, const std::string& belt_velocity = "",
                                const std::string& normal_law = kHardFloor,
                                const std::string& extra = "") {
  const std::string floor =
      belt_velocity.empty()
          ? fmt::format(R"("links": [{{"id": "floor", "nodes": ["block", "ground"], "axis": [0, -1],
                          "law": {}, "friction": {{"coefficient": 0.5}}}}],)",
                        normal_law)
          : fmt::format(R"("surfaces": [{{"id": "belt", "point": [0, 0], "normal": [0, 1],
                            "velocity": [{}, 0], "nodes": ["block"],
                            "law": {{"type": "hard_contact", "restitution": 0}},
                            "friction": {{"coefficient": 0.5}}}}],
                           "links": [{{"id": "spring", "nodes": ["anchor", "block"],
                                      "axis": [1, 0],
                                      "law": {{"type": "elastic_spring", "stiffness": 1000}}}}],)",
                        belt_velocity);
  return StructuralSystem(
      builder::build(
          io::parse_model(fmt::format(R"({{
    "dimension": 2,
    "nodes": [{{"id": "block", "x": 0, "y": 0}}, {{"id": "ground", "x": 0, "y": 0}},
              {{"id": "anchor", "x": -1, "y": 0}}{}],
    "masses": [{{"node": "block", "mass": 10}}{}],
    "supports": [{{"node": "ground", "fix": ["x", "y"]}}, {{"node": "anchor", "fix": ["x", "y"]}}],
    "loads": [{{"node": "block", "x": {}, "y": -98.1}}{}],
    {}
    "analysis": {{"time_step": 0.001, "duration": 1}}
  }})",
                                      extra.empty() ? "" : R"(, {"id": "loose", "x": 2, "y": 0})",
                                      extra.empty() ? "" : R"(, {"node": "loose", "mass": 1})",
                                      push, extra, floor),
                          "block.json"))
          .model);
}

TEST(StaticEquilibrium, ABlockOnARoughFloorSticksBelowMuWAndSlidesAwayAbove) {
  StructuralSystem system = block_on_floor(30.0);
  const StaticEquilibrium solution = static_equilibrium(system, 0.0);
  const double normal = hard_force(system, 0);
  const double tangential = imposed_forces(system)[1];
  std::cout << fmt::format(
      "block pushed by 30 < mu W = 49.05: moved {:.1e}, normal force - W = "
      "{:.1e}, friction - P = {:.1e}\n",
      solution.displacement.cwiseAbs().maxCoeff(), normal - 98.1, std::abs(tangential) - 30.0);
  EXPECT_LT(solution.displacement.cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(normal, 98.1, 1e-12);
  EXPECT_NEAR(std::abs(tangential), 30.0, 1e-12);

  // Past mu W no static state exists: with the loads applied in proportion, friction is passed
  // at their first tenth as at the whole, so the error names the cause and the link, whether the
  // floor is a hard contact (the active set finds a mechanism) or a penalty (Newton cannot
  // converge).
  for (const std::string& law :
       {std::string(kHardFloor),
        std::string(R"({"type": "kelvin_voigt", "stiffness": 1e7, "damping": 2e4})")}) {
    StructuralSystem pushed_off = block_on_floor(60.0, "", law);
    try {
      static_equilibrium(pushed_off, 0.0);
      ADD_FAILURE() << "a block pushed past mu W found a static state";
    } catch (const SolveError& error) {
      const std::string what = error.what();
      std::cout << "pushed by 60 > mu W on " << law << ": " << what << "\n";
      EXPECT_NE(what.find("ask more of friction than it holds"), std::string::npos) << what;
      EXPECT_NE(what.find("at link(s) 'floor'"), std::string::npos) << what;
      EXPECT_EQ(what.find("did not converge"), std::string::npos) << what;
    }
  }
}

// A block held by friction (pushed by 30 < mu W) beside a loaded mass that nothing holds: the
// mechanism is the loose mass's, and friction, which holds, is not blamed.
TEST(StaticEquilibrium, AMechanismBesideAHeldBlockIsNotBlamedOnFriction) {
  StructuralSystem system = block_on_floor(30.0, "", kHardFloor, R"(, {"node": "loose", "x": 1})");
  try {
    static_equilibrium(system, 0.0);
    ADD_FAILURE() << "a loose mass under a load found a static state";
  } catch (const SolveError& error) {
    const std::string what = error.what();
    std::cout << "a loose loaded mass beside the block: " << what << "\n";
    EXPECT_NE(what.find("a mechanism"), std::string::npos) << what;
    EXPECT_EQ(what.find("ask more of friction"), std::string::npos) << what;
  }
}

// On a belt moving at +1 m/s the block slips at mu W = 49.05 in the belt's direction, held by
// its spring (k = 1000): u_x = 0.04905 exactly, as the penalty friction gives it.
TEST(StaticEquilibrium, ABlockOnABeltSlipsAtMuWInTheBeltsDirection) {
  for (const char* velocity : {"1", "-1"}) {
    StructuralSystem system = block_on_floor(0.0, velocity);
    const StaticEquilibrium solution = static_equilibrium(system, 0.0);
    const double sign = velocity[0] == '-' ? -1.0 : 1.0;
    const Index x = system.dofs().own_equation(0, 0), y = system.dofs().own_equation(0, 1);
    std::cout << fmt::format("block on a belt at {} m/s: u_x - mu W / k = {:.1e}, u_y = {:.1e}\n",
                             velocity, solution.displacement[x] - sign * 0.04905,
                             solution.displacement[y]);
    EXPECT_NEAR(solution.displacement[x], sign * 0.04905, 1e-15);
    EXPECT_NEAR(solution.displacement[y], 0.0, 1e-15);
    for (Index k = 0; k < system.links().count(); ++k)
      if (system.links().has_friction(k)) {
        EXPECT_TRUE(system.links().friction(k)->slipping());
      }
  }
}

// In a 3-D scene the friction of a hard contact acts in the contact plane, its limit a circle:
// a block (weight 98.1, mu = 0.5: mu W = 49.05) on a hard floor, held by springs k_x = 1000 and
// k_y = 2500 and pushed by P in the plan. Below the circle (|P| = 42.4, each component 30) it
// sticks where it stands, friction carrying P; past it (P = (60, 45), |P| = 75) it slips, the
// friction mu W along each load increment's slide, the springs taking the rest.
StructuralSystem block_on_floor_in_space(double push_x, double push_y) {
  return StructuralSystem(builder::build(io::parse_model(fmt::format(R"({{
    "dimension": 3,
    "nodes": [{{"id": "block", "x": 0, "y": 0, "z": 0}}, {{"id": "ground", "x": 0, "y": 0, "z": 0}}],
    "masses": [{{"node": "block", "mass": 10}}],
    "supports": [{{"node": "ground", "fix": ["x", "y", "z"]}}],
    "loads": [{{"node": "block", "x": {}, "y": {}, "z": -98.1}}],
    "links": [{{"id": "floor", "nodes": ["block", "ground"], "axis": [0, 0, -1],
               "law": {{"type": "hard_contact", "restitution": 0}},
               "friction": {{"coefficient": 0.5}}}},
              {{"id": "spring_x", "nodes": ["block", "ground"], "axis": [1, 0, 0],
               "law": {{"type": "elastic_spring", "stiffness": 1000}}}},
              {{"id": "spring_y", "nodes": ["block", "ground"], "axis": [0, 1, 0],
               "law": {{"type": "elastic_spring", "stiffness": 2500}}}}],
    "analysis": {{"time_step": 0.001, "duration": 1}}
  }})",
                                                                     push_x, push_y),
                                                         "block_3d.json"))
                              .model);
}

TEST(StaticEquilibrium, InSpaceAHardFloorsFrictionLimitIsACircle) {
  const double limit = 49.05;
  StructuralSystem held = block_on_floor_in_space(30.0, 30.0);
  const StaticEquilibrium still = static_equilibrium(held, 0.0);
  const Vector held_forces = imposed_forces(held);
  const double held_error = std::hypot(held_forces[1] - 30.0, held_forces[2] - 30.0);
  EXPECT_LT(still.displacement.cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT(held_error, 1e-12);
  EXPECT_FALSE(held.links().friction(0)->slipping());

  StructuralSystem pushed = block_on_floor_in_space(60.0, 45.0);
  const StaticEquilibrium slid = static_equilibrium(pushed, 0.0);
  // The static solve applies the loads (weight and push) in 10 equal increments, each slip
  // measured from where the last one left the block; |P| / W = 0.76 > mu, so it slips in each:
  // K u_k + mu W_k e = P_k with e = (u_k - u_{k-1}) / |u_k - u_{k-1}|, W_k = k W / 10. For a slip
  // angle phi, u(phi) = K^-1 (P_k - mu W_k e(phi)); the reference finds the phi at which the slide
  // u(phi) - u_{k-1} lies along e(phi) (a sign change of their cross product, by bisection).
  const Eigen::Vector2d load(60.0, 45.0);
  const Eigen::Matrix2d compliance = Eigen::Vector2d(1e-3, 4e-4).asDiagonal();
  Eigen::Vector2d u = Eigen::Vector2d::Zero(), last_slide_start = u;
  for (int k = 1; k <= 10; ++k) {
    const Eigen::Vector2d applied = 0.1 * k * load, previous = u;
    const double resisted = 0.1 * k * limit;
    last_slide_start = previous;
    const auto along = [&](double phi) { return Eigen::Vector2d(std::cos(phi), std::sin(phi)); };
    const auto slide = [&](double phi) {
      return Eigen::Vector2d(compliance * (applied - resisted * along(phi)) - previous);
    };
    const auto cross = [&](double phi) {
      const Eigen::Vector2d s = slide(phi), e = along(phi);
      return s.x() * e.y() - s.y() * e.x();
    };
    double low = 0.0, high = 0.0;
    const int samples = 3600;
    for (int j = 0; j < samples; ++j) {
      const double a = 2.0 * std::acos(-1.0) * j / samples, b = a + 2.0 * std::acos(-1.0) / samples;
      if (cross(a) * cross(b) <= 0.0 && slide(a).dot(along(a)) > 0.0) {
        low = a;
        high = b;
        break;
      }
    }
    ASSERT_LT(low, high);
    for (int halving = 0; halving < 60; ++halving) {
      const double middle = 0.5 * (low + high);
      (cross(low) * cross(middle) <= 0.0 ? high : low) = middle;
    }
    u = previous + slide(0.5 * (low + high));
  }
  const Index x = pushed.dofs().own_equation(0, 0), y = pushed.dofs().own_equation(0, 1);
  const Eigen::Vector2d found(slid.displacement[x], slid.displacement[y]);
  const Vector forces = imposed_forces(pushed);
  const Eigen::Vector2d friction(forces[1], forces[2]);
  const double displacement_error = (found - u).norm() / u.norm();
  // (The loads being proportional, every increment slides the same way: u_k = k u_1.)
  const double limit_error = friction.norm() / limit - 1.0;
  const double direction_error =
      1.0 - friction.normalized().dot((u - last_slide_start).normalized());
  std::cout << fmt::format(
      "3-D block on a hard floor: held by |P| = 42.4 < mu W, moved {:.1e}, friction - P {:.1e}; "
      "pushed by |P| = 75: u error {:.1e} of |u| = {:.4f}, |F_t| / (mu W) - 1 = {:.1e}, 1 - "
      "cos(F_t, u) = {:.1e} ({} iterations)\n",
      still.displacement.cwiseAbs().maxCoeff(), held_error, displacement_error, u.norm(),
      limit_error, direction_error, slid.iterations);
  EXPECT_LT(displacement_error, 1e-9);
  EXPECT_LT(std::abs(limit_error), 1e-9);
  EXPECT_LT(direction_error, 1e-9);
  EXPECT_TRUE(pushed.links().friction(0)->slipping());
}

}  // namespace
}  // namespace pound::assembly
