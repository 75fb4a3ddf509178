// Step cutting and loud failure of the transient driver, on a one-DOF system.
#include "integrators/transient_analysis.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <set>
#include <thread>
#include <vector>

#include "core/errors.hpp"
#include "integrators/central_difference.hpp"
#include "integrators/newmark.hpp"
#include "support/oscillator.hpp"

namespace pound {
namespace {

// F = k delta^3 in contact, but reporting a zero tangent: Newton becomes the fixed-point
// iteration F <- F(delta_lin - G F), which converges only while |3 k delta^2 G| < 1, and
// G = beta dt^2 / m shrinks with the step. So large steps fail and cut steps succeed.
class CubicWithoutTangent final : public links::LinkLaw {
 public:
  explicit CubicWithoutTangent(double stiffness) : stiffness_(stiffness) {}
  std::string name() const override { return "cubic_without_tangent"; }
  std::unique_ptr<links::LinkLaw> clone() const override {
    return std::make_unique<CubicWithoutTangent>(*this);
  }
  links::LawResponse set_trial(const links::LinkKinematics& trial) override {
    const double delta = std::max(0.0, trial.penetration);
    return {.force = stiffness_ * delta * delta * delta};
  }
  void commit() override {}
  void revert() override {}
  bool in_contact() const override { return false; }

 private:
  double stiffness_;
};

// A law whose force is NaN once it is in contact (a model gone wrong).
class Poisoned final : public links::LinkLaw {
 public:
  std::string name() const override { return "poisoned"; }
  std::unique_ptr<links::LinkLaw> clone() const override { return std::make_unique<Poisoned>(); }
  links::LawResponse set_trial(const links::LinkKinematics& trial) override {
    if (trial.penetration <= 0.0) return {};
    return {.force = std::numeric_limits<double>::quiet_NaN(), .stiffness = 1.0};
  }
  void commit() override {}
  void revert() override {}
  bool in_contact() const override { return false; }
};

testing::Oscillator mass_against_wall(std::unique_ptr<links::LinkLaw> law) {
  std::vector<std::unique_ptr<links::LinkLaw>> laws;
  laws.push_back(std::move(law));
  return testing::Oscillator(1.0, 0.0, 0.0,
                             integrators::LinkSet(1, {{{0, 1.0}}}, {0.0}, std::move(laws)));
}

// A unit mass at 1 m/s into a wall of CubicWithoutTangent(1e14), average acceleration at a tight
// tolerance, steps of 1 ms to 0.02 s: too large for the fixed-point iteration once in contact,
// so the run succeeds only by cutting steps, at most `max_step_cuts` times each.
struct CubicWallImpact {
  explicit CubicWallImpact(int max_step_cuts)
      : analysis(system, newmark,
                 {.time_step = 1e-3, .end_time = 0.02, .max_step_cuts = max_step_cuts}) {
    state.velocity = Vector::Constant(1, 1.0);
  }
  testing::Oscillator system = mass_against_wall(std::make_unique<CubicWithoutTangent>(1.0e14));
  integrators::Newmark newmark = integrators::Newmark::average_acceleration(
      {.relative_tolerance = 1e-10, .max_iterations = 30});
  integrators::TransientAnalysis analysis;
  integrators::State state;
};

TEST(TransientAnalysis, CutsStepsThatDoNotConvergeAndFinishes) {
  CubicWallImpact impact(12);
  integrators::State& state = impact.state;
  // Every accepted step, cut or not, satisfied m a = -F; with gamma = 1/2 the velocity is the
  // trapezoidal integral of the acceleration, so the impulse of the recorded forces must equal
  // the momentum change to rounding.
  double impulse = 0.0, previous_time = 0.0, previous_force = 0.0, peak_force = 0.0;
  const integrators::TransientStatistics stats =
      impact.analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
        impulse += 0.5 * (s.link_force[0] + previous_force) * (s.time - previous_time);
        previous_time = s.time;
        previous_force = s.link_force[0];
        peak_force = std::max(peak_force, s.link_force[0]);
      });
  const double momentum_error = std::abs((1.0 - state.velocity[0]) - impulse) / impulse;
  std::cout << "step cuts " << stats.step_cuts << ", steps " << stats.steps << ", impulse "
            << impulse << ", momentum error " << momentum_error << ", rebound velocity "
            << state.velocity[0] << "\n";
  EXPECT_GT(stats.step_cuts, 0);
  EXPECT_NEAR(state.time, 0.02, 1e-12);
  EXPECT_LT(momentum_error, 1e-9);
  // An impact resolved by a few cut steps is coarse (energy is not conserved to better than
  // tens of per cent), but it is an impact: the mass comes back.
  EXPECT_LT(state.velocity[0], -0.8);
  EXPECT_GT(peak_force, 0.0);
}

TEST(TransientAnalysis, FailsLoudlyWithTimeAndReasonWhenCuttingIsNotEnough) {
  CubicWallImpact impact(0);
  try {
    impact.analysis.run(impact.state);
    FAIL() << "an unconverged step was accepted";
  } catch (const SolveError& error) {
    std::cout << error.what() << "\n";
    EXPECT_GE(error.time(), 0.0);
    EXPECT_LT(error.time(), 0.02);
    EXPECT_NE(std::string(error.what()).find("did not converge"), std::string::npos);
  }
}

TEST(TransientAnalysis, NonFiniteForcesStopTheRun) {
  auto system = mass_against_wall(std::make_unique<Poisoned>());
  integrators::Newmark newmark = integrators::Newmark::average_acceleration();
  integrators::TransientAnalysis analysis(system, newmark,
                                          {.time_step = 0.01, .end_time = 1.0, .max_step_cuts = 3});
  integrators::State state;
  state.velocity = Vector::Constant(1, 1.0);
  EXPECT_THROW(
      {
        try {
          analysis.run(state);
        } catch (const SolveError& error) {
          EXPECT_NE(std::string(error.what()).find("not finite"), std::string::npos)
              << error.what();
          throw;
        }
      },
      SolveError);
}

TEST(TransientAnalysis, StepLimitStopsARunawayRun) {
  testing::Oscillator system(1.0, 0.0, 1.0);
  integrators::Newmark newmark = integrators::Newmark::average_acceleration();
  integrators::TransientAnalysis analysis(system, newmark,
                                          {.time_step = 0.01, .end_time = 1.0, .max_steps = 10});
  integrators::State state;
  long recorded = 0;
  EXPECT_THROW(analysis.run(state, [&](const integrators::State&,
                                       const integrators::StepResult&) { ++recorded; }),
               SolveError);
  EXPECT_EQ(recorded, 11);  // the initial state and ten steps
}

TEST(TransientAnalysis, TimeLimitStopsARunawayRunWithTheTimeAndTheReason) {
  testing::Oscillator system(1.0, 0.0, 1.0);
  integrators::Newmark newmark = integrators::Newmark::average_acceleration();
  // 1e9 steps would take minutes; a limit of 20 ms stops it after a few thousand.
  integrators::TransientAnalysis analysis(system, newmark,
                                          {.time_step = 1e-9, .end_time = 1.0, .time_limit = 0.02});
  integrators::State state;
  try {
    analysis.run(state);
    FAIL() << "the run was not stopped";
  } catch (const SolveError& error) {
    std::cout << "error: " << error.what() << "\n";
    EXPECT_NE(std::string(error.what()).find("time limit of 0.02 s"), std::string::npos)
        << error.what();
    EXPECT_GT(error.time(), 0.0);
    EXPECT_LT(error.time(), 1.0);
    EXPECT_EQ(state.time, error.time());  // the state is the last accepted step
  }
}

// A law that costs 1 ms a trial (a Bouc-Wen law asked for an enormous move takes that long):
// once the mass 5 mm from the wall strikes it, each attempt at the 1 ms step fails after 30 slow
// iterations and is cut. The clock is read every 64 accepted steps, and at every attempt of a
// cut step: the run stops at the first cut after the limit, with the last accepted state before
// the contact, not 64 steps later.
class SlowCubic final : public links::LinkLaw {
 public:
  std::string name() const override { return "slow_cubic"; }
  std::unique_ptr<links::LinkLaw> clone() const override { return std::make_unique<SlowCubic>(); }
  links::LawResponse set_trial(const links::LinkKinematics& trial) override {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return cubic_.set_trial(trial);
  }
  void commit() override {}
  void revert() override {}
  bool in_contact() const override { return false; }

 private:
  CubicWithoutTangent cubic_{1.0e14};
};

TEST(TransientAnalysis, TimeLimitStopsASlowCutStep) {
  testing::Oscillator system = mass_against_wall(std::make_unique<SlowCubic>());
  integrators::Newmark newmark = integrators::Newmark::average_acceleration(
      {.relative_tolerance = 1e-10, .max_iterations = 30});
  integrators::TransientAnalysis analysis(
      system, newmark,
      {.time_step = 1e-3, .end_time = 1.0, .max_step_cuts = 12, .time_limit = 0.02});
  integrators::State state;
  state.displacement = Vector::Constant(1, -0.0045);
  state.velocity = Vector::Constant(1, 1.0);
  try {
    analysis.run(state);
    FAIL() << "the run was not stopped";
  } catch (const SolveError& error) {
    std::cout << "error: " << error.what() << "\n";
    EXPECT_NE(std::string(error.what()).find("time limit of 0.02 s"), std::string::npos)
        << error.what();
    EXPECT_LT(error.time(), 0.0055) << "stopped after the contact's cut step, not at it";
  }
}

TEST(TransientAnalysis, NegativeTimeLimitIsRefused) {
  testing::Oscillator system(1.0, 0.0, 1.0);
  integrators::Newmark newmark = integrators::Newmark::average_acceleration();
  EXPECT_THROW(integrators::TransientAnalysis(
                   system, newmark, {.time_step = 0.1, .end_time = 1.0, .time_limit = -1.0}),
               std::invalid_argument);
}

TEST(TransientAnalysis, EndTimeIsReachedExactlyWithoutDrift) {
  testing::Oscillator system(1.0, 0.0, 1.0);
  integrators::Newmark newmark = integrators::Newmark::average_acceleration();
  integrators::TransientAnalysis analysis(system, newmark, {.time_step = 0.1, .end_time = 1.05});
  integrators::State state;
  const integrators::TransientStatistics stats = analysis.run(state);
  EXPECT_EQ(stats.steps, 11);  // ten steps of 0.1 and a last one of 0.05
  EXPECT_EQ(state.time, 1.05);
}

// `pound check` and the memory check count a run's steps before it starts with
// fixed_step_count; the run must take exactly that many. A quotient a few ulps above a whole
// number (0.004 / 1e-6 = 4000.0000000000005) was counted one step too many.
TEST(TransientAnalysis, FixedStepCountIsTheStepsARunTakes) {
  struct Span {
    double time_step, end_time;
  };
  for (const Span span : {Span{1e-6, 0.004}, Span{0.1, 1.05}, Span{0.1, 0.3}, Span{0.0015, 25.0},
                          Span{0.01, 0.07}, Span{1e-3, 1.0}, Span{0.3, 0.9}, Span{0.002, 30.0}}) {
    testing::Oscillator system(1.0, 0.0, 1.0);
    integrators::Newmark newmark = integrators::Newmark::average_acceleration();
    integrators::TransientAnalysis analysis(
        system, newmark, {.time_step = span.time_step, .end_time = span.end_time});
    integrators::State state;
    const long counted =
        static_cast<long>(integrators::fixed_step_count(span.end_time, span.time_step));
    EXPECT_EQ(analysis.run(state).steps, counted)
        << span.end_time << " / " << span.time_step << " = " << span.end_time / span.time_step;
    EXPECT_EQ(state.time, span.end_time);
  }
  EXPECT_EQ(integrators::fixed_step_count(0.004, 1e-6), 4000.0);  // 4001 by std::ceil alone
  EXPECT_EQ(integrators::fixed_step_count(1.05, 0.1), 11.0);      // ten of 0.1, one of 0.05
}

// Issue 20: the steps were the differences of their end times, which vary in their last bits
// (16 distinct values over the bundled bridge's 16,667 steps), and the implicit integrators
// made a factorisation for each. Every step is now the nominal dt exactly, cut steps its exact
// halves, and the recorded times are still k dt without drift.
class StepSizeSpy final : public integrators::Integrator {
 public:
  std::string name() const override { return newmark.name(); }
  void initialize(integrators::SecondOrderSystem& system, integrators::State& state,
                  double first_step) override {
    newmark.initialize(system, state, first_step);
  }
  integrators::StepResult advance(integrators::SecondOrderSystem& system,
                                  const integrators::State& from, double dt, double end,
                                  integrators::State& to) override {
    steps.insert(dt);
    return newmark.advance(system, from, dt, end, to);
  }
  integrators::Newmark newmark = integrators::Newmark::average_acceleration();
  std::set<double> steps;
};

TEST(TransientAnalysis, EveryStepIsTheNominalStepExactly) {
  testing::Oscillator system(1.0, 0.05, 40.0);
  StepSizeSpy spy;
  integrators::TransientAnalysis analysis(system, spy, {.time_step = 0.0015, .end_time = 25.0});
  integrators::State state;
  state.displacement = Vector::Constant(1, 1.0);
  std::vector<double> times;
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    times.push_back(s.time);
  });
  std::cout << "distinct step sizes: " << spy.steps.size() << "\n";
  // 16,666 steps of 0.0015 and a last one of 0.001.
  EXPECT_EQ(spy.steps.size(), 2u);
  EXPECT_EQ(*spy.steps.rbegin(), 0.0015);
  ASSERT_EQ(times.size(), 16668u);
  for (std::size_t k = 1; k + 1 < times.size(); ++k)
    ASSERT_EQ(times[k], static_cast<double>(k) * 0.0015) << k;
  EXPECT_EQ(times.back(), 25.0);
}

// The loads of a step are taken at the time the step is reported at, its grid time k dt: they
// were taken at from.time + dt, which differs from k dt in its last bit at about a third of the
// steps, so the load the step carried was not the load at its state's time (and the observers,
// which read f at the state's time, formed it a second time).
TEST(TransientAnalysis, EachStepsLoadIsTakenAtTheTimeItIsReportedAt) {
  std::vector<double> asked;
  const auto force = [&](double time) {
    asked.push_back(time);
    return std::sin(3.0 * time);
  };
  integrators::Newmark newmark = integrators::Newmark::average_acceleration();
  integrators::CentralDifference central;
  // Undamped and damped: Newmark's lumped-mass step and its general one.
  for (const auto& [integrator, damping] : std::vector<std::pair<integrators::Integrator*, double>>{
           {&newmark, 0.0}, {&newmark, 0.05}, {&central, 0.0}}) {
    testing::Oscillator system(1.0, damping, 40.0, integrators::LinkSet(1), force);
    integrators::TransientAnalysis analysis(system, *integrator,
                                            {.time_step = 0.0015, .end_time = 3.0});
    integrators::State state;
    state.displacement = Vector::Constant(1, 1.0);
    std::vector<double> reported;
    asked.clear();
    analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
      reported.push_back(s.time);
    });
    // Every load asked for is at one of the reported times.
    const std::set<double> grid(reported.begin(), reported.end());
    std::size_t off_grid = 0;
    for (double time : asked) off_grid += grid.count(time) == 0 ? 1 : 0;
    std::cout << integrator->name() << " (damping " << damping << "): " << asked.size()
              << " loads asked, " << off_grid << " off the reported times\n";
    EXPECT_GT(asked.size(), 1999u);
    EXPECT_EQ(off_grid, 0u) << integrator->name() << ", damping " << damping;
  }
}

}  // namespace
}  // namespace pound
