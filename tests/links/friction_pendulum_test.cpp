// Friction pendulum (CoulombFriction with a radius): the consistent tangent against finite
// differences in every regime, and the force-displacement loop under a prescribed slow
// sinusoidal slide against Zayas, Low & Mahin's F = W s / R + mu W sign(s_dot).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <numbers>

#include "links/coulomb_friction.hpp"
#include "links/extended_penalty.hpp"
#include "links/gap_spring.hpp"
#include "links/hertz_damp.hpp"

namespace pound::links {
namespace {

constexpr double kRadius = 2.0, kMu = 0.1;

// The six variables of a trial: delta, delta_dot, delta_ddot, s, s_dot, s_ddot.
using Trial = std::array<double, 6>;

FrictionResponse evaluate(CoulombFriction& friction, const Trial& x) {
  return friction.set_trial({x[0], x[1], x[2]}, {x[3], x[4], x[5]});
}

// Largest error of the 2 x 6 tangent [dR_n, dR_t] / d(variables) against central differences,
// each column relative to its largest analytic entry (or to |R_t| / |x| where the column is 0).
double tangent_error(CoulombFriction& friction, const Trial& at, bool expect_slip) {
  const FrictionResponse r = evaluate(friction, at);
  EXPECT_EQ(r.slipping, expect_slip);
  EXPECT_GT(r.normal.force, 0.0);
  const LawResponse& n = r.normal;
  const LawResponse& tn = r.tangential_on_normal[0];
  const LawResponse& ts = r.tangential_on_slip[0][0];
  const double analytic[2][6] = {
      {n.stiffness, n.damping, n.mass, 0.0, 0.0, 0.0},
      {tn.stiffness, tn.damping, tn.mass, ts.stiffness, ts.damping, ts.mass}};
  double worst = 0.0;
  for (int v = 0; v < 6; ++v) {
    const double h = 1e-6 * std::max(std::abs(at[v]), 1e-3);
    Trial up = at, down = at;
    up[v] += h;
    down[v] -= h;
    const FrictionResponse p = evaluate(friction, up), m = evaluate(friction, down);
    EXPECT_EQ(p.slipping, expect_slip);
    EXPECT_EQ(m.slipping, expect_slip);
    const double numeric[2] = {(p.normal.force - m.normal.force) / (2 * h),
                               (p.tangential_force[0] - m.tangential_force[0]) / (2 * h)};
    double scale = std::max(std::abs(analytic[0][v]), std::abs(analytic[1][v]));
    if (scale == 0.0) scale = std::abs(r.tangential_force[0]) / std::max(std::abs(at[v]), 1e-3);
    for (int row = 0; row < 2; ++row)
      worst = std::max(worst, std::abs(numeric[row] - analytic[row][v]) / scale);
  }
  evaluate(friction, at);  // leave the trial where it was
  return worst;
}

// In contact and committed with the slide at `slide` (where sticking is anchored): the approach
// is committed first so that an impact law's onset velocity is fixed before the trials.
CoulombFriction settled(std::unique_ptr<LinkLaw> normal, double penetration, double slide) {
  CoulombFriction friction(std::move(normal), kMu, {2e6, 300.0, 0.4}, kRadius);
  friction.set_trial({-1e-5, 0.05, 0.0}, {slide, 0.0, 0.0});
  friction.commit();
  friction.set_trial({penetration, 0.01, 0.0}, {slide, 0.0, 0.0});
  friction.commit();
  return friction;
}

struct Regime {
  const char* name;
  double normal_rate;  // > 0 loading, < 0 unloading
  double slide_offset, slide_rate;
  bool slip;
};

// Every regime at s = +0.15 and s = -0.15 off the dish's centre: sticking (just off the anchor)
// and slipping either way, while the normal force loads and unloads.
TEST(FrictionPendulum, TangentMatchesFiniteDifferencesInEveryRegime) {
  const Regime regimes[] = {
      {"stick, loading", 0.02, 2e-6, 1e-3, false},
      {"stick, unloading", -0.02, -2e-6, -1e-3, false},
      {"slip +, loading", 0.02, 0.01, 0.3, true},
      {"slip +, unloading", -0.02, 0.01, 0.3, true},
      {"slip -, loading", 0.02, -0.01, -0.3, true},
      {"slip -, unloading", -0.02, -0.01, -0.3, true},
  };
  const std::function<std::unique_ptr<LinkLaw>()> normals[] = {
      [] { return std::make_unique<HertzDamp>(1e10, 0.5); },  // nonlinear, rate-dependent
      [] {
        return std::make_unique<ExtendedPenalty>(ExtendedPenalty::Numbers{1e8, 2e4, 50.0});
      },
  };
  const char* normal_names[] = {"hertz_damp", "extended_penalty"};
  double worst = 0.0;
  for (int law = 0; law < 2; ++law)
    for (double centre : {0.15, -0.15})
      for (const Regime& regime : regimes) {
        CoulombFriction friction = settled(normals[law](), 1e-4, centre);
        const Trial at{
            1.1e-4, regime.normal_rate, 0.5, centre + regime.slide_offset, regime.slide_rate, 0.7};
        const double error = tangent_error(friction, at, regime.slip);
        std::cout << fmt::format("{:16} s = {:+.2f}, {:18}: tangent error {:.2e}\n",
                                 normal_names[law], centre, regime.name, error);
        worst = std::max(worst, error);
        EXPECT_LT(error, 1e-6) << normal_names[law] << " " << regime.name;
      }
  std::cout << fmt::format("worst tangent error {:.2e}\n", worst);
}

// The restoring part adds exactly R_n s / R to the flat slider's force, and its couplings.
TEST(FrictionPendulum, AddsTheRestoringForceOfTheVerticalLoadToTheFlatSlider) {
  const auto make = [](std::optional<double> radius) {
    CoulombFriction friction(std::make_unique<GapSpring>(1e8), kMu, {2e6, 0.0, 0.0}, radius);
    friction.set_trial({1e-4, 0.0, 0.0}, {0.0, 0.0, 0.0});
    friction.commit();
    return friction;
  };
  CoulombFriction flat = make(std::nullopt), pendulum = make(kRadius);
  const double normal = 1e8 * 1e-4;
  for (const Trial& at : {Trial{1e-4, 0, 0, 1e-7, 0, 0}, Trial{1e-4, 0, 0, 0.2, 0.4, 0}}) {
    const FrictionResponse f = evaluate(flat, at), p = evaluate(pendulum, at);
    EXPECT_DOUBLE_EQ(p.tangential_force[0] - f.tangential_force[0], normal * at[3] / kRadius);
    EXPECT_DOUBLE_EQ(p.tangential_on_slip[0][0].stiffness - f.tangential_on_slip[0][0].stiffness,
                     normal / kRadius);
    EXPECT_DOUBLE_EQ(p.tangential_on_normal[0].stiffness - f.tangential_on_normal[0].stiffness,
                     1e8 * at[3] / kRadius);
  }
  // Apart: no force at all, however far off the centre.
  EXPECT_EQ(evaluate(pendulum, {-1e-4, 0, 0, 0.2, 0.4, 0}).tangential_force[0], 0.0);
}

// One slow cycle of s = D sin(2 pi t / T) on a normal spring pressed by W: the loop's forces,
// its dissipated energy, and how they scale with W.
struct Loop {
  double energy = 0.0;  // the loop integral of R_t ds over the second cycle
  // R_t one step before s = +D and s = -D, still sliding towards them, and the closed form
  // W s / R +- mu W there.
  double peak_plus = 0.0, expected_plus = 0.0;
  double peak_minus = 0.0, expected_minus = 0.0;
  double worst_slip_error = 0.0;  // max |R_t - (W s / R + mu W sign)| while slipping
};

constexpr double kAmplitude = 0.1, kStickStiffness = 1e8;

Loop sinusoidal_slide(double weight) {
  constexpr double k = 1e9;
  CoulombFriction friction(std::make_unique<GapSpring>(k), kMu, {kStickStiffness, 0.0, 0.0},
                           kRadius);
  const double delta = weight / k, period = 20.0;
  constexpr int steps = 40000;  // per cycle
  Loop loop;
  double previous_s = 0.0, previous_force = 0.0;
  for (int step = 0; step <= 2 * steps; ++step) {
    const double phase = 2 * std::numbers::pi * step / steps;
    const double s = kAmplitude * std::sin(phase);
    const double rate = kAmplitude * 2 * std::numbers::pi / period * std::cos(phase);
    const FrictionResponse r = friction.set_trial({delta, 0.0, 0.0}, {s, rate, 0.0});
    friction.commit();
    const double force = r.tangential_force[0];
    if (step > steps) loop.energy += 0.5 * (force + previous_force) * (s - previous_s);
    // One step before the turning points, where s_dot is clearly non-zero.
    if (step == steps + steps / 4 - 1) {
      loop.peak_plus = force;
      loop.expected_plus = weight * s / kRadius + kMu * weight;
    }
    if (step == steps + 3 * steps / 4 - 1) {
      loop.peak_minus = force;
      loop.expected_minus = weight * s / kRadius - kMu * weight;
    }
    if (r.slipping)
      loop.worst_slip_error =
          std::max(loop.worst_slip_error,
                   std::abs(force - (weight * s / kRadius + std::copysign(kMu * weight, rate))));
    previous_s = s;
    previous_force = force;
  }
  return loop;
}

TEST(FrictionPendulum, SlowSinusoidalSlideTracesZayasLoop) {
  constexpr double weight = 1e5;
  const Loop loop = sinusoidal_slide(weight);
  // Near the peaks the force is W D / R + mu W; with an elastic stick branch of yield slide
  // d_y = mu W / k_t the loop's area is 4 mu W (D - d_y), and 4 mu W D as k_t -> infinity.
  const double peak = weight * kAmplitude / kRadius + kMu * weight;
  const double yield_slide = kMu * weight / kStickStiffness;
  const double energy_elastoplastic = 4 * kMu * weight * (kAmplitude - yield_slide);
  const double energy_rigid_plastic = 4 * kMu * weight * kAmplitude;
  const double peak_error = std::max(std::abs(loop.peak_plus - loop.expected_plus),
                                     std::abs(loop.peak_minus - loop.expected_minus)) /
                            peak;
  EXPECT_NEAR(loop.expected_plus, peak, 1e-6 * peak);  // the step before is at the peak
  const double energy_error = std::abs(loop.energy / energy_elastoplastic - 1.0);
  const double energy_vs_4muWD = loop.energy / energy_rigid_plastic - 1.0;
  std::cout << fmt::format(
      "pendulum loop: peak force error {:.2e}, slip force error {:.2e} of mu W, energy error "
      "{:.2e} against 4 mu W (D - d_y), {:.2e} against 4 mu W D (d_y / D = {:.1e})\n",
      peak_error, loop.worst_slip_error / (kMu * weight), energy_error, energy_vs_4muWD,
      yield_slide / kAmplitude);
  EXPECT_LT(peak_error, 1e-9);
  EXPECT_LT(loop.worst_slip_error / (kMu * weight), 1e-9);
  EXPECT_LT(energy_error, 1e-6);
  EXPECT_LT(std::abs(energy_vs_4muWD), 2 * yield_slide / kAmplitude);
}

TEST(FrictionPendulum, TheFrictionForceFollowsTheVerticalLoad) {
  const Loop single = sinusoidal_slide(1e5), doubled = sinusoidal_slide(2e5);
  const double peak_ratio = doubled.peak_plus / single.peak_plus;
  const double energy_ratio = doubled.energy / single.energy;
  std::cout << fmt::format("double the vertical load: peak force x {:.9f}, loop energy x {:.9f}\n",
                           peak_ratio, energy_ratio);
  EXPECT_NEAR(peak_ratio, 2.0, 1e-9);
  // The yield slide doubles too (mu W / k_t), so the energy doubles only up to d_y / D.
  EXPECT_NEAR(energy_ratio,
              2.0 * (kAmplitude - 2 * kMu * 1e5 / kStickStiffness) /
                  (kAmplitude - kMu * 1e5 / kStickStiffness),
              1e-6);
}

}  // namespace
}  // namespace pound::links
