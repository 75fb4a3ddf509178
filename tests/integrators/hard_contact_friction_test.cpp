// Coulomb friction on a hard contact (a constraint on the tangential row: stick, or slip at
// mu R_n) under every integrator, against rigid-body closed forms: a block sliding to rest, a
// block under a growing push that sticks and then slips, and an oblique impact (Routh's
// solution: the tangential impulse is mu times the normal one, or what stops the slide).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "integrators/central_difference.hpp"
#include "integrators/newmark.hpp"
#include "integrators/transient_analysis.hpp"
#include "support/free_masses.hpp"

namespace pound {
namespace {

using testing::FreeMassPair;
using testing::hard_contact_on_the_ground;

struct Method {
  std::string name;
  std::function<std::unique_ptr<integrators::Integrator>()> make;
  // HHT and generalised-alpha: a held hard contact's force settles over some 100 steps (the
  // methods' own transient, with the residual rate O(dt a (gamma - 1/2))), and their loads act
  // at t_{n+1-alpha_f}: the friction force follows within a step of the load's change.
  bool alpha = false;
  // An implicit step's hard-contact force is its impulse / dt, the step's average.
  bool average_force = true;
};

std::vector<Method> methods() {
  return {{"central_difference", [] { return std::make_unique<integrators::CentralDifference>(); },
           false, false},
          {"newmark",
           [] {
             return std::make_unique<integrators::Newmark>(
                 integrators::Newmark::average_acceleration());
           }},
          {"hht",
           [] { return std::make_unique<integrators::Newmark>(integrators::Newmark::hht(-0.1)); },
           true},
          {"generalized_alpha",
           [] {
             return std::make_unique<integrators::Newmark>(
                 integrators::Newmark::generalized_alpha(0.5));
           },
           true}};
}

constexpr double kGravity = 9.81;

// A 10 kg block on the ground, sliding at 2 m/s with mu = 0.5: it slows at mu g exactly, stops at
// v^2 / (2 mu g) after v / (mu g), and then stays where it stopped, pressed by m g.
TEST(HardContactFriction, BlockSlidesToRestWhereMuGSays) {
  const double mass = 10.0, speed = 2.0, mu = 0.5, dt = 1e-3;
  const double stop = speed * speed / (2.0 * mu * kGravity);
  for (const Method& method : methods()) {
    FreeMassPair system(mass, mass, hard_contact_on_the_ground(0.0, 0.0, mu), [&](double) {
      return Vector{{0.0, -mass * kGravity}};
    });
    std::unique_ptr<integrators::Integrator> integrator = method.make();
    integrators::TransientAnalysis analysis(system, *integrator,
                                            {.time_step = dt, .end_time = 0.6});
    integrators::State state;
    state.displacement = Vector::Zero(2);
    state.velocity = Vector{{speed, 0.0}};
    double speed_error = 0.0;
    analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
      if (s.time < 0.4)
        speed_error =
            std::max(speed_error, std::abs(s.velocity[0] - (speed - mu * kGravity * s.time)));
    });
    const double stop_error = state.displacement[0] - stop;
    const double normal_error = state.link_force[0] / (mass * kGravity) - 1.0;
    std::cout << method.name << ": speed error while sliding " << speed_error << ", stop error "
              << stop_error << " (bound mu g dt^2 " << mu * kGravity * dt * dt << "), final speed "
              << state.velocity[0] << ", normal force / m g - 1 " << normal_error
              << ", friction force " << state.link_force[1] << "\n";
    EXPECT_LT(speed_error, method.alpha ? 1e-3 * speed : 1e-10) << method.name;
    EXPECT_LT(std::abs(stop_error), mu * kGravity * dt * dt) << method.name;
    EXPECT_LT(std::abs(state.velocity[0]), 1e-12) << method.name;
    EXPECT_LT(std::abs(normal_error), 1e-6) << method.name;
    EXPECT_LT(std::abs(state.link_force[1]), 1e-9) << method.name;  // at rest, nothing to resist
  }
}

// The same block pushed sideways by P = k t: it sticks (not moving at all) until P = mu m g at
// t_s = mu m g / k, then slides with m x'' = P - mu m g: x = k (t - t_s)^3 / (6 m). While it
// sticks the friction force is the push (at t; an implicit step's, its average over the step).
TEST(HardContactFriction, PushedBlockSticksThenSlips) {
  const double mass = 10.0, mu = 0.5, dt = 1e-3, rate = 98.1;  // t_s = 0.5
  const double start = mu * mass * kGravity / rate, end = 1.0;
  for (const Method& method : methods()) {
    FreeMassPair system(mass, mass, hard_contact_on_the_ground(0.0, 0.0, mu), [&](double t) {
      return Vector{{rate * t, -mass * kGravity}};
    });
    std::unique_ptr<integrators::Integrator> integrator = method.make();
    integrators::TransientAnalysis analysis(system, *integrator,
                                            {.time_step = dt, .end_time = end});
    integrators::State state;
    state.displacement = Vector::Zero(2);
    state.velocity = Vector::Zero(2);
    double moved_while_stuck = 0.0, stick_force_error = 0.0;
    analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
      if (s.time > start - 0.5 * dt || s.time < 0.5 * dt) return;  // the start has no step
      moved_while_stuck = std::max(moved_while_stuck, std::abs(s.displacement[0]));
      const double time = method.average_force ? s.time - 0.5 * dt : s.time;
      stick_force_error = std::max(stick_force_error, std::abs(s.link_force[1] - rate * time));
    });
    const double exact = rate * std::pow(end - start, 3) / (6.0 * mass);
    const double error = state.displacement[0] / exact - 1.0;
    std::cout << method.name << ": moved while stuck " << moved_while_stuck
              << ", stick force error " << stick_force_error << ", slide " << state.displacement[0]
              << " against " << exact << " (relative error " << error << ")\n";
    EXPECT_LT(moved_while_stuck, 1e-14) << method.name;
    EXPECT_LT(stick_force_error, method.alpha ? rate * dt : 1e-9) << method.name;
    EXPECT_LT(std::abs(error), 1e-4) << method.name;
  }
}

// A mass striking the ground obliquely (tangential speed 1, normal 2) with restitution e: the
// normal speed becomes e w; the tangential one loses mu (1 + e) w if that is less than it has
// (slip throughout the impact), else stops (it sticks): Routh's solution for a point mass.
TEST(HardContactFriction, ObliqueImpactGivesRouthsSolution) {
  const double mass = 2.0, tangential = 1.0, normal = 2.0, dt = 1e-3;
  for (const Method& method : methods()) {
    double worst = 0.0;
    for (const double e : {0.0, 0.5})
      for (const double mu : {0.1, 0.6})
        for (const double phase : {0.0, 0.3, 0.7}) {
          FreeMassPair system(mass, mass,
                              hard_contact_on_the_ground(normal * dt * (2.0 + phase), e, mu));
          std::unique_ptr<integrators::Integrator> integrator = method.make();
          integrators::TransientAnalysis analysis(system, *integrator,
                                                  {.time_step = dt, .end_time = 12.0 * dt});
          integrators::State state;
          state.displacement = Vector::Zero(2);
          state.velocity = Vector{{tangential, -normal}};
          analysis.run(state);
          const double slide = std::max(0.0, tangential - mu * (1.0 + e) * normal);
          worst = std::max({worst, std::abs(state.velocity[0] - slide),
                            std::abs(state.velocity[1] - e * normal)});
        }
    std::cout << method.name << ": oblique impact, largest velocity error " << worst << "\n";
    // The alpha methods leave a held contact a rate of O(dt a (gamma - 1/2)); here nothing
    // presses after the impact.
    EXPECT_LT(worst, 1e-12) << method.name;
  }
}

}  // namespace
}  // namespace pound
