// Ground motions: sampling, scaling, and the Nigam & Jennings SDOF recurrence against closed
// forms that it reproduces exactly (a piecewise-linear record is its exact input).
#include "model/ground_motion.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace pound::model {
namespace {

constexpr double kPi = std::numbers::pi;

GroundMotion sampled(const std::function<double(double)>& acceleration, double time_step,
                     std::size_t samples) {
  GroundMotion motion;
  motion.name = "sampled";
  motion.time_step = time_step;
  for (std::size_t k = 0; k < samples; ++k)
    motion.acceleration.push_back(acceleration(static_cast<double>(k) * time_step));
  return motion;
}

// Relative displacement and velocity from rest of u'' + 2 z w u' + w^2 u = -(a0 + r t):
// u = P + Q t + e^{-z w t} (c1 cos wd t + c2 sin wd t) with Q = -r/w^2, P = -a0/w^2 - 2 z Q/w,
// c1 = -P, c2 = (z w c1 - Q)/wd. For r = 0 it is the step response
// u = -a0/w^2 (1 - e^{-z w t} (cos wd t + z/sqrt(1 - z^2) sin wd t)).
struct ExactState {
  double displacement, velocity;
};

ExactState exact_linear_input(double a0, double rate, double omega, double zeta, double t) {
  const double omega_d = omega * std::sqrt(1.0 - zeta * zeta);
  const double q = -rate / (omega * omega);
  const double p = -a0 / (omega * omega) - 2.0 * zeta * q / omega;
  const double c1 = -p, c2 = (zeta * omega * c1 - q) / omega_d;
  const double decay = std::exp(-zeta * omega * t);
  const double c = std::cos(omega_d * t), s = std::sin(omega_d * t);
  return {p + q * t + decay * (c1 * c + c2 * s),
          q + decay * ((omega_d * c2 - zeta * omega * c1) * c -
                       (zeta * omega * c2 + omega_d * c1) * s)};
}

struct LinearInputCase {
  const char* name;
  double a0, rate, period, zeta, time_step;
  std::size_t samples;
};

std::ostream& operator<<(std::ostream& out, const LinearInputCase& c) { return out << c.name; }

class NigamJenningsExact : public ::testing::TestWithParam<LinearInputCase> {};

double largest_magnitude(const std::vector<double>& values) {
  double largest = 0.0;
  for (double value : values) largest = std::max(largest, std::abs(value));
  return largest;
}

// Largest |computed - exact| over the history, relative to `scale`.
double relative_error(const std::vector<double>& computed, const std::vector<double>& exact,
                      double scale) {
  double error = 0.0;
  for (std::size_t k = 0; k < exact.size(); ++k)
    error = std::max(error, std::abs(computed[k] - exact[k]));
  return error / scale;
}

TEST_P(NigamJenningsExact, MatchesTheClosedForm) {
  const LinearInputCase& c = GetParam();
  const GroundMotion motion =
      sampled([&](double t) { return c.a0 + c.rate * t; }, c.time_step, c.samples);
  const SdofResponse response = sdof_response(motion, c.period, c.zeta);
  ASSERT_EQ(response.displacement.size(), c.samples);
  const double omega = 2.0 * kPi / c.period;
  std::vector<double> u, v, absolute;
  for (std::size_t k = 0; k < c.samples; ++k) {
    const double t = static_cast<double>(k) * c.time_step;
    const ExactState exact = exact_linear_input(c.a0, c.rate, omega, c.zeta, t);
    u.push_back(exact.displacement);
    v.push_back(exact.velocity);
    absolute.push_back(
        -(2.0 * c.zeta * omega * exact.velocity + omega * omega * exact.displacement));
  }
  const double u_error = relative_error(response.displacement, u, largest_magnitude(u));
  // The recurrence carries u and v together, so its velocity error scales with w |u| as well as
  // |v| (w |u| / |v| = w t for a slow ramp).
  const double velocity_scale = std::max(largest_magnitude(v), omega * largest_magnitude(u));
  const double v_error = relative_error(response.velocity, v, velocity_scale);
  const double a_error =
      relative_error(response.absolute_acceleration, absolute, largest_magnitude(absolute));
  std::cout << c.name << ": relative error displacement " << u_error << ", velocity " << v_error
            << ", absolute acceleration " << a_error << "\n";
  EXPECT_LE(u_error, 1e-12);
  EXPECT_LE(v_error, 1e-12);
  EXPECT_LE(a_error, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(
    GroundMotion, NigamJenningsExact,
    ::testing::Values(LinearInputCase{"step_damped", 2.5, 0.0, 1.0, 0.05, 0.01, 1001},
                      LinearInputCase{"step_undamped", 2.5, 0.0, 1.0, 0.0, 0.01, 1001},
                      LinearInputCase{"ramp_damped", 0.0, 0.7, 0.5, 0.05, 0.01, 1001},
                      LinearInputCase{"ramp_undamped", 0.0, 0.7, 0.5, 0.0, 0.01, 1001},
                      LinearInputCase{"step_and_ramp_heavily_damped", -1.0, 3.0, 2.0, 0.4, 0.02,
                                      501},
                      LinearInputCase{"step_long_period", 2.5, 0.0, 10.0, 0.05, 0.005, 8001},
                      LinearInputCase{"ramp_short_period", 0.0, 0.7, 0.02, 0.05, 0.005, 2001}),
    [](const ::testing::TestParamInfo<LinearInputCase>& test) { return test.param.name; });

// The step response's first peak is at t = pi/wd with u = -a/w^2 (1 + e^{-z pi/sqrt(1-z^2)}):
// with a sample exactly there, Sa is exact.
TEST(GroundMotion, SpectralAccelerationOfAStepIsTheFirstPeak) {
  for (const double zeta : {0.0, 0.02, 0.05, 0.2}) {
    const double period = 0.8, a = 3.0;
    const double omega_d = 2.0 * kPi / period * std::sqrt(1.0 - zeta * zeta);
    const double time_step = kPi / omega_d / 50.0;
    const GroundMotion step = sampled([&](double) { return a; }, time_step, 76);
    const double expected = a * (1.0 + std::exp(-zeta * kPi / std::sqrt(1.0 - zeta * zeta)));
    const double error = std::abs(spectral_acceleration(step, period, zeta) - expected) / expected;
    std::cout << "zeta " << zeta << ": Sa of a step, relative error " << error << "\n";
    EXPECT_LE(error, 1e-12);
  }
}

// Undamped resonance: u = A/(2w) t cos wt - A/(2w^2) sin wt, so Sa grows as A pi N over N
// cycles; with damping it levels off at A/(2 zeta). The record is the sine sampled at T/200,
// whose linear interpolation lowers the amplitude by about (w dt)^2/12 = 8e-5.
TEST(GroundMotion, ResonantSpectralAccelerationGrowsLinearlyUndamped) {
  const double period = 0.5, amplitude = 2.0, time_step = period / 200.0;
  const double omega = 2.0 * kPi / period;
  for (const int cycles : {1, 2, 4, 8, 16}) {
    const GroundMotion sine = sampled([&](double t) { return amplitude * std::sin(omega * t); },
                                      time_step, static_cast<std::size_t>(200 * cycles) + 1);
    const double ratio = spectral_acceleration(sine, period, 0.0) / (amplitude * kPi * cycles);
    std::cout << cycles << " cycles: Sa / (A pi N) = " << ratio << "\n";
    EXPECT_NEAR(ratio, 1.0, 1e-3);
  }
  const GroundMotion long_sine =
      sampled([&](double t) { return amplitude * std::sin(omega * t); }, time_step, 200 * 40 + 1);
  const double steady = spectral_acceleration(long_sine, period, 0.05) / (amplitude / 0.1);
  std::cout << "damped steady state: Sa / (A / (2 zeta)) = " << steady << "\n";
  EXPECT_NEAR(steady, 1.0, 1e-3);
}

// A test record: enveloped sum of three sines.
GroundMotion wiggly_record() {
  return sampled(
      [](double t) {
        return t * std::exp(-0.5 * t) *
               (std::sin(7.0 * t) + 0.5 * std::sin(19.0 * t + 1.0) - 0.3 * std::cos(3.0 * t));
      },
      0.01, 2001);
}

// The time of the largest |a|: a negative peak counts, and of equal peaks the first.
TEST(GroundMotion, TimeOfPeakIsTheFirstLargestMagnitude) {
  const GroundMotion motion{
      .name = "r", .time_step = 0.02, .acceleration = {0.0, 1.0, -3.0, 2.0, 3.0, -1.0}};
  EXPECT_DOUBLE_EQ(motion.time_of_peak(), 0.04);
  EXPECT_EQ(GroundMotion{}.time_of_peak(), 0.0);
}

TEST(GroundMotion, ScaleToPeakHitsTheTarget) {
  GroundMotion motion = wiggly_record();
  const double target = 0.35 * 9.80665;
  scale(motion, scale_to_peak(motion, target));
  const double error = std::abs(motion.peak() - target) / target;
  std::cout << "peak after scaling: relative error " << error << "\n";
  EXPECT_LE(error, 1e-12);
}

TEST(GroundMotion, ScaleToSpectralAccelerationHitsTheTarget) {
  for (const double period : {0.1, 0.5, 1.0, 3.0}) {
    GroundMotion motion = wiggly_record();
    const double target = 0.8;
    scale(motion, scale_to_spectral_acceleration(motion, target, period, 0.05));
    const double error = std::abs(spectral_acceleration(motion, period, 0.05) - target) / target;
    std::cout << "T = " << period << " s: Sa after scaling, relative error " << error << "\n";
    EXPECT_LE(error, 1e-12);
  }
}

TEST(GroundMotion, PeriodZeroGivesThePeak) {
  const GroundMotion motion = wiggly_record();
  EXPECT_EQ(spectral_acceleration(motion, 0.0, 0.05), motion.peak());
}

TEST(GroundMotion, SpectralAccelerationAgreesWithTheResponseHistory) {
  const GroundMotion motion = wiggly_record();
  const SdofResponse response = sdof_response(motion, 0.7, 0.05);
  double largest = 0.0;
  for (double u : response.displacement) largest = std::max(largest, std::abs(u));
  const double omega = 2.0 * kPi / 0.7;
  EXPECT_DOUBLE_EQ(spectral_acceleration(motion, 0.7, 0.05), omega * omega * largest);
}

// The record is zero after its last sample, as a run takes it, and an oscillator longer than the
// record peaks in its free vibration after it: two cycles of a 1 s sine (ending at a zero sample)
// under a 5 s oscillator. Sa is that free vibration's exact first extremum: the same record padded
// with 10 s of zeros, sampled every 5 ms, gives it to (w dt)^2 / 8 = 5e-6; at T = 5 s the samples
// alone gave 0.61 of it (audit 71: 3 s of a record scaled to Sa(1 s) = 0.25 g ran at 0.42 g).
// At 2 s and 20 s the peak is inside the record, which both give alike.
TEST(GroundMotion, SpectralAccelerationTakesTheFreeVibrationAfterTheRecord) {
  const double time_step = 0.005;
  const auto pulse = [](double t) { return t <= 2.0 ? 3.0 * std::sin(2.0 * kPi * t) : 0.0; };
  const GroundMotion short_record = sampled(pulse, time_step, 401);
  const GroundMotion padded = sampled(pulse, time_step, 401 + 2000);
  for (const double period : {2.0, 5.0, 20.0}) {
    const double with_free = spectral_acceleration(short_record, period, 0.05);
    const double sampled_free = spectral_acceleration(padded, period, 0.05);
    const SdofResponse response = sdof_response(short_record, period, 0.05);
    double largest = 0.0;
    for (double u : response.displacement) largest = std::max(largest, std::abs(u));
    const double omega = 2.0 * kPi / period;
    std::cout << "T = " << period << " s: Sa " << with_free << ", the padded record's "
              << sampled_free << " (relative " << with_free / sampled_free - 1.0
              << "), over the samples alone " << omega * omega * largest << "\n";
    EXPECT_GE(with_free, sampled_free);
    EXPECT_NEAR(with_free / sampled_free, 1.0, 1e-5);
    if (period == 5.0) {
      EXPECT_GT(with_free, 1.5 * omega * omega * largest);
    }
  }
}

// free_vibration_peak: |u| where the motion decays from the start, else the first extremum of
// the damped free vibration, against a fine sampling of its closed form.
TEST(GroundMotion, FreeVibrationPeakIsTheFirstExtremum) {
  const double omega = 3.0;
  for (const double zeta : {0.0, 0.05, 0.5})
    for (const auto& [u, v] :
         {std::pair{1.0, 0.0}, {0.0, 2.0}, {1.0, 5.0}, {-1.0, 5.0}, {1.0, -0.1}, {0.0, 0.0}}) {
      const double omega_d = omega * std::sqrt(1.0 - zeta * zeta);
      const double c = (v + zeta * omega * u) / omega_d;
      double largest = 0.0;
      for (int k = 0; k <= 200000; ++k) {
        const double t = k * 1e-5;
        largest =
            std::max(largest, std::abs(std::exp(-zeta * omega * t) *
                                       (u * std::cos(omega_d * t) + c * std::sin(omega_d * t))));
      }
      const double peak = free_vibration_peak(u, v, omega, zeta);
      EXPECT_NEAR(peak, largest, 1e-9 * std::max(1.0, largest))
          << "zeta " << zeta << ", u " << u << ", v " << v;
      EXPECT_GE(peak, largest - 1e-15);
    }
}

TEST(GroundMotion, InterpolatesAndIsAtRestOutsideTheRecord) {
  GroundMotion motion;
  motion.time_step = 0.1;
  motion.acceleration = {1.0, 3.0, -1.0};
  EXPECT_DOUBLE_EQ(motion.duration(), 0.2);
  EXPECT_DOUBLE_EQ(motion.peak(), 3.0);
  EXPECT_DOUBLE_EQ(motion.at(0.0), 1.0);
  EXPECT_DOUBLE_EQ(motion.at(0.05), 2.0);
  EXPECT_DOUBLE_EQ(motion.at(0.15), 1.0);
  EXPECT_DOUBLE_EQ(motion.at(2 * 0.1), -1.0);  // the last sample, though 2 * 0.1 != 0.2
  EXPECT_EQ(motion.at(0.21), 0.0);             // after the record: at rest
  EXPECT_EQ(motion.at(0.3), 0.0);
  EXPECT_EQ(motion.at(-0.01), 0.0);
  EXPECT_EQ(GroundMotion{}.at(1.0), 0.0);
  EXPECT_EQ(GroundMotion{}.duration(), 0.0);
}

TEST(GroundMotion, RejectsInvalidOscillatorsAndRecords) {
  const GroundMotion motion = wiggly_record();
  EXPECT_THROW(spectral_acceleration(motion, -1.0, 0.05), std::invalid_argument);
  EXPECT_THROW(spectral_acceleration(motion, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(sdof_response(motion, 0.0, 0.05), std::invalid_argument);
  EXPECT_THROW(sdof_response(GroundMotion{}, 1.0, 0.05), std::invalid_argument);
  EXPECT_THROW(scale_to_peak(sampled([](double) { return 0.0; }, 0.01, 10), 1.0),
               std::invalid_argument);
}

}  // namespace
}  // namespace pound::model
