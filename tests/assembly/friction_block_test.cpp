// A block sliding on a rough floor (2-D, a link with Coulomb friction, gravity as a nodal load)
// against the closed form: it decelerates at mu g, stops after v0^2 / (2 mu g) and then sticks.
// In 3-D (issue 18) the block slides obliquely on the contact plane of a vertical link: it stops
// where and when mu g says, on the line it was launched along, and its friction limit is a
// circle (a push past mu m g slides it even when each component is below the limit).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <iostream>

#include "assembly/static_equilibrium.hpp"
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "io/model_reader.hpp"

namespace pound {
namespace {

constexpr double kMu = 0.5, kGravity = 9.81, kSpeed = 2.0, kMass = 10.0;

// The block sits on the floor (gap 0); the normal law is critically damped so the start-up
// bounce dies within milliseconds.
std::string block_model(double horizontal_load, double speed) {
  return fmt::format(R"({{
    "dimension": 2,
    "nodes": [{{"id": "block", "x": 0, "y": 0}}, {{"id": "floor", "x": 0, "y": 0}}],
    "masses": [{{"node": "block", "mass": {mass}}}],
    "supports": [{{"node": "floor", "fix": ["x", "y"]}}],
    "loads": [{{"node": "block", "x": {push}, "y": {weight}}}],
    "initial_velocities": [{{"node": "block", "x": {speed}}}],
    "links": [{{"id": "contact", "nodes": ["block", "floor"], "axis": [0, -1],
                "law": {{"type": "kelvin_voigt", "stiffness": 1e7, "damping": 2e4}},
                "friction": {{"coefficient": {mu}}}}}],
    "analysis": {{"time_step": 1e-4, "duration": 0.6}}
  }})",
                     fmt::arg("mass", kMass), fmt::arg("push", horizontal_load),
                     fmt::arg("weight", -kMass * kGravity), fmt::arg("speed", speed),
                     fmt::arg("mu", kMu));
}

struct Slide {
  std::vector<double> time, position, velocity, tangential_force;
};

Slide run(const std::string& text) {
  const builder::BuiltModel built = builder::build(io::parse_model(text, "block.json"));
  assembly::StructuralSystem system(built.model);
  auto integrator = builder::make_integrator(built.analysis);
  integrators::TransientAnalysis analysis(system, *integrator,
                                          builder::make_transient_settings(built.analysis));
  const Index x = system.dofs().own_equation(built.node_index.at("block"), 0);
  Slide slide;
  integrators::State state;
  state.velocity = system.initial_velocity(built.model);
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    slide.time.push_back(s.time);
    slide.position.push_back(s.displacement[x]);
    slide.velocity.push_back(s.velocity[x]);
    slide.tangential_force.push_back(s.link_force[1]);
  });
  return slide;
}

TEST(FrictionBlock, DeceleratesAtMuGAndStopsWhereTheClosedFormSays) {
  const Slide slide = run(block_model(0.0, kSpeed));
  const double stop_time = kSpeed / (kMu * kGravity),
               stop_distance = kSpeed * kSpeed / (2 * kMu * kGravity);
  // Deceleration from the velocity between 0.05 s and 0.35 s (after the start-up transient).
  const auto at = [&](double t) { return static_cast<std::size_t>(std::lround(t / 1e-4)); };
  const double deceleration = (slide.velocity[at(0.05)] - slide.velocity[at(0.35)]) / 0.30;
  const double deceleration_error = deceleration / (kMu * kGravity) - 1.0;
  const double distance_error = slide.position.back() / stop_distance - 1.0;
  std::cout << "deceleration error " << deceleration_error << ", stopping distance error "
            << distance_error << ", final velocity " << slide.velocity.back() << "\n";
  EXPECT_LT(std::abs(deceleration_error), 1e-3);
  EXPECT_LT(std::abs(distance_error), 5e-3);
  EXPECT_LT(std::abs(slide.velocity.back()), 1e-3);  // stuck, not creeping
  EXPECT_GT(slide.time.back(), stop_time + 0.1);
  EXPECT_LT(std::abs(slide.tangential_force.back()), 1e-3 * kMu * kMass * kGravity);
}

TEST(FrictionBlock, APushBelowTheFrictionLimitDoesNotMoveTheBlock) {
  const double push = 0.8 * kMu * kMass * kGravity;
  const Slide slide = run(block_model(push, 0.0));
  std::cout << "displacement under a push of 0.8 mu m g: " << slide.position.back() << "\n";
  // Only the elastic stick deflection push / k_t (k_t = the normal law's 1e7).
  EXPECT_NEAR(slide.position.back(), push / 1e7, 1e-6);
  EXPECT_NEAR(slide.tangential_force.back(), push, 1e-3 * push);
}

// The same closed form for an elastic block of quads (2 x 2 elements, 1 m x 0.5 m, E = 10 MPa)
// sliding on a rigid floor: gravity as nodal loads (the lumped masses times g), the floor a
// surface with the extended penalty and mu = 0.3, the static state under gravity first, then
// the block launched at 2 m/s (central difference at 0.8 of its stable step).
TEST(FrictionBlock, AnElasticBlockOfQuadsDeceleratesAtMuGToo) {
  constexpr double mu = 0.3, g = 9.81, speed = 2.0, mass = 1000.0 * 1.0 * 0.5 * 1.0;
  std::string loads;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) {
      const double share = (i == 1 ? 2.0 : 1.0) * (j == 1 ? 2.0 : 1.0) / 16.0;
      loads += fmt::format("{}{{\"node\": \"b.{}.{}\", \"y\": {}}}", loads.empty() ? "" : ",", i, j,
                           -share * mass * g);
    }
  const std::string text = fmt::format(R"({{
    "dimension": 2,
    "materials": [{{"id": "m", "youngs_modulus": 1e7, "poisson_ratio": 0.25, "density": 1000}}],
    "generators": [{{"type": "block", "id": "b", "width": 1.0, "height": 0.5, "elements": [2, 2],
                    "material": "m", "thickness": 1.0, "initial_velocity": [{}, 0.0]}}],
    "loads": [{}],
    "surfaces": [{{"id": "floor", "point": [0, 0], "normal": [0, 1], "nodes": ["b.bottom"],
                  "law": {{"type": "extended_penalty"}}, "friction": {{"coefficient": {}}}}}],
    "analysis": {{"integrator": "central_difference", "time_step": "auto", "duration": 0.9,
                 "initial_state": "static"}}
  }})",
                                       speed, loads, mu);
  const builder::BuiltModel built = builder::build(io::parse_model(text, "quads.json"));
  assembly::StructuralSystem system(built.model);
  builder::BuiltModel settled = built;
  builder::settle_time_step(settled.analysis, settled.model, system, "quads.json");
  auto integrator = builder::make_integrator(settled.analysis);
  integrators::TransientAnalysis analysis(system, *integrator,
                                          builder::make_transient_settings(settled.analysis));
  const Vector mass_vector = system.mass_matrix().diagonal();
  // Centroid velocity and position along x.
  std::vector<double> time, velocity, position;
  integrators::State state;
  state.velocity = system.initial_velocity(built.model);
  state.displacement = assembly::static_equilibrium(system, 0.0).displacement;
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    double momentum = 0.0, moment = 0.0, total = 0.0;
    for (Index node = 0; node < static_cast<Index>(built.model.nodes.size()); ++node)
      if (const Index x = system.dofs().own_equation(node, 0); x >= 0) {
        momentum += mass_vector[x] * s.velocity[x];
        moment += mass_vector[x] * s.displacement[x];
        total += mass_vector[x];
      }
    time.push_back(s.time);
    velocity.push_back(momentum / total);
    position.push_back(moment / total);
  });
  const double stop_time = speed / (mu * g), stop_distance = speed * speed / (2 * mu * g);
  // Mean deceleration by a least-squares line through the velocity over [0.1, 0.5] s.
  double st = 0, sv = 0, stt = 0, stv = 0, count = 0;
  for (std::size_t k = 0; k < time.size(); ++k)
    if (time[k] >= 0.1 && time[k] <= 0.5) {
      st += time[k], sv += velocity[k], stt += time[k] * time[k], stv += time[k] * velocity[k];
      ++count;
    }
  const double deceleration = -(count * stv - st * sv) / (count * stt - st * st);
  const double deceleration_error = deceleration / (mu * g) - 1.0;
  const double distance_error = position.back() / stop_distance - 1.0;
  std::cout << fmt::format(
      "quad block: deceleration error {:.2e}, stopping distance error {:.2e}, "
      "final velocity {:.2e} m/s (stops at {:.3f} s)\n",
      deceleration_error, distance_error, velocity.back(), stop_time);
  // The block rocks a little on the penalty contact as it brakes (front nodes loaded more):
  // the mean deceleration is mu g within 0.5 %, the stopping distance within 2 %.
  EXPECT_LT(std::abs(deceleration_error), 0.005);
  EXPECT_LT(std::abs(distance_error), 0.02);
  EXPECT_LT(std::abs(velocity.back()), 0.05 * speed);
}

// The 3-D block: launched at `speed` along the plan angle `angle`, pushed by `push` (x, y),
// on a vertical link (axis -z, tangents x and y) with Kelvin-Voigt contact and friction mu.
constexpr const char* kKelvinVoigt =
    R"({"type": "kelvin_voigt", "stiffness": 1e7, "damping": 2e4})";
constexpr const char* kHardFloor = R"({"type": "hard_contact", "restitution": 0})";

std::string space_block(double speed, double angle, std::array<double, 2> push,
                        const std::string& integrator, const std::string& law = kKelvinVoigt,
                        double duration = 0.6) {
  return fmt::format(R"({{
    "dimension": 3,
    "nodes": [{{"id": "block", "x": 0, "y": 0, "z": 0}}, {{"id": "floor", "x": 0, "y": 0, "z": 0}}],
    "masses": [{{"node": "block", "mass": {mass}}}],
    "supports": [{{"node": "floor", "fix": ["x", "y", "z"]}}],
    "loads": [{{"node": "block", "x": {px}, "y": {py}, "z": {weight}}}],
    "initial_velocities": [{{"node": "block", "x": {vx}, "y": {vy}}}],
    "links": [{{"id": "contact", "nodes": ["block", "floor"], "axis": [0, 0, -1],
                "law": {law}, "friction": {{"coefficient": {mu}}}}}],
    "analysis": {{"integrator": "{integrator}", "time_step": 1e-4, "duration": {duration}}}
  }})",
                     fmt::arg("mass", kMass), fmt::arg("px", push[0]), fmt::arg("py", push[1]),
                     fmt::arg("weight", -kMass * kGravity), fmt::arg("vx", speed * std::cos(angle)),
                     fmt::arg("vy", speed * std::sin(angle)), fmt::arg("mu", kMu),
                     fmt::arg("integrator", integrator), fmt::arg("law", law),
                     fmt::arg("duration", duration));
}

struct PlanSlide {
  std::vector<double> time, x, y, z, vx, vy, normal, force_1, force_2;
};

PlanSlide run_in_plan(const std::string& text) {
  const builder::BuiltModel built = builder::build(io::parse_model(text, "block_3d.json"));
  assembly::StructuralSystem system(built.model);
  auto integrator = builder::make_integrator(built.analysis);
  integrators::TransientAnalysis analysis(system, *integrator,
                                          builder::make_transient_settings(built.analysis));
  const Index block = built.node_index.at("block");
  const Index x = system.dofs().own_equation(block, 0), y = system.dofs().own_equation(block, 1),
              z = system.dofs().own_equation(block, 2);
  EXPECT_EQ(system.links().rows(0), 3);  // normal, t_1 = x, t_2 = y
  PlanSlide slide;
  integrators::State state;
  state.displacement = Vector::Zero(system.dofs().size());
  state.velocity = system.initial_velocity(built.model);
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    slide.time.push_back(s.time);
    slide.x.push_back(s.displacement[x]);
    slide.y.push_back(s.displacement[y]);
    slide.z.push_back(s.displacement[z]);
    slide.normal.push_back(s.link_force[0]);
    slide.vx.push_back(s.velocity[x]);
    slide.vy.push_back(s.velocity[y]);
    slide.force_1.push_back(s.link_force[1]);
    slide.force_2.push_back(s.link_force[2]);
  });
  return slide;
}

// What an oblique slide launched at kSpeed along `angle` is judged by: its deceleration between
// 0.05 and 0.35 s against mu g, its stopping distance against v0^2 / (2 mu g), its final direction
// against the launch angle, and how far it strayed off the launch line.
struct ObliqueErrors {
  double deceleration, distance, direction, off_line;
};

ObliqueErrors oblique_errors(const PlanSlide& slide, double angle, double dt) {
  const auto at = [&](double t) { return static_cast<std::size_t>(std::lround(t / dt)); };
  const auto speed = [&](std::size_t k) { return std::hypot(slide.vx[k], slide.vy[k]); };
  ObliqueErrors errors{};
  errors.deceleration = (speed(at(0.05)) - speed(at(0.35))) / 0.30 / (kMu * kGravity) - 1.0;
  errors.distance =
      std::hypot(slide.x.back(), slide.y.back()) / (kSpeed * kSpeed / (2 * kMu * kGravity)) - 1.0;
  errors.direction = std::atan2(slide.y.back(), slide.x.back()) - angle;
  for (std::size_t k = 0; k < slide.x.size(); ++k)
    errors.off_line = std::max(
        errors.off_line, std::abs(-std::sin(angle) * slide.x[k] + std::cos(angle) * slide.y[k]));
  return errors;
}

TEST(FrictionBlock, SlidingObliquelyInSpaceStopsWhereAndWhenMuGSaysAlongItsPath) {
  const double angle = 35.0 * std::acos(-1.0) / 180.0;
  const double stop_time = kSpeed / (kMu * kGravity),
               stop_distance = kSpeed * kSpeed / (2 * kMu * kGravity);
  for (const char* integrator : {"newmark_average_acceleration", "central_difference"}) {
    SCOPED_TRACE(integrator);
    const PlanSlide slide = run_in_plan(space_block(kSpeed, angle, {0.0, 0.0}, integrator));
    const auto speed = [&](std::size_t k) { return std::hypot(slide.vx[k], slide.vy[k]); };
    const auto [deceleration_error, distance_error, direction_error, off_line] =
        oblique_errors(slide, angle, 1e-4);
    // When it stopped: the first step at rest (|v| below 1 % of v0).
    std::size_t stopped = 0;
    while (stopped < slide.time.size() && speed(stopped) > 0.01 * kSpeed) ++stopped;
    ASSERT_LT(stopped, slide.time.size());
    const double stop_time_error = slide.time[stopped] / stop_time - 1.0;
    std::cout << fmt::format(
        "{}: deceleration error {:.2e}, stopping distance error {:.2e}, stop time error "
        "{:.2e}, direction error {:.1e} rad, off the launch line {:.1e} m, final speed "
        "{:.1e} m/s\n",
        integrator, deceleration_error, distance_error, stop_time_error, direction_error, off_line,
        speed(slide.time.size() - 1));
    EXPECT_LT(std::abs(deceleration_error), 1e-3);
    EXPECT_LT(std::abs(distance_error), 5e-3);
    // |v| = 1 % of v0 is reached 1 % of the stopping time early.
    EXPECT_LT(std::abs(stop_time_error + 0.01), 5e-3);
    EXPECT_LT(std::abs(direction_error), 1e-9);
    EXPECT_LT(off_line, 1e-9 * stop_distance);
    EXPECT_LT(speed(slide.time.size() - 1), 1e-3);  // stuck, not creeping
    EXPECT_LT(std::hypot(slide.force_1.back(), slide.force_2.back()),
              1e-3 * kMu * kMass * kGravity);
  }
}

// The friction limit is a circle of radius mu R_n: a push of 0.6 mu m g along x and y together
// (0.85 mu m g in all) is held, one of 0.8 mu m g along each (1.13 mu m g) slides the block
// along the push at (|P| - mu m g) / m, though each component alone is below the limit.
TEST(FrictionBlock, TheFrictionLimitInSpaceIsACircleNotABox) {
  const double limit = kMu * kMass * kGravity, diagonal = std::sqrt(0.5);
  const PlanSlide held = run_in_plan(
      space_block(0.0, 0.0, {0.6 * limit, 0.6 * limit}, "newmark_average_acceleration"));
  const double held_force_error =
      std::hypot(held.force_1.back() - 0.6 * limit, held.force_2.back() - 0.6 * limit) / limit;
  EXPECT_NEAR(held.x.back(), 0.6 * limit / 1e7, 1e-9);  // the stick deflection P / k_t
  EXPECT_NEAR(held.y.back(), 0.6 * limit / 1e7, 1e-9);
  EXPECT_LT(held_force_error, 1e-6);
  const double push = 0.8 * limit;
  const PlanSlide pushed =
      run_in_plan(space_block(0.0, 0.0, {push, push}, "newmark_average_acceleration"));
  const double expected = (std::hypot(push, push) - limit) / kMass;  // along (1, 1) / sqrt 2
  const auto at = [&](double t) { return static_cast<std::size_t>(std::lround(t / 1e-4)); };
  const double along =
      diagonal *
      (pushed.vx[at(0.5)] - pushed.vx[at(0.1)] + pushed.vy[at(0.5)] - pushed.vy[at(0.1)]) / 0.4;
  const double acceleration_error = along / expected - 1.0;
  const double across = std::abs(pushed.vx.back() - pushed.vy.back());
  std::cout << fmt::format(
      "held at 0.85 mu m g: friction force error {:.1e} of mu m g; pushed at 1.13 mu m g: "
      "acceleration error {:.2e}, velocity across the push {:.1e} m/s\n",
      held_force_error, acceleration_error, across);
  EXPECT_LT(std::abs(acceleration_error), 1e-3);
  EXPECT_LT(across, 1e-12);
}

// On a hard floor (issue 17: friction on a hard contact in a contact plane) the block slides
// obliquely with no penalty in the way: it decelerates at mu g to round-off, under the implicit
// integrators and central difference, stops on its launch line, and then sticks.
TEST(FrictionBlock, OnAHardFloorSlidingObliquelyStopsWhereAndWhenMuGSays) {
  const double angle = 35.0 * std::acos(-1.0) / 180.0, dt = 1e-4;
  const double stop_time = kSpeed / (kMu * kGravity),
               stop_distance = kSpeed * kSpeed / (2 * kMu * kGravity);
  for (const char* integrator : {"newmark_average_acceleration", "hht", "central_difference"}) {
    SCOPED_TRACE(integrator);
    const PlanSlide slide =
        run_in_plan(space_block(kSpeed, angle, {0.0, 0.0}, integrator, kHardFloor));
    const auto speed = [&](std::size_t k) { return std::hypot(slide.vx[k], slide.vy[k]); };
    const auto [deceleration_error, distance_error, direction_error, off_line] =
        oblique_errors(slide, angle, dt);
    double lift = 0.0, force_error = 0.0;
    for (std::size_t k = 0; k < slide.x.size(); ++k) {
      lift = std::max(lift, std::abs(slide.z[k]));
      if (slide.time[k] > 0.01 && slide.time[k] < stop_time - 0.01)  // slipping: mu R_n
        force_error =
            std::max(force_error, std::abs(std::hypot(slide.force_1[k], slide.force_2[k]) /
                                               (kMu * std::max(slide.normal[k], 1e-300)) -
                                           1.0));
    }
    std::size_t stopped = 0;
    while (stopped < slide.time.size() && speed(stopped) > 1e-9) ++stopped;
    ASSERT_LT(stopped, slide.time.size());
    const double stop_time_error = slide.time[stopped] - stop_time;
    std::cout << fmt::format(
        "{} on a hard floor: deceleration error {:.1e}, stopping distance error {:.1e}, "
        "stopped {:.1e} s after v0 / (mu g), direction error {:.1e} rad, off the launch line "
        "{:.1e} m, |F_t| / (mu R_n) - 1 while slipping {:.1e}, lift {:.1e} m\n",
        integrator, deceleration_error, distance_error, stop_time_error, direction_error, off_line,
        force_error, lift);
    // Round-off explicitly; implicitly what Newton's tolerance leaves in each step's impulse.
    const bool explicit_step = std::string(integrator) == "central_difference";
    EXPECT_LT(std::abs(deceleration_error), explicit_step ? 1e-12 : 5e-9);
    // The step's impulse takes the speed to zero within the step in which it runs out.
    EXPECT_LT(std::abs(stop_time_error), 1.01 * dt);
    EXPECT_LT(std::abs(distance_error), kSpeed * dt / stop_distance);
    EXPECT_LT(std::abs(direction_error), 1e-9);
    EXPECT_LT(off_line, 1e-9 * stop_distance);
    EXPECT_LT(force_error, 1e-9);
    EXPECT_LT(lift, 1e-9);
    EXPECT_LT(speed(slide.time.size() - 1), 1e-11 * kSpeed);  // stuck
    EXPECT_LT(std::abs(std::hypot(slide.x.back(), slide.y.back()) -
                       std::hypot(slide.x[stopped], slide.y[stopped])),
              1e-12 * stop_distance);  // not creeping
  }
}

// On a hard floor the limit is a circle too: held at 0.85 mu m g (the friction force equals the
// push, nothing moves), pushed at 1.13 mu m g (0.8 along each axis) it slides along the push at
// (|P| - mu m g) / m.
TEST(FrictionBlock, OnAHardFloorTheFrictionLimitIsACircle) {
  const double limit = kMu * kMass * kGravity, diagonal = std::sqrt(0.5);
  for (const char* integrator : {"newmark_average_acceleration", "central_difference"}) {
    SCOPED_TRACE(integrator);
    const PlanSlide held =
        run_in_plan(space_block(0.0, 0.0, {0.6 * limit, 0.6 * limit}, integrator, kHardFloor, 0.2));
    const double held_force_error =
        std::hypot(held.force_1.back() - 0.6 * limit, held.force_2.back() - 0.6 * limit) / limit;
    const double held_motion = std::hypot(held.x.back(), held.y.back());
    const double push = 0.8 * limit;
    const PlanSlide pushed =
        run_in_plan(space_block(0.0, 0.0, {push, push}, integrator, kHardFloor, 0.2));
    const double expected = (std::hypot(push, push) - limit) / kMass;
    const auto at = [&](double t) { return static_cast<std::size_t>(std::lround(t / 1e-4)); };
    const double along =
        diagonal *
        (pushed.vx[at(0.15)] - pushed.vx[at(0.05)] + pushed.vy[at(0.15)] - pushed.vy[at(0.05)]) /
        0.1;
    const double acceleration_error = along / expected - 1.0;
    const double across = std::abs(pushed.vx.back() - pushed.vy.back());
    std::cout << fmt::format(
        "{} on a hard floor: held at 0.85 mu m g, friction force error {:.1e} of mu m g, moved "
        "{:.1e} m; pushed at 1.13 mu m g: acceleration error {:.1e}, velocity across the push "
        "{:.1e} m/s\n",
        integrator, held_force_error, held_motion, acceleration_error, across);
    EXPECT_LT(held_force_error, 1e-9);
    EXPECT_LT(held_motion, 1e-12);
    EXPECT_LT(std::abs(acceleration_error), 1e-9);
    EXPECT_LT(across, 1e-12);
  }
}

// A curved slide: launched along x and pushed along y at half the friction limit, the block's
// path bends, so the friction's direction turns at every step (Newton's iteration on the slip
// direction, not a fixed one). Against the ODE m v' = P - mu m g v / |v| integrated by RK4 at
// dt / 100 until the block stops (|P| < mu m g: it then sticks for good).
struct CurvedSlide {
  double x, y, stop_time;
};

CurvedSlide curved_slide_reference(double push, double duration) {
  const double h = 1e-6;
  Eigen::Vector2d position(0.0, 0.0), velocity(kSpeed, 0.0);
  const auto acceleration = [&](const Eigen::Vector2d& v) {
    return Eigen::Vector2d(Eigen::Vector2d(0.0, push / kMass) - kMu * kGravity * v / v.norm());
  };
  double t = 0.0;
  // Stop when one more step would carry |v| through zero (|v| falls at least mu g - P / m).
  while (t < duration && velocity.norm() > (kMu * kGravity) * h) {
    const Eigen::Vector2d k1v = acceleration(velocity), k1x = velocity;
    const Eigen::Vector2d k2v = acceleration(velocity + 0.5 * h * k1v),
                          k2x = velocity + 0.5 * h * k1v;
    const Eigen::Vector2d k3v = acceleration(velocity + 0.5 * h * k2v),
                          k3x = velocity + 0.5 * h * k2v;
    const Eigen::Vector2d k4v = acceleration(velocity + h * k3v), k4x = velocity + h * k3v;
    position += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    velocity += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    t += h;
  }
  return {position.x(), position.y(), t};
}

TEST(FrictionBlock, OnAHardFloorACurvedSlideFollowsTheOdeOfItsTurningFriction) {
  const double limit = kMu * kMass * kGravity, push = 0.5 * limit, dt = 1e-4;
  const CurvedSlide reference = curved_slide_reference(push, 0.6);
  const double scale = kSpeed * kSpeed / (2 * kMu * kGravity);
  for (const char* integrator : {"newmark_average_acceleration", "central_difference"}) {
    SCOPED_TRACE(integrator);
    const PlanSlide slide =
        run_in_plan(space_block(kSpeed, 0.0, {0.0, push}, integrator, kHardFloor));
    double turn = 0.0, force_error = 0.0, against = 0.0;
    std::size_t stopped = 0;
    for (std::size_t k = 1; k < slide.x.size(); ++k) {
      const double speed = std::hypot(slide.vx[k], slide.vy[k]);
      if (speed < 1e-9 * kSpeed) {
        if (stopped == 0) stopped = k;
        continue;
      }
      if (slide.time[k] > reference.stop_time - 2 * dt) continue;
      // Slipping: |F_t| = mu R_n, against the step's slide (F_t > 0 resists s growing).
      const Eigen::Vector2d force(slide.force_1[k], slide.force_2[k]);
      const Eigen::Vector2d slid(slide.x[k] - slide.x[k - 1], slide.y[k] - slide.y[k - 1]);
      force_error = std::max(force_error, std::abs(force.norm() / (kMu * slide.normal[k]) - 1.0));
      against = std::max(against, std::abs(force.normalized().dot(slid.normalized()) - 1.0));
      turn = std::max(turn, std::atan2(slide.vy[k], slide.vx[k]));
    }
    ASSERT_GT(stopped, 0u);
    const double position_error =
        std::hypot(slide.x.back() - reference.x, slide.y.back() - reference.y) / scale;
    const double stop_error = slide.time[stopped] - reference.stop_time;
    std::cout << fmt::format(
        "{}: curved slide (turned {:.1f} deg): rest position error {:.1e} of v0^2 / (2 mu g), "
        "stop time error {:.1e} s, |F_t| / (mu R_n) - 1 {:.1e}, 1 - cos(force, slide) {:.1e}\n",
        integrator, turn * 180.0 / std::acos(-1.0), position_error, stop_error, force_error,
        against);
    EXPECT_GT(turn, 0.3);  // the path really bends
    EXPECT_LT(force_error, 1e-9);
    // The friction lies along the step's slide: to round-off explicitly (it is the slide's
    // direction), to the direction's change over a step (slide and velocity differ) implicitly.
    EXPECT_LT(against, 1e-6);
    // First order in dt: the stop falls inside a step.
    EXPECT_LT(position_error, 10.0 * dt);
    EXPECT_LT(std::abs(stop_error), 2.0 * dt);
  }
}

}  // namespace
}  // namespace pound
