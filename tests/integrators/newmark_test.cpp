// Newmark on a one-DOF oscillator against closed forms.
#include "integrators/newmark.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "integrators/integrator_catalog.hpp"
#include "integrators/transient_analysis.hpp"
#include "links/bilinear_spring.hpp"
#include "links/elastic_spring.hpp"
#include "links/gap_spring.hpp"
#include "links/hard_contact.hpp"
#include "links/hertz_damp.hpp"
#include "links/stiffness_damping.hpp"
#include "support/chain.hpp"
#include "support/free_masses.hpp"
#include "support/oscillator.hpp"

namespace pound {
namespace {

using testing::Oscillator;
constexpr double kPi = std::numbers::pi;

// Free vibration: the average-acceleration rule reproduces u(t) = cos(w~ t) exactly at the steps,
// with the discrete frequency w~ dt = 2 atan(w dt / 2) (no amplitude decay).
TEST(Newmark, AverageAccelerationMatchesItsExactDiscreteSolution) {
  const double mass = 2.0, stiffness = 50.0, omega = std::sqrt(stiffness / mass), dt = 0.05;
  Oscillator system(mass, 0.0, stiffness);
  integrators::Newmark newmark = integrators::Newmark::average_acceleration();
  integrators::TransientAnalysis analysis(system, newmark, {.time_step = dt, .end_time = 10.0});
  integrators::State state;
  state.displacement = Vector::Constant(1, 1.0);
  state.velocity = Vector::Zero(1);
  const double discrete = 2.0 * std::atan(omega * dt / 2.0) / dt;
  double worst = 0.0;
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    worst = std::max(worst, std::abs(s.displacement[0] - std::cos(discrete * s.time)));
  });
  std::cout << "max |u - cos(w~ t)| = " << worst << "\n";
  EXPECT_LT(worst, 1e-11);
}

// Damped, harmonically forced oscillator against the closed-form response; the error must fall
// as dt^2 (second order), measured between dt and dt/2.
double forced_error(const integrators::Newmark& prototype, double dt) {
  const double mass = 1.0, stiffness = 40.0, zeta = 0.05;
  const double omega = std::sqrt(stiffness / mass), damping = 2.0 * zeta * omega * mass;
  const double force_amplitude = 3.0, forcing = 4.0;
  Oscillator system(mass, damping, stiffness, integrators::LinkSet(1),
                    [&](double t) { return force_amplitude * std::sin(forcing * t); });
  // Steady state X sin(W t - phi) plus the free part fitted to u(0) = v(0) = 0.
  const double r = forcing / omega;
  const double amplitude = force_amplitude / stiffness /
                           std::sqrt((1 - r * r) * (1 - r * r) + (2 * zeta * r) * (2 * zeta * r));
  const double phase = std::atan2(2 * zeta * r, 1 - r * r);
  const double omega_d = omega * std::sqrt(1 - zeta * zeta);
  const double a = amplitude * std::sin(phase);
  const double b = (zeta * omega * a - amplitude * forcing * std::cos(phase)) / omega_d;
  auto exact = [&](double t) {
    return amplitude * std::sin(forcing * t - phase) +
           std::exp(-zeta * omega * t) * (a * std::cos(omega_d * t) + b * std::sin(omega_d * t));
  };
  integrators::Newmark newmark = prototype;
  integrators::TransientAnalysis analysis(system, newmark, {.time_step = dt, .end_time = 4.0});
  integrators::State state;
  double worst = 0.0;
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    worst = std::max(worst, std::abs(s.displacement[0] - exact(s.time)));
  });
  return worst;
}

TEST(Newmark, ForcedDampedOscillatorConvergesAtSecondOrder) {
  for (const integrators::Newmark& method :
       {integrators::Newmark::average_acceleration(), integrators::Newmark::linear_acceleration(),
        integrators::Newmark::hht(-0.1), integrators::Newmark::generalized_alpha(0.8),
        integrators::Newmark::generalized_alpha(0.0)}) {
    const double coarse = forced_error(method, 0.01), fine = forced_error(method, 0.005);
    const double order = std::log2(coarse / fine);
    std::cout << method.name() << ": error(dt=0.01) = " << coarse << ", error(dt=0.005) = " << fine
              << ", observed order " << order << "\n";
    EXPECT_NEAR(order, 2.0, 0.1);
    EXPECT_LT(fine, 5e-4);  // rho_inf = 0 trades accuracy for damping: 2.8e-4
  }
}

// At omega dt -> infinity the alpha methods damp a free vibration by their spectral radius per
// step: rho_inf for generalised-alpha, (1 + alpha) / (1 - alpha) for HHT. (Their two roots meet
// there, so u_k ~ (a + b k) rho^k ~ b k rho^k: the rate is that of u_k / k, steps 100 to 200.)
TEST(Newmark, AlphaMethodsDampTheHighestModesAtTheirSpectralRadius) {
  struct Case {
    integrators::Newmark method;
    double radius;
  };
  for (const Case& c : {Case{integrators::Newmark::generalized_alpha(0.5), 0.5},
                        Case{integrators::Newmark::generalized_alpha(0.8), 0.8},
                        Case{integrators::Newmark::hht(-0.1), 0.9 / 1.1},
                        Case{integrators::Newmark::hht(-1.0 / 3.0), 0.5}}) {
    Oscillator system(1.0, 0.0, 1.0e12);  // omega dt = 1e6 with dt = 1
    integrators::Newmark newmark = c.method;
    integrators::TransientAnalysis analysis(system, newmark, {.time_step = 1.0, .end_time = 200.0});
    integrators::State state;
    state.displacement = Vector::Constant(1, 1.0);
    std::vector<double> u;
    analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
      u.push_back(std::abs(s.displacement[0]));
    });
    const double rate = std::pow((u[200] / 200.0) / (u[100] / 100.0), 1.0 / 100.0);
    std::cout << newmark.name() << ": decay per step " << rate << ", spectral radius " << c.radius
              << "\n";
    EXPECT_NEAR(rate / c.radius, 1.0, 0.01);
  }
}

// Newmark with beta < gamma / 2 is stable only up to the catalog's omega dt = 1 / sqrt(gamma / 2 -
// beta) (linear acceleration: 2 sqrt(3)), the limit the builder refuses steps past: a free
// vibration at 0.99 of it keeps its amplitude, at 1.01 of it grows without bound.
TEST(Newmark, ConditionallyStableVariantsHoldBelowTheirCatalogLimitOnly) {
  struct Case {
    double beta, gamma;
  };
  for (const Case& c : {Case{1.0 / 6.0, 0.5}, Case{0.1, 0.5}, Case{0.2, 0.6}}) {
    const integrators::IntegratorChoice choice(integrators::Newmark::newmark_entry(),
                                               {{"beta", c.beta}, {"gamma", c.gamma}});
    const std::optional<double> limit = choice.stability_limit();
    ASSERT_TRUE(limit);
    EXPECT_NEAR(*limit, 1.0 / std::sqrt(0.5 * c.gamma - c.beta), 1e-15);
    const auto largest_after = [&](double omega_dt) {
      Oscillator system(1.0, 0.0, omega_dt * omega_dt);  // omega dt as given with dt = 1
      integrators::Newmark newmark(c.beta, c.gamma);
      integrators::TransientAnalysis analysis(system, newmark,
                                              {.time_step = 1.0, .end_time = 3000.0});
      integrators::State state;
      state.displacement = Vector::Constant(1, 1.0);
      double largest = 0.0;
      analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
        largest = std::max(largest, std::abs(s.displacement[0]));
      });
      return largest;
    };
    const double below = largest_after(0.99 * *limit), above = largest_after(1.01 * *limit);
    std::cout << "beta " << c.beta << ", gamma " << c.gamma << ": limit " << *limit
              << ", largest |u| over 3000 steps at 0.99 of it " << below << ", at 1.01 " << above
              << "\n";
    EXPECT_LT(below, 10.0);
    EXPECT_GT(above, 1e6);
  }
  EXPECT_FALSE(
      integrators::IntegratorChoice::preset("newmark_average_acceleration").stability_limit());
  EXPECT_FALSE(integrators::IntegratorChoice::preset("hht").stability_limit());
  EXPECT_EQ(integrators::IntegratorChoice::preset("central_difference").stability_limit(), 2.0);
}

// A mass hitting a rigid wall through a gap spring: while in contact it is a half cycle of a
// linear oscillator, so the contact lasts pi sqrt(m/k) and the rebound is elastic (e = 1).
TEST(Newmark, GapSpringAgainstRigidWallGivesHalfCycleContact) {
  const double mass = 1.0, wall_stiffness = 1.0e4, speed = 0.5, gap = 0.01;
  std::vector<std::unique_ptr<links::LinkLaw>> laws;
  laws.push_back(std::make_unique<links::GapSpring>(wall_stiffness));
  integrators::LinkSet links(1, {{{0, 1.0}}}, {gap}, std::move(laws));
  Oscillator system(mass, 0.0, 0.0, std::move(links));
  const double contact_time = kPi * std::sqrt(mass / wall_stiffness);
  const double dt = contact_time / 2000.0;
  integrators::Newmark newmark = integrators::Newmark::average_acceleration();
  integrators::TransientAnalysis analysis(system, newmark, {.time_step = dt, .end_time = 0.1});
  integrators::State state;
  state.velocity = Vector::Constant(1, speed);
  double first_contact = -1, last_contact = -1, peak_force = 0;
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    if (s.link_force[0] > 0) {
      if (first_contact < 0) first_contact = s.time;
      last_contact = s.time;
      peak_force = std::max(peak_force, s.link_force[0]);
    }
  });
  const double rebound = -state.velocity[0] / speed;
  const double duration_error = (last_contact - first_contact) / contact_time - 1.0;
  const double peak_error = peak_force / (speed * std::sqrt(wall_stiffness * mass)) - 1.0;
  std::cout << "restitution " << rebound << ", duration error " << duration_error
            << ", peak force error " << peak_error << "\n";
  EXPECT_NEAR(rebound, 1.0, 1e-3);
  // The contact is resolved to dt = T/2000 at each end: 2 steps out of 2000.
  EXPECT_NEAR(duration_error, 0.0, 2e-3);
  EXPECT_NEAR(peak_error, 0.0, 1e-3);
}

}  // namespace
}  // namespace pound

namespace pound {
namespace {

using testing::FreeMassPair;
using testing::hard_contact_row;

std::vector<integrators::Newmark> implicit_methods() {
  return {integrators::Newmark::average_acceleration(), integrators::Newmark::hht(-0.1),
          integrators::Newmark::generalized_alpha(0.5)};
}

// Masses 1 and 3 closing at 3 through a hard contact, first touch at several phases of a step,
// under each implicit method: the impact law holds at velocity level, so afterwards their
// velocities are the rigid-body impulse solution with Newton's e and the pair has lost exactly
// (1 - e^2) of 1/2 m_eff w^2, whatever the phase; the overlap left is under w dt / 2.
TEST(Newmark, HardContactGivesTheRigidImpulseSolution) {
  const double m0 = 1.0, m1 = 3.0, v0 = 2.0, v1 = -1.0, dt = 1e-3;
  const double closing = v0 - v1, effective = m0 * m1 / (m0 + m1);
  for (const integrators::Newmark& method : implicit_methods()) {
    double worst_velocity = 0.0, worst_energy = 0.0, deepest = 0.0;
    for (const double e : {0.0, 0.3, 0.7, 1.0})
      for (const double phase : {0.0, 0.25, 0.5, 0.9}) {
        const double gap = closing * dt * (3.0 + phase);
        FreeMassPair system(m0, m1, hard_contact_row({{0, 1.0}, {1, -1.0}}, gap, e));
        integrators::Newmark newmark = method;
        integrators::TransientAnalysis analysis(system, newmark,
                                                {.time_step = dt, .end_time = 20.0 * dt});
        integrators::State state;
        state.displacement = Vector::Zero(2);
        state.velocity = Vector{{v0, v1}};
        analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
          deepest = std::max(deepest, s.link_penetration[0]);
        });
        const double exact_0 = (m0 * v0 + m1 * v1 - m1 * e * closing) / (m0 + m1);
        const double exact_1 = (m0 * v0 + m1 * v1 + m0 * e * closing) / (m0 + m1);
        worst_velocity = std::max({worst_velocity, std::abs(state.velocity[0] - exact_0),
                                   std::abs(state.velocity[1] - exact_1)});
        const double lost = 0.5 * (m0 * v0 * v0 + m1 * v1 * v1) -
                            0.5 * (m0 * state.velocity[0] * state.velocity[0] +
                                   m1 * state.velocity[1] * state.velocity[1]);
        const double expected = (1.0 - e * e) * 0.5 * effective * closing * closing;
        worst_energy = std::max(worst_energy, std::abs(lost - expected) / (0.5 * effective * 9.0));
      }
    std::cout << method.name() << ": largest velocity error " << worst_velocity
              << ", energy loss error " << worst_energy << " of the approach energy, deepest "
              << "overlap " << deepest << " (w dt / 2 = " << 0.5 * closing * dt << ")\n";
    EXPECT_LT(worst_velocity, 1e-12) << method.name();
    EXPECT_LT(worst_energy, 1e-12) << method.name();
    EXPECT_LE(deepest, 0.5 * closing * dt * (1.0 + 1e-12)) << method.name();
  }
}

// A mass pushed by a constant force into a rigid wall (the link's other end fixed), e = 0: it
// stops at the impact and stays, and the contact's force is the push (no alternation from step to
// step, which a bound on the position alone gives under the trapezoidal rule): at every step after
// the impact with average acceleration. The alpha methods hold the position, but their u, v, a
// relation is not the trapezoid's: a transient of the force that has fallen under 1 % of the push
// 100 steps later, and a rate left of O(dt |a| (gamma - 1/2)) (under 2e-4 of the approach speed
// here). e = 1 sends the mass back at the speed it came.
TEST(Newmark, HardContactAgainstAWallHoldsOrBounces) {
  const double mass = 2.0, velocity = 0.5, push = 3.0, dt = 1e-3, gap = velocity * dt * 2.6;
  for (const integrators::Newmark& method : implicit_methods())
    for (const double e : {0.0, 1.0}) {
      testing::Oscillator system(mass, 0.0, 0.0, hard_contact_row({{0, 1.0}}, gap, e),
                                 [&](double) { return e == 0.0 ? push : 0.0; });
      integrators::Newmark newmark = method;
      integrators::TransientAnalysis analysis(system, newmark,
                                              {.time_step = dt, .end_time = 200.0 * dt});
      integrators::State state;
      state.displacement = Vector::Zero(1);
      state.velocity = Vector::Constant(1, velocity);
      double worst_hold = 0.0, deepest = -1.0;
      int pressed_steps = 0;
      analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
        deepest = std::max(deepest, s.link_penetration[0]);
        const bool trapezoidal = method.gamma() == 0.5 && method.alpha_f() == 0.0;
        if (s.time > (trapezoidal ? 6.0 : 100.0) * dt && e == 0.0) {
          worst_hold = std::max(worst_hold, std::abs(s.link_force[0] - push));
          ++pressed_steps;
        }
      });
      std::cout << method.name() << ", e = " << e << ": velocity " << state.velocity[0]
                << ", force " << state.link_force[0] << ", largest |F - push| after the impact "
                << worst_hold << ", deepest overlap " << deepest << "\n";
      EXPECT_LE(deepest, 0.5 * velocity * dt * (1.0 + 1e-12));
      if (e == 0.0) {
        const bool trapezoidal = method.gamma() == 0.5 && method.alpha_f() == 0.0;
        EXPECT_NEAR(state.velocity[0], 0.0, (trapezoidal ? 1e-12 : 2e-4) * velocity)
            << method.name();
        EXPECT_GT(pressed_steps, 90);
        EXPECT_LT(worst_hold, (trapezoidal ? 1e-9 : 1e-2) * push) << method.name();
      } else {
        EXPECT_NEAR(state.velocity[0], -velocity, 1e-12) << method.name();
      }
    }
}

// A link row on a linear branch is folded into the factored matrix (integrators/newmark.hpp): a
// linear spring, with or without a dashpot, then takes no Newton iteration (the first gives the
// oscillator with its stiffness added, to round-off); one that yields gives the response of the
// unfolded iteration to within its tolerance, in fewer iterations.
TEST(Newmark, FoldedLinkRowsGiveTheUnfoldedResponse) {
  using LawMaker = std::function<std::unique_ptr<links::LinkLaw>()>;
  const std::vector<std::pair<std::string, LawMaker>> laws = {
      {"elastic spring", [] { return std::make_unique<links::ElasticSpring>(30.0); }},
      {"spring with a dashpot",
       [] {
         return std::make_unique<links::StiffnessDamping>(
             std::make_unique<links::ElasticSpring>(30.0), 0.01, links::DampingStiffness::initial);
       }},
      {"bilinear spring", [] { return std::make_unique<links::BilinearSpring>(30.0, 2.0, 0.1); }}};
  const auto load = [](double t) { return 5.0 * std::sin(3.0 * t); };
  struct Run {
    std::vector<double> displacement, force;
    long iterations = 0;
  };
  const auto run = [&](const LawMaker& law, bool fold) {
    std::vector<std::unique_ptr<links::LinkLaw>> link_laws;
    link_laws.push_back(law());
    Oscillator system(1.0, 0.2, 10.0,
                      integrators::LinkSet(1, {{{0, 1.0}}}, {0.0}, std::move(link_laws)), load);
    system.set_folds_links(fold);
    integrators::Newmark newmark = integrators::Newmark::average_acceleration();
    integrators::TransientAnalysis analysis(system, newmark, {.time_step = 0.01, .end_time = 10.0});
    integrators::State state;
    Run result;
    result.iterations = analysis
                            .run(state,
                                 [&](const integrators::State& s, const integrators::StepResult&) {
                                   result.displacement.push_back(s.displacement[0]);
                                   result.force.push_back(s.link_force[0]);
                                 })
                            .newton_iterations;
    return result;
  };
  const auto largest_difference = [](const std::vector<double>& a, const std::vector<double>& b) {
    double difference = 0.0, scale = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      difference = std::max(difference, std::abs(a[k] - b[k]));
      scale = std::max(scale, std::abs(b[k]));
    }
    return difference / scale;
  };
  for (const auto& [name, law] : laws) {
    const Run folded = run(law, true), unfolded = run(law, false);
    ASSERT_EQ(folded.displacement.size(), unfolded.displacement.size());
    const double displacement = largest_difference(folded.displacement, unfolded.displacement);
    const double force = largest_difference(folded.force, unfolded.force);
    std::cout << name << ": Newton iterations " << folded.iterations << " folded, "
              << unfolded.iterations << " unfolded; relative differences u " << displacement
              << ", F " << force << "\n";
    EXPECT_LE(displacement, 1e-9) << name;
    EXPECT_LE(force, 1e-9) << name;
    EXPECT_LT(folded.iterations, unfolded.iterations) << name;
    if (name != "bilinear spring") {
      EXPECT_EQ(folded.iterations, 0) << name;
    }
  }
  // The linear spring: no iteration, and the oscillator with k = 10 + 30 (no link).
  const Run folded = run(laws[0].second, true);
  EXPECT_EQ(folded.iterations, 0);
  Oscillator plain(1.0, 0.2, 40.0, integrators::LinkSet(1), load);
  integrators::Newmark newmark = integrators::Newmark::average_acceleration();
  integrators::TransientAnalysis analysis(plain, newmark, {.time_step = 0.01, .end_time = 10.0});
  integrators::State state;
  std::vector<double> expected;
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    expected.push_back(s.displacement[0]);
  });
  const double error = largest_difference(folded.displacement, expected);
  std::cout << "linear spring folded against k = 40 without a link: " << error << "\n";
  EXPECT_LE(error, 1e-13);
}

// A chain of 11 masses under a load with a yielding bilinear spring (folded: its predicted
// unknown starts each step inside the linear solve) and a Hertz contact between masses (not
// folded), by the step for a lumped mass (predictors, M, f and Rayleigh's a0 M in one pass, a1 K x
// by the shift S x, no product by K) and by the general one (products by M and C): the same
// response to round-off, over a run in which the spring yields and the contact closes. Once with
// one a0, a1 for all, once cut in two structures damped each with its own, which the spring joins
// (so S, by DOF, does not commute with its folded row: the shift's L S x term).
struct LumpedAgainstGeneral {
  Matrix displacement;
  std::vector<double> spring, contact;
  long iterations = 0;
};

LumpedAgainstGeneral run_chain(bool lumped, bool split, const integrators::Newmark& preset) {
  using testing::Chain;
  std::vector<std::unique_ptr<links::LinkLaw>> laws;
  laws.push_back(std::make_unique<links::BilinearSpring>(200.0, 0.5, 0.05));
  laws.push_back(std::make_unique<links::HertzDamp>(1e5, 0.2));
  Chain chain(11, Chain::Damping::rayleigh,
              integrators::LinkSet(11, {{{2, 1.0}, {6, -1.0}}, {{8, 1.0}, {9, -1.0}}}, {0.0, 0.002},
                                   std::move(laws)),
              20.0);
  if (split) chain.split(5, 0.05, 0.01);
  chain.set_lumped(lumped);
  integrators::Newmark newmark = preset;
  integrators::TransientAnalysis analysis(chain, newmark, {.time_step = 0.005, .end_time = 3.0});
  integrators::State state;
  LumpedAgainstGeneral result;
  result.displacement = Matrix::Zero(11, 601);
  Index step = 0;
  result.iterations = analysis
                          .run(state,
                               [&](const integrators::State& s, const integrators::StepResult&) {
                                 result.displacement.col(step++) = s.displacement;
                                 result.spring.push_back(s.link_force[0]);
                                 result.contact.push_back(s.link_force[1]);
                               })
                          .newton_iterations;
  return result;
}

void expect_lumped_as_general(bool split, const integrators::Newmark& preset) {
  const LumpedAgainstGeneral lumped = run_chain(true, split, preset);
  const LumpedAgainstGeneral general = run_chain(false, split, preset);
  const double displacement = (lumped.displacement - general.displacement).cwiseAbs().maxCoeff() /
                              general.displacement.cwiseAbs().maxCoeff();
  double spring_yielded = 0.0, contact_peak = 0.0, force = 0.0;
  for (std::size_t k = 0; k < general.spring.size(); ++k) {
    spring_yielded = std::max(spring_yielded, std::abs(general.spring[k]));
    contact_peak = std::max(contact_peak, general.contact[k]);
    force = std::max({force, std::abs(lumped.spring[k] - general.spring[k]),
                      std::abs(lumped.contact[k] - general.contact[k])});
  }
  std::cout << preset.name() << (split ? ", two structures: " : ", one structure: ")
            << "Newton iterations " << lumped.iterations << " lumped, " << general.iterations
            << " general; relative differences u " << displacement << ", link forces "
            << force / std::max(spring_yielded, contact_peak) << "; peak spring force "
            << spring_yielded << " (yield 0.5), peak contact force " << contact_peak << "\n";
  EXPECT_GT(spring_yielded, 0.5);
  EXPECT_GT(contact_peak, 0.0);
  EXPECT_LE(displacement, 1e-10);
  // Round-off that the stiff contact amplifies: a load changed by one ulp moves the general
  // path's forces by as much over the run.
  EXPECT_LE(force, 1e-9 * std::max(spring_yielded, contact_peak));
}

TEST(Newmark, ALumpedRayleighStepGivesTheGeneralStepsResponse) {
  expect_lumped_as_general(false, integrators::Newmark::average_acceleration());
}

// One step of the two damped structures (no links) from a random state, by the lumped step (its
// shift S x for a1 K x) and the general one, against the same step in long double: u within 4
// ulps of the exact step's, a (= c_m (u - u~), which cancels) within what 4 ulps of u make of it.
// Measured: u 0.3-1.5 ulps on both paths at dt = 5, 1.5 and 0.5 ms.
TEST(Newmark, ALumpedRayleighStepIsExactToRoundOff) {
  using testing::Chain;
  using LongMatrix = Eigen::Matrix<long double, -1, -1>;
  using LongVector = Eigen::Matrix<long double, -1, 1>;
  const long double eps = std::numeric_limits<double>::epsilon();
  for (const double dt : {0.005, 0.0015, 0.0005}) {
    Chain chain(11, Chain::Damping::rayleigh, integrators::LinkSet(11), 20.0);
    chain.split(5, 0.05, 0.01);
    integrators::State from;
    from.time = 0.3;
    from.displacement = Vector::Random(11);
    from.velocity = 10.0 * Vector::Random(11);
    from.acceleration = 100.0 * Vector::Random(11);
    const auto matrix_of = [](const auto& product) {
      Matrix columns(11, 11);
      Vector column;
      for (Index i = 0; i < 11; ++i) {
        product(Vector::Unit(11, i), column);
        columns.col(i) = column;
      }
      return LongMatrix(columns.cast<long double>());
    };
    const LongMatrix m = matrix_of([&](const Vector& x, Vector& y) { chain.multiply_mass(x, y); });
    const LongMatrix k =
        matrix_of([&](const Vector& x, Vector& y) { chain.multiply_stiffness(x, y); });
    const LongMatrix c =
        matrix_of([&](const Vector& x, Vector& y) { chain.multiply_damping(x, y); });
    const long double step = dt, c_m = 4.0L / (step * step), c_c = 2.0L / step;
    const LongVector u = from.displacement.cast<long double>();
    const LongVector predicted_u = u + step * from.velocity.cast<long double>() +
                                   0.25L * step * step * from.acceleration.cast<long double>();
    const LongVector predicted_v =
        from.velocity.cast<long double>() + 0.5L * step * from.acceleration.cast<long double>();
    Vector load;
    chain.external_force(from.time + dt, load);
    const LongVector exact =
        (c_m * m + c_c * c + k)
            .fullPivLu()
            .solve(c_m * m * predicted_u + c * (c_c * predicted_u - predicted_v) +
                   load.cast<long double>());
    const LongVector exact_acceleration = c_m * (exact - predicted_u);
    const long double u_scale = exact.cwiseAbs().maxCoeff();
    const long double a_scale = exact_acceleration.cwiseAbs().maxCoeff();
    for (const bool lumped : {true, false}) {
      chain.set_lumped(lumped);
      integrators::Newmark newmark = integrators::Newmark::average_acceleration();
      integrators::State start = from, to;
      newmark.initialize(chain, start, dt);
      newmark.advance(chain, from, dt, from.time + dt, to);
      const long double u_error =
          (to.displacement.cast<long double>() - exact).cwiseAbs().maxCoeff() / u_scale / eps;
      const long double a_error =
          (to.acceleration.cast<long double>() - exact_acceleration).cwiseAbs().maxCoeff() /
          (c_m * eps * u_scale);
      std::cout << "dt " << dt << (lumped ? " lumped" : " general") << ": u "
                << static_cast<double>(u_error) << " ulps, a " << static_cast<double>(a_error)
                << " x c_m ulp(u) (|a| " << static_cast<double>(a_scale) << ")\n";
      EXPECT_LE(u_error, 4.0L) << dt << " " << lumped;
      EXPECT_LE(a_error, 4.0L) << dt << " " << lumped;
    }
  }
}

// The same by generalised-alpha too, whose history term joins the shifted right-hand side.
TEST(Newmark, ALumpedStepWithEachStructuresRayleighGivesTheGeneralStepsResponse) {
  expect_lumped_as_general(true, integrators::Newmark::average_acceleration());
  expect_lumped_as_general(true, integrators::Newmark::generalized_alpha(0.8));
}

}  // namespace
}  // namespace pound
