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
  EXPECT_EQ(force("in", "s", "kg"), "kg*in/s^2");  // no named unit: the product written out
  EXPECT_EQ(force("m", "s", nullptr), std::nullopt);
}

// What CSV headers name: every dimension in the model's units, forces only with a mass unit.
TEST(UnitsSpec, NamesEveryDimensionInTheModelsUnits) {
  const UnitNames named = UnitsSpec{"mm", "s", std::string("t")}.names();
  EXPECT_EQ(named.of(Dimension::time), "s");
  EXPECT_EQ(named.of(Dimension::length), "mm");
  EXPECT_EQ(named.of(Dimension::velocity), "mm/s");
  EXPECT_EQ(named.of(Dimension::acceleration), "mm/s^2");
  EXPECT_EQ(named.of(Dimension::force), "N");
  EXPECT_EQ(named.of(Dimension::moment), "N*mm");
  EXPECT_EQ(named.of(Dimension::angle), "rad");
  EXPECT_EQ(named.of(Dimension::angular_velocity), "rad/s");
  EXPECT_EQ(named.of(Dimension::angular_acceleration), "rad/s^2");
  EXPECT_EQ(named.of(Dimension::none), "");
  const UnitNames massless = UnitsSpec{"m", "ms", std::nullopt}.names();
  EXPECT_EQ(massless.of(Dimension::acceleration), "m/ms^2");
  EXPECT_EQ(massless.of(Dimension::force), "");
  EXPECT_EQ(massless.of(Dimension::moment), "");
}

}  // namespace
}  // namespace pound::builder
