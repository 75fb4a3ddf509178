// Floor spectra on states made by hand: the spectrum of a node's absolute acceleration equals the
// spectrum of the same signal computed directly as a record (model::spectral_acceleration), with
// steps of any length.
#include "results/spectrum_recorder.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/dof_readings.hpp"
#include "support/vectors.hpp"

namespace pound::results {
namespace {

using testing::dof;
using testing::entries;

// A ground at rest: the node's absolute acceleration is its relative one.
GroundAcceleration still_ground() {
  return {1,
          [](double, std::vector<double>& scales) { scales.clear(); },
          {},
          [](Index, int, double) { return 0.0; }};
}

// A floor's acceleration: a decaying pair of sines sampled every 0.01 s for 4 s.
model::GroundMotion floor_signal() {
  model::GroundMotion signal{"floor", 0.01, {}};
  for (int k = 0; k <= 400; ++k) {
    const double t = 0.01 * k;
    signal.acceleration.push_back(std::exp(-0.3 * t) *
                                  (3.0 * std::sin(2.0 * M_PI * 2.1 * t) + std::sin(9.0 * t)));
  }
  return signal;
}

integrators::State node_state(double time, double acceleration) {
  integrators::State state;
  state.time = time;
  state.displacement = entries({0.0});
  state.velocity = entries({0.0});
  state.acceleration = entries({acceleration});
  return state;
}

const std::vector<double> kPeriods = {0.0, 0.05, 0.2, 0.476, 1.0, 3.0};
const std::vector<double> kDampings = {0.02, 0.05};

TEST(SpectrumRecorder, EqualsTheSpectrumOfTheSameSignalAsARecord) {
  GroundAcceleration ground = still_ground();
  SpectrumRecorder recorder("floor.csv", {{"roof", dof(0), 4, 0}}, kPeriods, kDampings, ground);
  const model::GroundMotion signal = floor_signal();
  for (std::size_t k = 0; k < signal.acceleration.size(); ++k)
    recorder.record(node_state(0.01 * static_cast<double>(k), signal.acceleration[k]));
  const Table table = recorder.table();
  EXPECT_EQ(table.columns, (std::vector<std::string>{"period", "roof.sa_x_2%", "roof.sa_x_5%"}));
  EXPECT_EQ(table.values[0], kPeriods);
  for (std::size_t d = 0; d < kDampings.size(); ++d)
    for (std::size_t p = 0; p < kPeriods.size(); ++p) {
      const double direct = model::spectral_acceleration(signal, kPeriods[p], kDampings[d]);
      EXPECT_EQ(table.values[d + 1][p], direct) << "T = " << kPeriods[p];
    }
}

// The signal linear between samples, resampled `parts` times finer.
model::GroundMotion finer(const model::GroundMotion& signal, int parts) {
  model::GroundMotion fine{"fine", signal.time_step / parts, {}};
  const auto steps = static_cast<int>(signal.acceleration.size() - 1) * parts;
  for (int k = 0; k <= steps; ++k) fine.acceleration.push_back(signal.at(k * fine.time_step));
  return fine;
}

// Steps of 1 to 4 sub-steps at varying places (the cut steps of a run), the signal linear
// between the record's samples: the response at the shared times is the same, and the peak is
// taken at more of them, so Sa lies between the spectrum at the record's samples and the one
// on a grid 12 times finer (which holds every sub-step time).
TEST(SpectrumRecorder, StepsOfAnyLengthFollowTheLinearlyInterpolatedSignal) {
  GroundAcceleration ground = still_ground();
  SpectrumRecorder recorder("floor.csv", {{"roof", dof(0), 4, 0}}, kPeriods, {0.05}, ground);
  const model::GroundMotion signal = floor_signal();
  for (std::size_t k = 0; k < signal.acceleration.size(); ++k) {
    const int parts = k == 0 ? 1 : static_cast<int>(1 + (k * 7) % 4);
    for (int part = parts - 1; part >= 0; --part) {
      const double time = 0.01 * (static_cast<double>(k) - static_cast<double>(part) / parts);
      recorder.record(node_state(time, signal.at(time)));
    }
  }
  const Table table = recorder.table();
  const model::GroundMotion fine = finer(signal, 12);
  double widest = 0.0;
  for (std::size_t p = 0; p < kPeriods.size(); ++p) {
    const double coarse = model::spectral_acceleration(signal, kPeriods[p], 0.05);
    const double finest = model::spectral_acceleration(fine, kPeriods[p], 0.05);
    EXPECT_GE(table.values[1][p], coarse * (1.0 - 1e-12)) << "T = " << kPeriods[p];
    EXPECT_LE(table.values[1][p], finest * (1.0 + 1e-12)) << "T = " << kPeriods[p];
    widest = std::max(widest, (finest - coarse) / finest);
  }
  std::printf("Sa within its bounds; the bounds differ by up to %.2f %%\n", 100.0 * widest);
}

}  // namespace
}  // namespace pound::results
