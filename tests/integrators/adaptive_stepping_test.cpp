// Adaptive time stepping with contact location, on one-DOF systems without a model.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "core/errors.hpp"
#include "integrators/newmark.hpp"
#include "integrators/transient_analysis.hpp"
#include "links/gap_spring.hpp"
#include "support/oscillator.hpp"

namespace pound {
namespace {

using testing::Oscillator;
constexpr double kPi = std::numbers::pi;

struct WallImpact {
  double first_contact = -1.0;  // the last step before any force
  double last_force = -1.0;     // the last step with force
  double last_contact = -1.0;   // the first step without force after it
  double peak_force = 0.0, rebound = 0.0;
  long steps = 0, located = 0;
};

// A mass at 0.5 towards a rigid wall 0.01 away, through a gap spring (k = 1e4, m = 1): the
// contact starts at t = 0.02 exactly, lasts pi sqrt(m/k), and the rebound is elastic.
WallImpact wall_impact(double dt, bool adaptive) {
  const double mass = 1.0, wall_stiffness = 1.0e4, speed = 0.5, gap = 0.01;
  std::vector<std::unique_ptr<links::LinkLaw>> laws;
  laws.push_back(std::make_unique<links::GapSpring>(wall_stiffness));
  integrators::LinkSet links(1, {{{0, 1.0}}}, {gap}, std::move(laws));
  Oscillator system(mass, 0.0, 0.0, std::move(links));
  integrators::Newmark newmark = integrators::Newmark::average_acceleration();
  integrators::TransientSettings settings{.time_step = dt, .end_time = 0.1};
  if (adaptive) settings.adaptive = integrators::AdaptiveStepping{.tolerance = 1e-5};
  integrators::TransientAnalysis analysis(system, newmark, settings);
  integrators::State state;
  state.velocity = Vector::Constant(1, speed);
  WallImpact impact;
  double previous_time = 0.0, previous_force = 0.0;
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    if (s.link_force[0] > 0) {
      // The contact spans from the last step without force to the first without it again.
      if (impact.first_contact < 0) impact.first_contact = previous_time;
      impact.peak_force = std::max(impact.peak_force, s.link_force[0]);
      impact.last_force = s.time;
    } else if (previous_force > 0 && impact.last_contact < 0) {
      impact.last_contact = s.time;
    }
    previous_time = s.time;
    previous_force = s.link_force[0];
  });
  impact.rebound = -state.velocity[0] / speed;
  impact.steps = analysis.statistics().steps;
  impact.located = analysis.statistics().located_contacts;
  return impact;
}

// With a fixed step the contact starts wherever a step happens to end, up to a step late; with
// contact location it starts at 0.02 whatever the step.
TEST(AdaptiveStepping, LocatesTheContactInstantWhateverTheStep) {
  const double contact_time = kPi * std::sqrt(1.0 / 1.0e4);
  for (const double steps_per_contact : {7.0, 13.0, 20.0}) {
    const double dt = contact_time / steps_per_contact;
    const WallImpact fixed = wall_impact(dt, false);
    const WallImpact adaptive = wall_impact(dt, true);
    const double fixed_onset = fixed.first_contact - 0.02,
                 adaptive_onset = adaptive.first_contact - 0.02;
    const double peak_error = adaptive.peak_force / (0.5 * std::sqrt(1.0e4)) - 1.0;
    std::cout << fmt::format(
        "dt = T/{:.0f}: onset error fixed {:+.2e} ({:.2f} steps), located {:+.2e}; rebound fixed "
        "{:.6f}, adaptive {:.6f}; adaptive peak force error {:+.1e}; steps {} / {}\n",
        steps_per_contact, fixed_onset, fixed_onset / dt, adaptive_onset, fixed.rebound,
        adaptive.rebound, peak_error, fixed.steps, adaptive.steps);
    EXPECT_GE(adaptive.located, 1);
    // Before the contact the motion is free, so the extrapolated instant is exact (the step
    // lands 1e-9 of a step short of it).
    EXPECT_NEAR(adaptive_onset, 0.0, 1e-10);
    // The exact separation lies between the last step with force and the next one.
    const double separation = 0.02 + contact_time;
    EXPECT_LE(adaptive.last_force, separation + 1e-9);
    EXPECT_GE(adaptive.last_contact, separation - 1e-9);
    // The contact is resolved by the error control: rebound and peak force close to exact
    // (the peak is sampled by the steps, so within the steps' resolution of a half sine).
    EXPECT_NEAR(adaptive.rebound, 1.0, 2e-3);
    EXPECT_NEAR(peak_error, 0.0, 1e-2);
  }
}

// Free vibration, T = 1 s: the error control keeps the phase error of the trapezoidal rule
// (dt^2 w^2 / 12 per radian) near its tolerance, with far fewer steps than a step fine enough
// everywhere would need... and grows the step when nothing happens.
TEST(AdaptiveStepping, KeepsAFreeVibrationAccurateAndGrowsTheStep) {
  const double omega = 2.0 * kPi;
  Oscillator system(1.0, 0.0, omega * omega);
  integrators::Newmark newmark = integrators::Newmark::average_acceleration();
  integrators::TransientSettings settings{.time_step = 1e-3, .end_time = 5.0};
  settings.adaptive = integrators::AdaptiveStepping{.tolerance = 1e-5, .max_time_step = 0.1};
  integrators::TransientAnalysis analysis(system, newmark, settings);
  integrators::State state;
  state.velocity = Vector::Constant(1, omega);  // u = sin(w t)
  double worst = 0.0;
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    worst = std::max(worst, std::abs(s.displacement[0] - std::sin(omega * s.time)));
  });
  const integrators::TransientStatistics& stats = analysis.statistics();
  std::cout << fmt::format(
      "free vibration: {} steps ({} rejected), dt {:.2e} .. {:.2e}, worst error {:.2e}\n",
      stats.steps, stats.rejected_steps, stats.smallest_step, stats.largest_step, worst);
  EXPECT_GT(stats.largest_step, 1e-3);  // it grew from the first step
  EXPECT_LT(stats.steps, 5000);         // fewer than the fixed 1e-3
  EXPECT_LT(worst, 0.02);
  EXPECT_NEAR(state.time, 5.0, 1e-12);
}

// Steps are the nominal step x 2^k, so a shortest step between two of them (1e-5 over 0.002:
// 0.002 / 128 = 1.56e-5 is the nearest above) was never reached: a step failing at every size
// was cut back to 1.56e-5 for ever, and a step whose error stays above the tolerance rejected for
// ever. The floor is the grid's step now: the first stops with the time, the second is accepted.
class NeverConverges final : public integrators::Integrator {
 public:
  std::string name() const override { return "never_converges"; }
  void initialize(integrators::SecondOrderSystem&, integrators::State&, double) override {}
  integrators::StepResult advance(integrators::SecondOrderSystem&, const integrators::State&,
                                  double dt, double, integrators::State&) override {
    smallest = std::min(smallest, dt);
    return {.failure = "no equilibrium"};
  }
  double smallest = INFINITY;
};

TEST(AdaptiveStepping, AShortestStepBetweenGridStepsIsReachedAndEndsTheCuts) {
  Oscillator system(1.0, 0.0, 1.0);
  NeverConverges failing;
  const integrators::AdaptiveStepping bounds{.min_time_step = 1e-5};
  integrators::TransientAnalysis cut(system, failing,
                                     {.time_step = 0.002, .end_time = 1.0, .adaptive = bounds});
  integrators::State state;
  EXPECT_THROW(cut.run(state), SolveError);
  EXPECT_EQ(failing.smallest, 0.002 / 128.0);
  EXPECT_EQ(bounds.shortest(0.002), 0.002 / 128.0);
  EXPECT_EQ(bounds.longest(0.002), 0.002 * 16.0);

  // A tolerance no step meets: every step rejected down to the floor, and accepted there. Also
  // when the run ends a sliver past a whole number of floor steps: its last step, the floor and
  // the sliver, cannot be shortened either (it was rejected and retried for ever).
  integrators::Newmark newmark = integrators::Newmark::average_acceleration();
  const integrators::AdaptiveStepping strict{.tolerance = 1e-300, .min_time_step = 1e-5};
  for (const double end : {0.01, 0.01 + 1e-8}) {
    integrators::TransientAnalysis rejected(
        system, newmark, {.time_step = 0.002, .end_time = end, .adaptive = strict});
    integrators::State moving;
    moving.displacement = Vector::Constant(1, 1.0);
    const integrators::TransientStatistics stats = rejected.run(moving);
    std::cout << stats.steps << " steps, " << stats.rejected_steps << " rejected, smallest "
              << stats.smallest_step << ", largest " << stats.largest_step << "\n";
    EXPECT_NEAR(stats.smallest_step, 0.002 / 128.0, 1e-12 * 0.002);
    EXPECT_GT(stats.rejected_steps, 0);
    EXPECT_NEAR(moving.time, end, 1e-12);
  }
}

}  // namespace
}  // namespace pound
