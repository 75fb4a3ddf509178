#include "verification/exact_rod_impact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace pound::verification {
namespace {

ExactRod make_rod(double youngs_modulus, double density, double area, double length,
                  double initial_velocity, bool far_end_fixed = false) {
  ExactRod rod;
  rod.youngs_modulus = youngs_modulus;
  rod.density = density;
  rod.area = area;
  rod.length = length;
  rod.initial_velocity = initial_velocity;
  rod.far_end_fixed = far_end_fixed;
  return rod;
}

// Kawashima's rod: E = 100, rho = 0.1, A = 1, L = 10.
ExactRod kawashima_rod(double initial_velocity, bool far_end_fixed = false) {
  return make_rod(100.0, 0.1, 1.0, 10.0, initial_velocity, far_end_fixed);
}

double round_trip(const ExactRod& rod) { return 2.0 * rod.length / rod.wave_speed(); }

double relative_error(double value, double expected) {
  return std::abs(value - expected) / std::abs(expected);
}

void report(const std::string& name, double value) {
  std::ostringstream text;
  text << std::scientific << std::setprecision(3) << value;
  ::testing::Test::RecordProperty(name, text.str());
  std::cout << "  [measured] " << name << " = " << text.str() << "\n";
}

// Reports a measured error and checks that it is at rounding level, as an exact solution's must be.
void expect_exact(const std::string& name, double error) {
  report(name, error);
  EXPECT_LT(error, 1e-12) << name;
}

// Integral over [a, b] of weight(sample(s)) where sample is piecewise constant in s: bisects
// only where the samples at the ends and midpoint differ, down to a width negligible against
// (b - a), so the result is exact to about 1e-13 without knowing where the jumps are. Pulses
// narrower than (b - a) / 2^uniform_depth may be missed.
template <class Sample, class Weight>
double integrate_piecewise_constant(const Sample& sample, const Weight& weight, double a, double b,
                                    int uniform_depth = 12) {
  const double resolution = 1e-14 * (b - a);
  auto piece = [&](auto&& self, double lo, const auto& lo_value, double hi, const auto& hi_value,
                   int depth) -> double {
    const double mid = 0.5 * (lo + hi);
    const auto mid_value = sample(mid);
    if (depth >= uniform_depth && lo_value == mid_value && mid_value == hi_value) {
      return weight(mid_value) * (hi - lo);
    }
    if (hi - lo <= resolution || mid <= lo || mid >= hi)
      return 0.5 * (weight(lo_value) + weight(hi_value)) * (hi - lo);
    return self(self, lo, lo_value, mid, mid_value, depth + 1) +
           self(self, mid, mid_value, hi, hi_value, depth + 1);
  };
  return piece(piece, a, sample(a), b, sample(b), 0);
}

struct RodImpactCase {
  ExactRod left;
  ExactRod right;
  double gap = 0.0;
  double t_end = 0.0;
};

ExactRodImpact solve(const RodImpactCase& c) {
  return ExactRodImpact(c.left, c.right, c.gap, c.t_end);
}

const ExactRod& rod_of(const RodImpactCase& c, int rod) { return rod == 0 ? c.left : c.right; }

std::array<double, 2> rod_extent(const RodImpactCase& c, int rod) {
  return rod == 0 ? std::array{-c.left.length, 0.0} : std::array{c.gap, c.gap + c.right.length};
}

// Integral over a rod of density(velocity, stress) * dx, from state() alone.
template <class Density>
double integrate_over_rod(const ExactRodImpact& impact, const RodImpactCase& c, int rod, double t,
                          const Density& density) {
  const auto [a, b] = rod_extent(c, rod);
  auto sample = [&](double x) {
    const RodState state = impact.state(rod, x, t);
    return std::array{state.velocity, state.stress};
  };
  auto weight = [&](const std::array<double, 2>& value) { return density(value[0], value[1]); };
  return integrate_piecewise_constant(sample, weight, a, b);
}

double total_energy(const ExactRodImpact& impact, const RodImpactCase& c, double t) {
  double energy = 0.0;
  for (int rod = 0; rod < 2; ++rod) {
    const ExactRod& r = rod_of(c, rod);
    energy += integrate_over_rod(impact, c, rod, t, [&](double velocity, double stress) {
      return r.area *
             (0.5 * r.density * velocity * velocity + 0.5 * stress * stress / r.youngs_modulus);
    });
  }
  return energy;
}

double momentum_from_field(const ExactRodImpact& impact, const RodImpactCase& c, int rod,
                           double t) {
  const ExactRod& r = rod_of(c, rod);
  return integrate_over_rod(impact, c, rod, t,
                            [&](double velocity, double) { return r.density * r.area * velocity; });
}

struct InvariantErrors {
  double energy = 0.0;                   // |E(t) - E(0)| / E(0)
  double momentum = 0.0;                 // |p(t) - p(0)| / sum |m v0|, free-free only
  double centre_of_mass_velocity = 0.0;  // impulse-based vs field-integrated, / velocity scale
  double gap_kinematics = 0.0;           // gap(t) vs gap0 + integral of the face velocities
  double interface = 0.0;                // face stresses / velocities vs contact_force
  double min_force = 0.0;
  double min_gap = 0.0;
};

// Checks every case must satisfy, at many instants in [0, t_end] (including every force
// breakpoint): energy conservation (the fixed ends do no work), momentum conservation when both
// far ends are free, centre-of-mass velocity against the integrated velocity field, the gap
// against the face velocities, the interface conditions, no tension, no overlap.
InvariantErrors check_invariants(const RodImpactCase& c, const ExactRodImpact& impact) {
  const double velocity_scale =
      std::abs(c.left.initial_velocity) + std::abs(c.right.initial_velocity);
  const double force_scale = std::max(c.left.impedance(), c.right.impedance()) * velocity_scale;
  const double momentum_scale = c.left.mass() * std::abs(c.left.initial_velocity) +
                                c.right.mass() * std::abs(c.right.initial_velocity);
  const bool momentum_conserved = !c.left.far_end_fixed && !c.right.far_end_fixed;
  const double energy0 = total_energy(impact, c, 0.0);
  const double expected_energy0 =
      0.5 * c.left.mass() * c.left.initial_velocity * c.left.initial_velocity +
      0.5 * c.right.mass() * c.right.initial_velocity * c.right.initial_velocity;
  EXPECT_LT(relative_error(energy0, expected_energy0), 1e-12);
  const double momentum0 =
      c.left.mass() * c.left.initial_velocity + c.right.mass() * c.right.initial_velocity;

  std::vector<double> times;
  constexpr int kSamples = 60;
  for (int i = 0; i <= kSamples; ++i) times.push_back(c.t_end * i / kSamples);
  // Instants on a jump test the "value after it" convention; at most 61 of them for run time.
  const std::vector<double> jumps = impact.force_breakpoints();
  const std::size_t stride = jumps.size() / kSamples + 1;
  for (std::size_t i = 0; i < jumps.size(); i += stride) times.push_back(jumps[i]);
  std::sort(times.begin(), times.end());

  auto face_velocities = [&](double t) {
    return std::array{impact.state(0, 0.0, t).velocity, impact.state(1, c.gap, t).velocity};
  };
  auto closing_rate = [](const std::array<double, 2>& v) { return v[1] - v[0]; };

  InvariantErrors errors;
  errors.min_force = force_scale;
  errors.min_gap = c.gap;
  double previous_time = 0.0;
  double gap_from_faces = c.gap;
  for (double t : times) {
    errors.energy =
        std::max(errors.energy, std::abs(total_energy(impact, c, t) - energy0) / energy0);
    double momentum = 0.0;
    for (int rod = 0; rod < 2; ++rod) {
      const double mass = rod_of(c, rod).mass();
      const double from_impulse = impact.centre_of_mass_velocity(rod, t);
      const double from_field = momentum_from_field(impact, c, rod, t) / mass;
      errors.centre_of_mass_velocity = std::max(
          errors.centre_of_mass_velocity, std::abs(from_impulse - from_field) / velocity_scale);
      momentum += mass * from_impulse;
    }
    if (momentum_conserved) {
      errors.momentum = std::max(errors.momentum, std::abs(momentum - momentum0) / momentum_scale);
    }
    if (t > previous_time) {
      // Sample intervals are at most t_end / 60: 2^8 cells resolve pulses of t_end / 15000.
      gap_from_faces +=
          integrate_piecewise_constant(face_velocities, closing_rate, previous_time, t, 8);
      previous_time = t;
    }
    const double gap = impact.gap(t);
    errors.gap_kinematics =
        std::max(errors.gap_kinematics,
                 std::abs(gap - gap_from_faces) / std::max(c.gap, velocity_scale * c.t_end));
    const double force = impact.contact_force(t);
    errors.min_force = std::min(errors.min_force, force);
    errors.min_gap = std::min(errors.min_gap, gap);
    // Interface: face force = -F on both sides, equal face velocities and a closed gap while
    // in contact; free faces otherwise.
    const RodState left_face = impact.state(0, 0.0, t);
    const RodState right_face = impact.state(1, c.gap, t);
    double mismatch = std::abs(left_face.stress * c.left.area + force) / force_scale +
                      std::abs(right_face.stress * c.right.area + force) / force_scale;
    if (force > 0.0) {
      mismatch += std::abs(left_face.velocity - right_face.velocity) / velocity_scale +
                  std::abs(gap) / std::max(c.gap, velocity_scale * c.t_end);
    }
    errors.interface = std::max(errors.interface, mismatch);
  }
  expect_exact("energy_error", errors.energy);
  expect_exact("momentum_error", errors.momentum);
  expect_exact("centre_of_mass_velocity_error", errors.centre_of_mass_velocity);
  expect_exact("gap_kinematics_error", errors.gap_kinematics);
  expect_exact("interface_error", errors.interface);
  report("min_force", errors.min_force);
  report("min_gap", errors.min_gap);
  EXPECT_GE(errors.min_force, 0.0);
  EXPECT_GE(errors.min_gap, -1e-12);
  const std::vector<double> breakpoints = impact.force_breakpoints();
  for (double t : breakpoints) {
    EXPECT_GT(t, 0.0);
    EXPECT_LT(t, c.t_end);
  }
  EXPECT_TRUE(std::is_sorted(breakpoints.begin(), breakpoints.end()));
  // contacts() and contact_force agree: positive inside every interval, zero between them.
  for (const ContactInterval& contact : impact.contacts()) {
    EXPECT_LT(contact.start, contact.end);
    EXPECT_GT(impact.contact_force(0.5 * (contact.start + contact.end)), 0.0);
  }
  for (std::size_t i = 0; i + 1 < impact.contacts().size(); ++i) {
    const double between = 0.5 * (impact.contacts()[i].end + impact.contacts()[i + 1].start);
    EXPECT_EQ(impact.contact_force(between), 0.0);
  }
  return errors;
}

// Maximum relative deviation of contact_force from `expected` over [start, end).
double max_force_error(const ExactRodImpact& impact, double start, double end, double expected) {
  double error = 0.0;
  constexpr int kSamples = 200;
  for (int i = 0; i < kSamples; ++i) {
    const double t = start + (end - start) * (i + 0.5) / kSamples;
    error = std::max(error, relative_error(impact.contact_force(t), expected));
  }
  return error;
}

// The only contact runs from t = 0 to `end` at a constant `force`: reports and checks its end
// and the force over it. Callers wrap it in ASSERT_NO_FATAL_FAILURE: without one contact the
// rest of the test is meaningless.
void expect_one_contact(const ExactRodImpact& impact, double end, double force) {
  ASSERT_EQ(impact.contacts().size(), 1u);
  EXPECT_EQ(impact.contacts()[0].start, 0.0);
  expect_exact("duration_error", relative_error(impact.contacts()[0].end, end));
  expect_exact("force_error", max_force_error(impact, 0.0, end, force));
}

// Kawashima (1980): identical rods approaching at V0 each. Exact: one contact of 2L/C0 at
// rho*C0*V0*A, after which the rods swap velocities.
TEST(ExactRodImpact, KawashimaIdenticalRodsSwapVelocities) {
  const double speed = 0.1;
  const RodImpactCase c{kawashima_rod(speed), kawashima_rod(-speed), 0.0, 2.0};
  const ExactRodImpact impact = solve(c);
  const double wave_speed = c.left.wave_speed();
  const double contact_time = 2.0 * c.left.length / wave_speed;
  const double force = c.left.density * wave_speed * speed * c.left.area;
  EXPECT_NEAR(contact_time, 0.632456, 1e-6);
  EXPECT_NEAR(force, 0.316228, 1e-6);

  ASSERT_NO_FATAL_FAILURE(expect_one_contact(impact, contact_time, force));
  ASSERT_EQ(impact.force_breakpoints().size(), 1u);
  expect_exact("breakpoint_error", relative_error(impact.force_breakpoints()[0], contact_time));
  expect_exact("separation_velocity_error",
               std::max(relative_error(impact.centre_of_mass_velocity(0, 1.0), -speed),
                        relative_error(impact.centre_of_mass_velocity(1, 1.0), speed)));
  // The compressive front reaches x = -5 at 5/C0 = 0.158: behind it the left rod is stopped.
  const RodState behind_front = impact.state(0, -5.0, 0.25);
  expect_exact("stress_error", relative_error(behind_front.stress, -force / c.left.area));
  const RodState ahead_of_front = impact.state(0, -5.0, 0.1);
  EXPECT_LT(std::abs(behind_front.velocity), 1e-15);
  EXPECT_DOUBLE_EQ(ahead_of_front.velocity, speed);
  EXPECT_EQ(ahead_of_front.stress, 0.0);
  EXPECT_EQ(impact.contact_force(0.7), 0.0);
  EXPECT_NEAR(impact.gap(1.0), 2.0 * speed * (1.0 - contact_time), 1e-14);
  check_invariants(c, impact);
}

// Identical rods, the left one moving at V into the right one at rest whose far end is fixed.
// With T = 2L/C and Z = rho*C*A, by characteristics (I_k the wave arriving at face k):
//   [0, T):   I_left = -Z V, I_right = 0       -> F = Z V / 2; the left rod emits nothing back
//             (O_left = 0: it is stopped behind the front), the right one emits O = -Z V.
//   [T, 2T):  the left rod's free far end returns 0, the fixed end returns the right rod's
//             compression unchanged (-Z V)      -> F = Z V / 2 again.
//   [2T, ..): the left rod's far end returns the compression as tension (+Z V) and the right
//             rod's returns 0                   -> tension: separation.
// So F = Z V / 2 for 2T = 4L/C (impulse 2 m V), the left rod rebounds at -V and the right rod
// is left exactly at rest and unstressed.
TEST(ExactRodImpact, FixedFarEndIdenticalRodsContactLastsTwiceAsLong) {
  const double speed = 0.1;
  const RodImpactCase c{kawashima_rod(speed), kawashima_rod(0.0, true), 0.0, 4.0};
  const ExactRodImpact impact = solve(c);
  const double period = round_trip(c.left);
  const double force = 0.5 * c.left.impedance() * speed;

  ASSERT_NO_FATAL_FAILURE(expect_one_contact(impact, 2.0 * period, force));
  expect_exact("rebound_velocity_error",
               relative_error(impact.centre_of_mass_velocity(0, 3.0), -speed));
  EXPECT_TRUE(impact.force_breakpoints().size() == 1u);
  double right_rod_motion = 0.0;
  for (int i = 0; i <= 100; ++i) {
    const RodState state = impact.state(1, c.right.length * i / 100.0, 3.0);
    right_rod_motion = std::max({right_rod_motion, std::abs(state.velocity) / speed,
                                 std::abs(state.stress) * c.right.area / force});
  }
  report("right_rod_residual_motion", right_rod_motion);
  EXPECT_LT(right_rod_motion, 1e-14);
  check_invariants(c, impact);
}

// Suzuki & Toi: same material and length, A2 = 3 A1, the left (thin) rod moving at V into the
// right (thick) rod at rest. Z2 = 3 Z1, F = Z1 Z2/(Z1 + Z2) V = 3/4 Z1 V while the first waves
// travel. Free far ends: at T = 2L/C the thin rod's returning wave is tensile enough to open the
// interface; the rods leave at -V/2 and +V/2 (momentum m V = -m V/2 + 3m V/2, energy
// m V^2/2 = m V^2/8 + 3 m V^2/8: an elastic collision of rigid bodies).
TEST(ExactRodImpact, SuzukiToiAreaRatioThreeFreeEnds) {
  const double speed = 0.1;
  ExactRod thick = kawashima_rod(0.0);
  thick.area = 3.0;
  const RodImpactCase c{kawashima_rod(speed), thick, 0.0, 3.0};
  const ExactRodImpact impact = solve(c);
  const double period = round_trip(c.left);
  const double z1 = c.left.impedance();
  const double z2 = c.right.impedance();
  const double force = z1 * z2 / (z1 + z2) * speed;
  EXPECT_NEAR(force, 0.75 * z1 * speed, 1e-15);

  ASSERT_NO_FATAL_FAILURE(expect_one_contact(impact, period, force));
  expect_exact("post_impact_velocity_error",
               std::max(relative_error(impact.centre_of_mass_velocity(0, 2.0), -0.5 * speed),
                        relative_error(impact.centre_of_mass_velocity(1, 2.0), 0.5 * speed)));
  check_invariants(c, impact);
}

// As above with the thick rod's far end fixed. With Z = Z1:
//   [0, T):   F = 3/4 Z V; the thin rod emits O1 = -Z V/2, the thick one O2 = -3 Z V/2.
//   [T, 2T):  returning I1 = +Z V/2 (free end flips), I2 = -3 Z V/2 (fixed end keeps): the stuck
//             force is 3/4 Z V (1/2 - 1/2) = 0, so the faces move on together at -V/2 without
//             force; this is not counted as contact.
//   [2T, 3T): I1 = +Z V/2, I2 = +3 Z V/2: tensile, the faces part at relative velocity V.
// Afterwards the thin rod moves off rigidly at -V/2 and the thick rod's face swings between
// +V/2 and -V/2 every T, so the gap grows by V T every 2T and never closes again.
TEST(ExactRodImpact, SuzukiToiAreaRatioThreeFixedFarEnd) {
  const double speed = 0.1;
  ExactRod thick = kawashima_rod(0.0, true);
  thick.area = 3.0;
  const RodImpactCase c{kawashima_rod(speed), thick, 0.0, 6.0};
  const ExactRodImpact impact = solve(c);
  const double period = round_trip(c.left);
  const double force = 0.75 * c.left.impedance() * speed;

  ASSERT_NO_FATAL_FAILURE(expect_one_contact(impact, period, force));
  expect_exact("rebound_velocity_error",
               relative_error(impact.centre_of_mass_velocity(0, 2.5), -0.5 * speed));
  expect_exact("gap_error",
               std::max({std::abs(impact.gap(1.5 * period)), std::abs(impact.gap(2.0 * period)),
                         relative_error(impact.gap(3.0 * period), speed * period),
                         relative_error(impact.gap(4.0 * period), speed * period),
                         relative_error(impact.gap(5.0 * period), 2.0 * speed * period)}));
  EXPECT_EQ(impact.contact_force(1.5 * period), 0.0);
  check_invariants(c, impact);
}

// An initial gap closes at gap / (v_left - v_right); the impact is then Kawashima's, shifted.
TEST(ExactRodImpact, InitialGapDelaysContact) {
  const double speed = 0.1;
  const double initial_gap = 0.05;
  const RodImpactCase c{kawashima_rod(speed), kawashima_rod(-speed), initial_gap, 2.0};
  const ExactRodImpact impact = solve(c);
  const double closing_time = initial_gap / (2.0 * speed);
  const double contact_time = round_trip(c.left);
  const double force = c.left.impedance() * speed;

  ASSERT_EQ(impact.contacts().size(), 1u);
  expect_exact("contact_start_error", relative_error(impact.contacts()[0].start, closing_time));
  expect_exact("contact_end_error",
               relative_error(impact.contacts()[0].end, closing_time + contact_time));
  expect_exact("force_error",
               max_force_error(impact, closing_time, closing_time + contact_time, force));
  expect_exact("gap_error", relative_error(impact.gap(0.1), initial_gap - 2.0 * speed * 0.1));
  EXPECT_EQ(impact.contact_force(0.5 * closing_time), 0.0);
  // Before contact each rod moves rigidly.
  const RodState right_face = impact.state(1, initial_gap, 0.5 * closing_time);
  EXPECT_DOUBLE_EQ(right_face.velocity, -speed);
  EXPECT_EQ(right_face.stress, 0.0);
  check_invariants(c, impact);
}

// L2 = 2 L1, same material and area, the left rod moving at V, the right one at rest. By
// characteristics (T = 2 L1 / C): F = Z V/2 on [0, T); at T the short rod, stopped behind its
// front, returns nothing and the long rod's front has not come back, so the force drops to 0
// with the faces at rest; at 2T the long rod's returning tension pulls its face away at V.
// The short rod is left at rest, the long one carries the momentum: centre of mass at V/2.
TEST(ExactRodImpact, LongerRightRod) {
  const double speed = 0.1;
  ExactRod long_rod = kawashima_rod(0.0);
  long_rod.length = 20.0;
  const RodImpactCase c{kawashima_rod(speed), long_rod, 0.0, 8.0};
  const ExactRodImpact impact = solve(c);
  const double period = round_trip(c.left);
  const double force = 0.5 * c.left.impedance() * speed;

  ASSERT_NO_FATAL_FAILURE(expect_one_contact(impact, period, force));
  expect_exact("post_impact_velocity_error",
               std::max(std::abs(impact.centre_of_mass_velocity(0, 7.0)) / speed,
                        relative_error(impact.centre_of_mass_velocity(1, 7.0), 0.5 * speed)));
  check_invariants(c, impact);
}

// Incommensurable travel times (L2 = sqrt(2) L1), both rods moving, over many round trips: no
// closed form after the first waves, so conservation, no tension and no overlap are the checks.
TEST(ExactRodImpact, IncommensurableLengths) {
  const double v_left = 0.1;
  const double v_right = -0.03;
  ExactRod right = kawashima_rod(v_right);
  right.length = std::sqrt(2.0) * 10.0;
  const RodImpactCase c{kawashima_rod(v_left), right, 0.0, 12.0};
  const ExactRodImpact impact = solve(c);
  const double z1 = c.left.impedance();
  const double z2 = c.right.impedance();
  const double force = z1 * z2 / (z1 + z2) * (v_left - v_right);
  expect_exact("first_force_error", max_force_error(impact, 0.0, round_trip(c.left), force));
  report("contacts", static_cast<double>(impact.contacts().size()));
  report("force_breakpoints", static_cast<double>(impact.force_breakpoints().size()));
  ASSERT_FALSE(impact.contacts().empty());
  check_invariants(c, impact);
}

// Different materials (C2 = sqrt(8) C1, incommensurable round trips), areas and lengths, free
// and fixed far ends.
TEST(ExactRodImpact, DifferentMaterials) {
  const double v_left = 0.1;
  const double v_right = -0.04;
  const ExactRod steel_like = make_rod(100.0, 0.1, 1.0, 10.0, v_left);
  const ExactRod stiff = make_rod(400.0, 0.05, 0.7, 7.3, v_right);
  for (const bool right_fixed : {false, true}) {
    for (const bool left_fixed : {false, true}) {
      SCOPED_TRACE("left fixed: " + std::to_string(left_fixed) +
                   ", right fixed: " + std::to_string(right_fixed));
      ExactRod left = steel_like;
      ExactRod right = stiff;
      left.far_end_fixed = left_fixed;
      right.far_end_fixed = right_fixed;
      const RodImpactCase c{left, right, 0.0, 10.0};
      const ExactRodImpact impact = solve(c);
      const double z1 = left.impedance();
      const double z2 = right.impedance();
      // Until the first reflection returns (a fixed end returns earlier: its t = 0 wave).
      const double first_return = std::min(round_trip(left) / (left_fixed ? 2.0 : 1.0),
                                           round_trip(right) / (right_fixed ? 2.0 : 1.0));
      const double force = z1 * z2 / (z1 + z2) * (v_left - v_right);
      expect_exact("first_force_error", max_force_error(impact, 0.0, first_return, force));
      report("contacts", static_cast<double>(impact.contacts().size()));
      check_invariants(c, impact);
    }
  }
}

// Arbitrary pairs (properties spread over decades, free or fixed ends, gaps, either rod faster)
// over several round trips of the slower rod: the invariants must hold whatever happens.
TEST(ExactRodImpact, ArbitraryRodPairs) {
  std::mt19937 generator(20240601);  // std::mt19937 is fully specified: same cases everywhere
  auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(generator()) / 4294967296.0;
  };
  auto log_uniform = [&](double lo, double hi) {
    return lo * std::pow(hi / lo, uniform(0.0, 1.0));
  };
  auto random_rod = [&] {
    return make_rod(log_uniform(1.0, 1e4), log_uniform(0.1, 10.0), log_uniform(0.1, 10.0),
                    log_uniform(1.0, 20.0), uniform(-1.0, 1.0), uniform(0.0, 1.0) < 0.3);
  };
  for (int i = 0; i < 12; ++i) {
    RodImpactCase c{random_rod(), random_rod(), 0.0, 0.0};
    const double slowest_round_trip = std::max(round_trip(c.left), round_trip(c.right));
    const double closing_speed = std::abs(c.left.initial_velocity - c.right.initial_velocity);
    if (i % 2 == 1) c.gap = uniform(0.0, 0.5) * closing_speed * slowest_round_trip;
    c.t_end = 5.0 * slowest_round_trip;
    SCOPED_TRACE("case " + std::to_string(i));
    const ExactRodImpact impact = solve(c);
    report("contacts", static_cast<double>(impact.contacts().size()));
    check_invariants(c, impact);
  }
}

// A fixed far end with a non-zero initial velocity: the end stops at t = 0 and sends a wave.
// The right rod moves at +V away from the left one into its own fixed end: the end holds it,
// compression -rho C V travels back, the centre of mass stops at L/C and moves at -V at 2L/C
// (the rod has bounced off its support), then the support pulls it back: +V at 4L/C.
TEST(ExactRodImpact, FixedEndWithInitialVelocityEmitsWave) {
  const double speed = 0.1;
  const RodImpactCase c{kawashima_rod(0.0), kawashima_rod(speed, true), 1.0, 3.0};
  const ExactRodImpact impact = solve(c);
  const double period = round_trip(c.right);
  const double far_end = c.gap + c.right.length;
  const RodState near_support = impact.state(1, far_end - 1.0, 0.05);
  expect_exact("centre_of_mass_velocity_error",
               std::max({std::abs(impact.centre_of_mass_velocity(1, 0.5 * period)) / speed,
                         relative_error(impact.centre_of_mass_velocity(1, period), -speed),
                         relative_error(impact.centre_of_mass_velocity(1, 2.0 * period), speed)}));
  expect_exact("stress_error", relative_error(near_support.stress,
                                              -c.right.density * c.right.wave_speed() * speed));
  EXPECT_EQ(near_support.velocity, 0.0);
  EXPECT_DOUBLE_EQ(impact.state(1, c.gap + 1.0, 0.05).velocity,
                   speed);  // the wave is not there yet
  EXPECT_TRUE(impact.contacts().empty());
  check_invariants(c, impact);
}

TEST(ExactRodImpact, SeparatingRodsNeverTouch) {
  const RodImpactCase c{kawashima_rod(-0.1), kawashima_rod(0.2), 0.0, 2.0};
  const ExactRodImpact impact = solve(c);
  EXPECT_TRUE(impact.contacts().empty());
  EXPECT_TRUE(impact.force_breakpoints().empty());
  EXPECT_NEAR(impact.gap(2.0), 0.6, 1e-15);
  check_invariants(c, impact);
}

TEST(ExactRodImpact, RejectsBadInputAndQueries) {
  const ExactRod rod = kawashima_rod(0.1);
  EXPECT_THROW(ExactRodImpact(rod, rod, -0.1, 1.0), std::invalid_argument);
  EXPECT_THROW(ExactRodImpact(rod, rod, 0.0, -1.0), std::invalid_argument);
  ExactRod no_length = rod;
  no_length.length = 0.0;
  EXPECT_THROW(ExactRodImpact(no_length, rod, 0.0, 1.0), std::invalid_argument);
  const ExactRodImpact impact(rod, kawashima_rod(-0.1), 0.0, 1.0);
  EXPECT_THROW(impact.contact_force(1.5), std::out_of_range);
  EXPECT_THROW(impact.state(2, 0.0, 0.5), std::out_of_range);
  EXPECT_THROW(impact.state(0, 1.0, 0.5), std::out_of_range);
  EXPECT_EQ(impact.t_end(), 1.0);
}

}  // namespace
}  // namespace pound::verification
