// The ground's acceleration added to relative ones: formed only at the DOFs read, or as the whole
// frame when an observer asks for it, the same numbers either way.
#include "results/ground_acceleration.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "support/vectors.hpp"

namespace pound::results {
namespace {

using testing::entries;

// Two records along x and y (3 DOFs: x, y, and a rotation they do not drive), and a moving
// support whose influence reaches all three.
GroundAcceleration two_records_and_a_support(int& scale_reads) {
  return {3,
          [&scale_reads](double time, std::vector<double>& scales) {
            ++scale_reads;
            scales = {std::sin(7.0 * time), 0.3 * std::cos(5.0 * time), 0.1 * time};
          },
          {entries({1.0, 0.0, 0.0}), entries({0.0, 1.0, 0.0}), entries({0.7, -0.2, 0.05})},
          [](Index, int, double time) { return std::sin(7.0 * time); }};
}

integrators::State at(double time) {
  integrators::State state;
  state.time = time;
  state.acceleration = entries({0.25, -0.5, 2.0});
  return state;
}

TEST(GroundAcceleration, AnEntryReadAloneIsTheWholeFramesEntry) {
  int reads_alone = 0, reads_whole = 0;
  GroundAcceleration alone = two_records_and_a_support(reads_alone);
  GroundAcceleration whole = two_records_and_a_support(reads_whole);
  const DofReading reading{{0, 0.6}, {1, 0.8}, {2, 1.5}};  // a corner of a rigid floor
  double largest_difference = 0.0;
  for (int k = 1; k <= 200; ++k) {
    const integrators::State state = at(0.013 * k);
    const Vector& frame = whole.frame(state.time);
    const double from_whole = whole.absolute(state, reading, 4, 0);
    const double from_alone = alone.absolute(state, reading, 4, 0);
    ASSERT_EQ(from_alone, from_whole) << "t = " << state.time;  // to the bit
    // Against the sum written out: the frame is sin 7t + 0.7 (0.1 t) at x, and so on.
    const double s = std::sin(7.0 * state.time), c = 0.3 * std::cos(5.0 * state.time),
                 r = 0.1 * state.time;
    const Vector expected_frame = entries({s + 0.7 * r, c - 0.2 * r, 0.05 * r});
    largest_difference =
        std::max(largest_difference, (frame - expected_frame).cwiseAbs().maxCoeff());
    const double expected = 0.6 * (0.25 + expected_frame[0]) + 0.8 * (-0.5 + expected_frame[1]) +
                            1.5 * (2.0 + expected_frame[2]);
    ASSERT_NEAR(from_alone, expected, 1e-15) << "t = " << state.time;
  }
  std::cout << "largest difference of the frame from its sums written out: " << largest_difference
            << "\n";
  EXPECT_LE(largest_difference, 4e-16);
  // The ground's values are read once per time, however many DOFs are read then.
  EXPECT_EQ(reads_alone, 200);
  EXPECT_EQ(reads_whole, 200);
}

TEST(GroundAcceleration, WithoutRecordsTheFrameIsZeroAtEveryDof) {
  GroundAcceleration still(
      3, [](double, std::vector<double>& scales) { scales.clear(); }, {},
      [](Index, int, double) { return 0.0; });
  EXPECT_EQ(still.frame(1.0), Vector::Zero(3));
  EXPECT_EQ(still.absolute(at(1.0), {{2, 2.0}}, 0, 0), 4.0);
  // A fixed DOF (no terms) is the support's own.
  EXPECT_EQ(still.absolute(at(1.0), {}, 0, 0), 0.0);
}

}  // namespace
}  // namespace pound::results
