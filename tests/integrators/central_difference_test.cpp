// Explicit central difference: its stable step against closed forms, its order of accuracy, the
// contact-active limit of Suzuki & Toi's two-element model (eq. 4), and hard contacts against
// the rigid-body impulse solution.
#include "integrators/central_difference.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>

#include "integrators/transient_analysis.hpp"
#include "links/extended_penalty.hpp"
#include "links/hard_contact.hpp"
#include "links/viscous_damper.hpp"
#include "support/free_masses.hpp"
#include "support/oscillator.hpp"

namespace pound {
namespace {

using testing::Oscillator;

TEST(CentralDifference, StableStepOfAnOscillatorIsTwoOverOmega) {
  Oscillator system(2.0, 0.0, 800.0);  // omega = 20
  const double limit = integrators::stable_time_step(system, true);
  std::cout << "stable step " << limit << ", exact 0.1\n";
  EXPECT_NEAR(limit, 0.1, 1e-10);
  // With damping C v* (v* = v_n + dt a_n) the limit shrinks to (2 / w)(sqrt(1 + 4 z^2) - 2 z);
  // z = 0.2 here.
  Oscillator damped(2.0, 2.0 * 0.2 * 20.0 * 2.0, 800.0);
  EXPECT_NEAR(integrators::stable_time_step(damped, true), 0.1 * (std::sqrt(1.16) - 0.4), 1e-10);
}

// An oscillator damped far past critical (z = 1e9: a friction pendulum of R = 1e6 m has a
// tangent N / R of about 1 N/m beside its stick damping): the limit is the dashpot's m / c.
// Taken as (2 / w)(sqrt(1 + z^2) - z) it cancelled to 0, and central difference was refused.
TEST(CentralDifference, AStepLimitFarPastCriticalDampingIsTheDashpots) {
  const double mass = 2.0, stiffness = 1e-6, zeta = 1e9;
  const double damping = 2.0 * zeta * std::sqrt(stiffness * mass);
  Oscillator system(mass, damping, stiffness);
  const double limit = integrators::stable_time_step(system, true);
  std::cout << "z = 1e9: stable step " << limit << ", m / c " << mass / damping << "\n";
  EXPECT_NEAR(limit / (mass / damping), 1.0, 1e-9);
}

// The damped limit is the one the step has: a free vibration at 0.99 of it stays bounded, at 1.01
// it grows, for damping ratios of a high mode under Rayleigh damping (0.05 to 0.5) and far past
// critical. At the textbook limit (2 / w)(sqrt(1 + z^2) - z) a mode damped at 0.32 grew: 1.33
// times this one, and "time_step": "auto" failed at its own step.
TEST(CentralDifference, ADampedOscillatorIsBoundedBelowItsLimitAndGrowsAbove) {
  for (const double zeta : {0.05, 0.32, 0.5, 3.0}) {
    const double mass = 2.0, stiffness = 800.0, omega = 20.0;
    const double damping = 2.0 * zeta * omega * mass;
    for (const double factor : {0.99, 1.01}) {
      Oscillator system(mass, damping, stiffness);
      const double limit = integrators::stable_time_step(system, true);
      integrators::CentralDifference integrator;
      integrators::TransientAnalysis analysis(system, integrator,
                                              {.time_step = factor * limit, .end_time = 200.0});
      integrators::State state;
      state.displacement = Vector::Constant(1, 1.0);
      double late = 0.0;  // the largest |u| over the last quarter
      analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
        if (s.time > 150.0) late = std::max(late, std::abs(s.displacement[0]));
      });
      std::cout << fmt::format("z = {}: {} x the limit {:.6f} s, largest late |u| {:.3g}\n", zeta,
                               factor, limit, late);
      if (factor < 1.0)
        EXPECT_LT(late, 1.0);
      else
        EXPECT_GT(late, 1e3);
    }
  }
}

// Below the limit a free vibration stays bounded; just above it grows without bound.
TEST(CentralDifference, BoundedBelowTheLimitAndDivergesAbove) {
  for (const double factor : {0.99, 1.01}) {
    Oscillator system(2.0, 0.0, 800.0);
    integrators::CentralDifference integrator;
    integrators::TransientAnalysis analysis(system, integrator,
                                            {.time_step = factor * 0.1, .end_time = 60.0});
    integrators::State state;
    state.displacement = Vector::Constant(1, 1.0);
    double largest = 0.0;
    analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
      largest = std::max(largest, std::abs(s.displacement[0]));
    });
    std::cout << factor << " x limit: largest |u| " << largest << "\n";
    if (factor < 1.0) {
      EXPECT_LT(largest, 20.0);
    } else {
      EXPECT_GT(largest, 1e3);
    }
  }
}

TEST(CentralDifference, ForcedDampedOscillatorConvergesAtSecondOrder) {
  auto error = [](double dt) {
    const double mass = 1.0, stiffness = 40.0, zeta = 0.05, omega = std::sqrt(stiffness / mass);
    Oscillator system(mass, 2.0 * zeta * omega * mass, stiffness, integrators::LinkSet(1),
                      [](double t) { return 3.0 * std::sin(4.0 * t); });
    integrators::CentralDifference integrator;
    integrators::TransientAnalysis analysis(system, integrator, {.time_step = dt, .end_time = 4.0});
    // Reference: the same problem with a tiny step (the closed form is in newmark_test.cpp).
    integrators::CentralDifference fine_integrator;
    Oscillator fine_system(mass, 2.0 * zeta * omega * mass, stiffness, integrators::LinkSet(1),
                           [](double t) { return 3.0 * std::sin(4.0 * t); });
    integrators::TransientAnalysis fine(fine_system, fine_integrator,
                                        {.time_step = dt / 64.0, .end_time = 4.0});
    integrators::State a, b;
    analysis.run(a);
    fine.run(b);
    return std::abs(a.displacement[0] - b.displacement[0]);
  };
  const double coarse = error(0.01), finer = error(0.005);
  std::cout << "error " << coarse << " -> " << finer << ", order " << std::log2(coarse / finer)
            << "\n";
  EXPECT_NEAR(std::log2(coarse / finer), 2.0, 0.15);
}

using testing::FreeMassPair;
using testing::hard_contact_row;

// Masses 1 and 3 closing at 3 through a hard contact, first touch at several phases of a step:
// afterwards their velocities are the rigid-body impulse solution with Newton's e, the pair has
// lost exactly (1 - e^2) of 1/2 m_eff w^2, and the contact never penetrated.
TEST(CentralDifference, HardContactGivesTheRigidImpulseSolution) {
  const double m0 = 1.0, m1 = 3.0, v0 = 2.0, v1 = -1.0, dt = 1e-3;
  const double closing = v0 - v1, effective = m0 * m1 / (m0 + m1);
  double worst_velocity = 0.0, worst_energy = 0.0, deepest = 0.0;
  for (const double e : {0.0, 0.3, 0.7, 1.0})
    for (const double phase : {0.0, 0.25, 0.5, 0.9}) {
      const double gap = closing * dt * (3.0 + phase);
      FreeMassPair system(m0, m1, hard_contact_row({{0, 1.0}, {1, -1.0}}, gap, e));
      integrators::CentralDifference integrator;
      integrators::TransientAnalysis analysis(system, integrator,
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
      const double lost =
          0.5 * (m0 * v0 * v0 + m1 * v1 * v1) - 0.5 * (m0 * state.velocity[0] * state.velocity[0] +
                                                       m1 * state.velocity[1] * state.velocity[1]);
      const double expected = (1.0 - e * e) * 0.5 * effective * closing * closing;
      worst_energy = std::max(worst_energy, std::abs(lost - expected) / (0.5 * effective * 9.0));
    }
  std::cout << "hard contact, rigid pair: largest velocity error " << worst_velocity
            << ", energy loss error " << worst_energy << " of the approach energy, deepest "
            << "penetration " << deepest << "\n";
  EXPECT_LT(worst_velocity, 1e-12);
  EXPECT_LT(worst_energy, 1e-12);
  EXPECT_LE(deepest, 0.0);
}

// A mass against a rigid wall (the link's other end fixed): it comes back at -e v; with e = 0 it
// stays at the wall, pressed by a constant force with no bounce and no penetration, and the
// wall carries exactly that force.
TEST(CentralDifference, HardContactAgainstAWallBouncesOrHolds) {
  const double mass = 2.0, velocity = 0.5, dt = 1e-3, gap = velocity * dt * 2.6;
  for (const double e : {0.0, 0.5, 1.0}) {
    Oscillator system(mass, 0.0, 0.0, hard_contact_row({{0, 1.0}}, gap, e),
                      [](double) { return 3.0; });  // pushing towards the wall
    integrators::CentralDifference integrator;
    integrators::TransientAnalysis analysis(system, integrator,
                                            {.time_step = dt, .end_time = 8.0 * dt});
    integrators::State state;
    state.displacement = Vector::Zero(1);
    state.velocity = Vector::Constant(1, velocity);
    double deepest = -1.0;
    analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
      deepest = std::max(deepest, s.link_penetration[0]);
    });
    std::cout << "wall, e = " << e << ": velocity " << state.velocity[0] << ", force "
              << state.link_force[0] << ", deepest " << deepest << "\n";
    EXPECT_LE(deepest, 0.0);
    if (e == 0.0) {  // touching exactly, at rest
      EXPECT_NEAR(deepest, 0.0, 1e-15);
      EXPECT_NEAR(state.velocity[0], 0.0, 1e-15);
      EXPECT_NEAR(state.link_force[0], 3.0, 1e-12);
    }
  }
  // Without the push, a bounce is -e v exactly.
  for (const double e : {0.5, 1.0}) {
    Oscillator system(mass, 0.0, 0.0, hard_contact_row({{0, 1.0}}, gap, e));
    integrators::CentralDifference integrator;
    integrators::TransientAnalysis analysis(system, integrator,
                                            {.time_step = dt, .end_time = 10.0 * dt});
    integrators::State state;
    state.displacement = Vector::Zero(1);
    state.velocity = Vector::Constant(1, velocity);
    analysis.run(state);
    EXPECT_NEAR(state.velocity[0], -e * velocity, 1e-15);
  }
}

// A viscous damper link (no stiffness) on a mass: the link rate is taken at the half step, so the
// half-step velocity changes by the factor 1 - c h / m a step. Stable below 2 m / c (checked by
// running just below and just above it), but past m / c that factor is negative and the decay,
// which is the damper's whole response, flips sign at every step: the step is bounded at m / c,
// half the damped oscillator's (2 / w)(sqrt(1 + z^2) - z) as the spring vanishes.
TEST(CentralDifference, ViscousDamperLinkBoundsTheStep) {
  const double mass = 2.0, stiffness = 8.0, coefficient = 400.0;  // z = 50
  auto damped_mass = [&] {
    std::vector<std::unique_ptr<links::LinkLaw>> laws;
    laws.push_back(std::make_unique<links::ViscousDamper>(coefficient, 1.0, 1e-3));
    return Oscillator(mass, 0.0, stiffness,
                      integrators::LinkSet(1, {{{0, 1.0}}}, {0.0}, std::move(laws)));
  };
  Oscillator system = damped_mass();
  const double limit = integrators::stable_time_step(system, true);
  const double zeta = coefficient / (2.0 * std::sqrt(stiffness * mass)),
               stable = 2.0 / std::sqrt(stiffness / mass) * (std::sqrt(1.0 + zeta * zeta) - zeta);
  std::cout << "damper link: stable step " << limit << ", m / c " << mass / coefficient
            << ", the damped oscillator's stability limit " << stable << "\n";
  EXPECT_NEAR(limit, mass / coefficient, 1e-15);
  for (const double factor : {0.98, 1.02}) {
    Oscillator run = damped_mass();
    integrators::CentralDifference integrator;
    integrators::TransientAnalysis analysis(run, integrator,
                                            {.time_step = factor * stable, .end_time = 5.0});
    integrators::State state;
    state.displacement = Vector::Constant(1, 1.0);
    state.velocity = Vector::Constant(1, 1.0);
    double largest = 0.0;
    try {
      analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
        largest = std::max(largest, std::abs(s.velocity[0]));
      });
    } catch (const std::exception&) {
      largest = std::numeric_limits<double>::infinity();
    }
    std::cout << factor << " x the stability limit: largest |v| " << largest << "\n";
    if (factor < 1.0) {
      EXPECT_LT(largest, 10.0);
    } else {
      EXPECT_GT(largest, 1e3);
    }
  }
}

// Two masses on springs joined by a penalty spring alpha0 alone: the stable step with the
// contact active is 2 / w2 with w2 the larger root of Suzuki & Toi's eq. 4.
TEST(CentralDifference, ContactActiveLimitFollowsSuzukiToiEquation4) {
  const double k1 = 100.0, k2 = 300.0, m1 = 2.0, m2 = 1.0;
  for (double ratio : {1.0, 10.0, 1000.0}) {
    const double alpha0 = ratio * k1;
    std::vector<std::unique_ptr<links::LinkLaw>> laws;
    laws.push_back(std::make_unique<links::ExtendedPenalty>(
        links::ExtendedPenalty::Numbers{alpha0, 0.0, 0.0}));
    // A two-DOF system: masses m1, m2 on springs k1, k2 to ground, the link between them.
    struct TwoMasses final : integrators::SecondOrderSystem {
      TwoMasses(double k1_, double k2_, double m1_, double m2_, integrators::LinkSet l)
          : mass(Vector(2)), stiffness(Vector(2)), link_set(std::move(l)) {
        mass << m1_, m2_;
        stiffness << k1_, k2_;
      }
      Index size() const override { return 2; }
      void multiply_mass(const Vector& x, Vector& y) const override { y = mass.cwiseProduct(x); }
      const Vector* lumped_mass() const override { return &mass; }
      bool has_damping() const override { return false; }
      void multiply_damping(const Vector& x, Vector& y) const override {
        y = Vector::Zero(x.size());
      }
      void multiply_stiffness(const Vector& x, Vector& y) const override {
        y = stiffness.cwiseProduct(x);
      }
      bool has_external_force() const override { return false; }
      void external_force(double, Vector& f) const override { f = Vector::Zero(2); }
      std::unique_ptr<integrators::LinearSolver> factor(double, double, double) const override {
        return nullptr;
      }
      integrators::LinkSet& links() override { return link_set; }
      Vector mass, stiffness;
      integrators::LinkSet link_set;
    } system(k1, k2, m1, m2,
             integrators::LinkSet(2, {{{0, 1.0}, {1, -1.0}}}, {0.0}, std::move(laws)));
    const double sum = (k1 + alpha0) / m1 + (k2 + alpha0) / m2;
    const double product = (k1 * k2 + alpha0 * (k1 + k2)) / (m1 * m2);
    const double larger = 0.5 * (sum + std::sqrt(sum * sum - 4.0 * product));
    const double limit = integrators::stable_time_step(system, true),
                 exact = 2.0 / std::sqrt(larger);
    const double open = integrators::stable_time_step(system, false);
    std::cout << "alpha0 / k1 = " << ratio << ": stable step " << limit << ", eq. 4 gives " << exact
              << ", without contact " << open << "\n";
    EXPECT_NEAR(limit / exact, 1.0, 1e-8);
    EXPECT_NEAR(open, 2.0 / std::sqrt(std::max(k1 / m1, k2 / m2)), 1e-8);
  }
}

}  // namespace
}  // namespace pound
