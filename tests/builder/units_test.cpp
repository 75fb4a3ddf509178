// Issue 16 item 5: the force unit a model's units imply, mass x length / time^2, named.
#include <gtest/gtest.h>

#include "builder/spec.hpp"

namespace pound::builder {
namespace {

std::optional<std::string> force(const char* length, const char* time, const char* mass) {
  UnitsSpec units{length, time, mass ? std::optional<std::string>(mass) : std::nullopt};
  return units.force();
}

TEST(UnitsSpec, ForceUnitIsMassTimesLengthOverTimeSquared) {
  EXPECT_EQ(force("m", "s", "kg"), "N");
  EXPECT_EQ(force("m", "s", "t"), "kN");     // 1000 kg m/s^2
  EXPECT_EQ(force("mm", "s", "t"), "N");     // 1000 kg x 0.001 m
  EXPECT_EQ(force("mm", "ms", "kg"), "kN");  // 1e-3 m / 1e-6 s^2
  EXPECT_EQ(force("km", "s", "t"), "MN");
  EXPECT_EQ(force("in", "s", "kg"), "kg·in/s²");  // no named unit: the product written out
  EXPECT_EQ(force("m", "s", nullptr), std::nullopt);
}

}  // namespace
}  // namespace pound::builder
