// Record pairs: RotD50, RotD100 and the geometric mean of two horizontal components against the
// closed forms a linear oscillator gives for components that are copies or multiples of one
// another, their invariance under a rotation of the pair, and pairs that are refused.
#include "model/record_pair.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

namespace pound::model {
namespace {

constexpr double kPi = std::numbers::pi;

GroundMotion sampled(const std::string& name, const std::function<double(double)>& acceleration,
                     double time_step = 0.01, std::size_t samples = 2001) {
  GroundMotion motion;
  motion.name = name;
  motion.time_step = time_step;
  for (std::size_t k = 0; k < samples; ++k)
    motion.acceleration.push_back(acceleration(static_cast<double>(k) * time_step));
  return motion;
}

// A decaying two-frequency signal, unlike its partner below, so that the pair is polarised in no
// simple way.
double first_signal(double t) {
  return std::exp(-0.15 * t) *
         (std::sin(2.0 * kPi * 1.3 * t) + 0.6 * std::sin(2.0 * kPi * 3.1 * t));
}
double second_signal(double t) {
  return std::exp(-0.1 * t) *
         (0.8 * std::cos(2.0 * kPi * 0.7 * t) - 0.5 * std::sin(2.0 * kPi * 5.3 * t));
}

double relative(double value, double reference) { return std::abs(value / reference - 1.0); }

TEST(RecordPair, EqualComponentsGiveRotD50TheirSaAndRotD100RootTwoTimesIt) {
  // u(theta) = u (cos + sin) = sqrt(2) u sin(theta + 45): the median of |sin| over the whole
  // degrees is sin 45 exactly (each of 1..89 degrees twice, 0 and 90 once), its largest 1 at 45.
  const GroundMotionPair pair =
      make_component_pair(sampled("a", first_signal), sampled("b", first_signal));
  for (double period : {0.0, 0.1, 0.5, 2.0}) {
    const PairSpectralAcceleration sa = pair_spectral_acceleration(pair, period, 0.05);
    const double d50 = relative(sa.rot_d50, sa.first);
    const double d100 = relative(sa.rot_d100, std::sqrt(2.0) * sa.first);
    std::printf("T = %.1f s: Sa %.6g, RotD50 / Sa - 1 = %.1e, RotD100 / (sqrt 2 Sa) - 1 = %.1e\n",
                period, sa.first, d50, d100);
    EXPECT_LT(d50, 1e-14);
    EXPECT_LT(d100, 1e-14);
    EXPECT_EQ(sa.rot_d100_angle, 45.0);
    EXPECT_EQ(sa.geometric_mean, sa.first);
  }
}

TEST(RecordPair, OneComponentAloneGivesRotD50ItsSaOverRootTwo) {
  // u(theta) = u_1 cos(theta): peaks Sa_1 |cos|, median Sa_1 sin 45, largest Sa_1 at 0 degrees.
  const GroundMotionPair pair =
      make_component_pair(sampled("a", first_signal), sampled("zero", [](double) { return 0.0; }));
  for (double period : {0.0, 0.3, 1.0}) {
    const PairSpectralAcceleration sa = pair_spectral_acceleration(pair, period, 0.05);
    const double d50 = relative(sa.rot_d50, sa.first / std::sqrt(2.0));
    std::printf("T = %.1f s: RotD50 / (Sa / sqrt 2) - 1 = %.1e\n", period, d50);
    EXPECT_LT(d50, 1e-14);
    EXPECT_EQ(sa.rot_d100, sa.first);
    EXPECT_EQ(sa.rot_d100_angle, 0.0);
    EXPECT_EQ(sa.second, 0.0);
    EXPECT_EQ(sa.geometric_mean, 0.0);
  }
}

TEST(RecordPair, APolarisedGroundMotionPeaksInItsDirection) {
  // Ground motion along 30 degrees: at period 0 the peaks are |cos(theta - 30)| of its peak.
  const double c = std::cos(kPi / 6.0), s = std::sin(kPi / 6.0);
  const GroundMotionPair pair =
      make_component_pair(sampled("a", [&](double t) { return c * first_signal(t); }),
                          sampled("b", [&](double t) { return s * first_signal(t); }));
  const double peak = sampled("a", first_signal).peak();
  const PairSpectralAcceleration sa = pair_spectral_acceleration(pair, 0.0, 0.05);
  std::printf("RotD100 / peak - 1 = %.1e at %g degrees; RotD50 / (peak sin 45) - 1 = %.1e\n",
              relative(sa.rot_d100, peak), sa.rot_d100_angle,
              relative(sa.rot_d50, peak / std::sqrt(2.0)));
  EXPECT_EQ(sa.rot_d100_angle, 30.0);
  EXPECT_LT(relative(sa.rot_d100, peak), 1e-14);
  EXPECT_LT(relative(sa.rot_d50, peak / std::sqrt(2.0)), 1e-14);
}

TEST(RecordPair, RotDIsIndependentOfTheOrientationOfTheSensors) {
  const GroundMotionPair pair =
      make_component_pair(sampled("a", first_signal), sampled("b", second_signal));
  for (double period : {0.0, 0.2, 1.0}) {
    const PairSpectralAcceleration original = pair_spectral_acceleration(pair, period, 0.05);
    for (double degrees : {30.0, 117.0, -45.0}) {
      const PairSpectralAcceleration turned =
          pair_spectral_acceleration(rotated(pair, degrees * kPi / 180.0), period, 0.05);
      const double d50 = relative(turned.rot_d50, original.rot_d50);
      const double d100 = relative(turned.rot_d100, original.rot_d100);
      std::printf(
          "T = %.1f s turned %+g degrees: RotD50 %.1e, RotD100 %.1e apart; GM %.3g -> %.3g\n",
          period, degrees, d50, d100, original.geometric_mean, turned.geometric_mean);
      EXPECT_LT(d50, 1e-12);
      EXPECT_LT(d100, 1e-12);
      // The direction of the peak turns with the sensors.
      EXPECT_NEAR(std::fmod(turned.rot_d100_angle + degrees + 360.0, 180.0),
                  original.rot_d100_angle, 1e-9);
    }
    EXPECT_GE(original.rot_d100, std::max(original.first, original.second));
    EXPECT_LE(original.rot_d50, original.rot_d100);
  }
}

// A short pair under a long oscillator peaks in the free vibration after its last samples, in
// every direction: its RotD50 and RotD100 are those of the pair padded with 10 s of zeros, to that
// sampling's (w dt)^2 / 8, and each component's Sa is spectral_acceleration's.
TEST(RecordPair, AShortPairsRotDTakesTheFreeVibrationAfterIt) {
  const auto first = [](double t) { return t <= 2.0 ? 3.0 * std::sin(2.0 * kPi * t) : 0.0; };
  const auto second = [](double t) { return t <= 2.0 ? 2.0 * std::sin(kPi * t) : 0.0; };
  const GroundMotionPair short_pair = make_component_pair(sampled("first", first, 0.005, 401),
                                                          sampled("second", second, 0.005, 401));
  const GroundMotionPair padded = make_component_pair(sampled("first", first, 0.005, 2401),
                                                      sampled("second", second, 0.005, 2401));
  for (const double period : {2.0, 5.0}) {
    const PairSpectralAcceleration with_free = pair_spectral_acceleration(short_pair, period, 0.05);
    const PairSpectralAcceleration sampled_free = pair_spectral_acceleration(padded, period, 0.05);
    std::printf("T = %g s: RotD50 %.8g, padded %.8g; RotD100 %.8g, padded %.8g\n", period,
                with_free.rot_d50, sampled_free.rot_d50, with_free.rot_d100, sampled_free.rot_d100);
    EXPECT_LT(relative(with_free.rot_d50, sampled_free.rot_d50), 1e-5);
    EXPECT_LT(relative(with_free.rot_d100, sampled_free.rot_d100), 1e-5);
    EXPECT_EQ(with_free.first, spectral_acceleration(short_pair.first, period, 0.05));
    EXPECT_EQ(with_free.second, spectral_acceleration(short_pair.second, period, 0.05));
  }
}

TEST(RecordPair, ComponentsOnDifferentTimeGridsAreRefusedNamingBoth) {
  const auto refused = [](GroundMotion a, GroundMotion b, const std::string& what) {
    try {
      make_component_pair(std::move(a), std::move(b));
      ADD_FAILURE() << "accepted";
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      std::printf("%s\n", message.c_str());
      EXPECT_NE(message.find("'north.AT2' and 'east.AT2'"), std::string::npos);
      EXPECT_NE(message.find(what), std::string::npos);
    }
  };
  refused(sampled("north.AT2", first_signal, 0.01, 2001),
          sampled("east.AT2", first_signal, 0.01, 2000), "as many samples (2001 and 2000)");
  refused(sampled("north.AT2", first_signal, 0.01, 2001),
          sampled("east.AT2", first_signal, 0.005, 2001), "one time step");
  // A pair put together by hand is checked where it is used.
  const GroundMotionPair uneven{sampled("north.AT2", first_signal, 0.01, 2001),
                                sampled("east.AT2", first_signal, 0.01, 1000)};
  EXPECT_THROW(pair_spectral_acceleration(uneven, 1.0, 0.05), std::invalid_argument);
  EXPECT_THROW(rotated(uneven, 0.3), std::invalid_argument);
}

}  // namespace
}  // namespace pound::model
