#include "model/direction.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace pound::model {
namespace {

// Plane scenes keep the numbering every 2-D result and message has used: x, y, rotation.
TEST(Direction, PlaneScenesNumberXYAndTheRotationAboutZ) {
  for (int dimension : {1, 2}) {
    EXPECT_EQ(direction_count(dimension), 3);
    EXPECT_EQ(std::string(direction(0, dimension).symbol), "x");
    EXPECT_EQ(std::string(direction(1, dimension).symbol), "y");
    const Direction rotation = direction(2, dimension);
    EXPECT_EQ(std::string(rotation.symbol), "rz");
    EXPECT_EQ(std::string(rotation.words), "rotation");
    EXPECT_TRUE(rotation.rotation);
    EXPECT_EQ(rotation.axis, 2);
    EXPECT_FALSE(direction(1, dimension).rotation);
    EXPECT_THROW(direction(3, dimension), std::out_of_range);
  }
}

// 3-D scenes follow the 12-DOF beam-column's order: three translations, then the rotations.
TEST(Direction, SpaceScenesNumberTheTranslationsThenTheRotations) {
  EXPECT_EQ(direction_count(3), 6);
  const char* symbols[] = {"x", "y", "z", "rx", "ry", "rz"};
  for (int d = 0; d < 6; ++d) {
    const Direction along = direction(d, 3);
    EXPECT_EQ(std::string(along.symbol), symbols[d]);
    EXPECT_EQ(along.rotation, d >= 3);
    EXPECT_EQ(along.axis, d % 3);
  }
  EXPECT_EQ(std::string(direction(4, 3).words), "rotation about y");
  EXPECT_THROW(direction(6, 3), std::out_of_range);
  EXPECT_THROW(direction(-1, 3), std::out_of_range);
}

}  // namespace
}  // namespace pound::model
