// Extreme inputs on the simplest collision with a closed form: two free bodies meeting through an
// elastic gap spring leave with the velocities of a perfectly elastic collision,
//   v1' = (m1 - m2) / (m1 + m2) V,   v2' = 2 m1 / (m1 + m2) V,
// whatever the spring stiffness, as long as the contact (duration T = pi sqrt(m_eff / k)) is
// resolved. Swept: mass ratios 1e-6 .. 1e6, approach speeds V0 and 1e3 V0, zero and open gaps,
// implicit and explicit integration. Nothing may be NaN, and the answer must stay right.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <iostream>
#include <numbers>
#include <string>
#include <tuple>

#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "io/model_reader.hpp"

namespace pound {
namespace {

constexpr double kStriker = 1.0e3;         // kg, the moving body
constexpr double kStiffness = 1.0e6;       // N/m
constexpr double kSpeed = 0.5;             // m/s, V0
constexpr double kStepsPerContact = 20.0;  // Kawashima: T_contact / dt >= 20

struct Case {
  double target_over_striker;  // m2 / m1
  double speed;                // m/s
  double gap;                  // m
  std::string integrator;
};

std::string name_of(const ::testing::TestParamInfo<Case>& info) {
  const Case& c = info.param;
  std::string name = fmt::format("ratio_{:g}_speed_{:g}_gap_{:g}_{}", c.target_over_striker,
                                 c.speed, c.gap, c.integrator);
  std::string identifier;  // gtest names: letters, digits and '_' only
  for (char ch : name) {
    if (ch == '-')
      identifier += "m";
    else if (ch == '.')
      identifier += "p";
    else if (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_')
      identifier += ch;
  }
  return identifier;
}

class ExtremeCollision : public ::testing::TestWithParam<Case> {};

TEST_P(ExtremeCollision, LeavesWithTheElasticCollisionVelocities) {
  const Case& c = GetParam();
  const double target = kStriker * c.target_over_striker;
  const double effective_mass = kStriker * target / (kStriker + target);
  const double contact_duration = std::numbers::pi * std::sqrt(effective_mass / kStiffness);
  const double time_step = contact_duration / kStepsPerContact;
  const double duration = c.gap / c.speed + 2.0 * contact_duration;
  const std::string text =
      fmt::format(R"({{
    "nodes": [{{"id": "striker", "x": 0}}, {{"id": "target", "x": 1}}],
    "masses": [{{"node": "striker", "mass": {}}}, {{"node": "target", "mass": {}}}],
    "initial_velocities": [{{"node": "striker", "x": {}}}],
    "links": [{{"id": "contact", "nodes": ["striker", "target"], "axis": [1], "gap": {},
               "law": {{"type": "gap_spring", "stiffness": {}}}}}],
    "analysis": {{"integrator": "{}", "time_step": {}, "duration": {}}},
    "recorders": []
  }})",
                  kStriker, target, c.speed, c.gap, kStiffness, c.integrator, time_step, duration);
  builder::BuiltModel built = builder::build(io::parse_model(text, "collision.json"));
  assembly::StructuralSystem system(built.model);
  builder::settle_time_step(built.analysis, built.model, system, "collision.json");
  auto integrator = builder::make_integrator(built.analysis);
  integrators::TransientAnalysis analysis(system, *integrator,
                                          builder::make_transient_settings(built.analysis));
  integrators::State state;
  state.velocity = system.initial_velocity(built.model);
  bool finite = true;
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    finite = finite && s.velocity.allFinite() && s.displacement.allFinite();
  });
  ASSERT_TRUE(finite);

  const double striker_after = state.velocity[system.dofs().own_equation(0, 0)];
  const double target_after = state.velocity[system.dofs().own_equation(1, 0)];
  const double striker_exact = (kStriker - target) / (kStriker + target) * c.speed;
  const double target_exact = 2.0 * kStriker / (kStriker + target) * c.speed;
  // The striker's error relative to the approach speed (its exact value may be 0); the target's
  // relative to its own exact value (2e-6 V for the heaviest target).
  const double striker_error = std::abs(striker_after - striker_exact) / c.speed;
  const double target_error = std::abs(target_after - target_exact) / target_exact;
  std::cout << fmt::format("{}: striker error {:.2e}, target error {:.2e}\n", name_of({c, 0}),
                           striker_error, target_error);
  // At Kawashima's minimum of 20 steps per contact the largest error measured over the sweep is
  // 4.9e-4 (it falls about a thousandfold at 200 steps); 2e-3 leaves a factor of 4.
  EXPECT_LT(striker_error, 2e-3);
  EXPECT_LT(target_error, 2e-3);
  EXPECT_LE(state.link_penetration[0], 0.0) << "still in contact at the end";
}

std::vector<Case> cases() {
  std::vector<Case> all;
  for (double ratio : {1e-6, 1.0, 1e6})
    for (double speed : {kSpeed, 1e3 * kSpeed})
      for (double gap : {0.0, 0.01})
        for (const char* integrator : {"newmark_average_acceleration", "central_difference"})
          all.push_back({ratio, speed, gap, integrator});
  return all;
}

INSTANTIATE_TEST_SUITE_P(Sweep, ExtremeCollision, ::testing::ValuesIn(cases()), name_of);

}  // namespace
}  // namespace pound
