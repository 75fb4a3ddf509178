// `pound pushover`: the capacity curve of the bundled hinged bridge, written with its summary;
// bad requests, and models with hard contacts, are refused before anything is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>

#include "support/process.hpp"

namespace pound::testing {
namespace {

class PushoverCommand : public PoundProcess {};

const std::string kModel = std::string(POUND_SOURCE_DIR) + "/models/three_span_bridge_takeda.json";

TEST_F(PushoverCommand, WritesTheCapacityCurveAndFindsTheFirstYield) {
  const Outcome outcome = pound({"pushover", kModel, "--node", "bridge.p1.top", "--to", "0.02",
                                 "--increments", "50", "--out", path("out").string()});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  std::cout << outcome.out;
  const std::string csv = read_text(path("out") / "pushover.csv");
  EXPECT_TRUE(contains(csv, "displacement,base_shear,iterations,bridge.p1.hinge.deformation"));
  const std::string summary = read_text(path("out") / "pushover.json");
  EXPECT_TRUE(contains(summary, "\"status\": \"completed\""));
  // The pier yields at its top displacement M_y h^2 / (3 E I) = 3.56 mm: the first point past it.
  EXPECT_TRUE(contains(summary, "\"link\": \"bridge.p1.hinge\"")) << summary;
  EXPECT_TRUE(contains(outcome.out, "first yield: bridge.p1.hinge at displacement 0.0036"))
      << outcome.out;
}

TEST_F(PushoverCommand, BadRequestsAreRefusedAndNothingIsWritten) {
  const auto run = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> arguments{"pushover", kModel, "--out", path("out").string()};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return pound(arguments);
  };
  Outcome outcome = run({"--node", "no_such_node", "--to", "0.01"});
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_TRUE(contains(outcome.err, "--node")) << outcome.err;
  outcome = run({"--node", "bridge.p1.base", "--to", "0.01"});
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_TRUE(contains(outcome.err, "fixed along x")) << outcome.err;
  outcome = run({"--node", "bridge.p1.top", "--to", "0"});
  EXPECT_EQ(outcome.exit_code, 1);
  outcome = run({"--node", "bridge.p1.top", "--to", "0.01", "--pattern", "wavy"});
  EXPECT_EQ(outcome.exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(path("out")));
}

// A hard contact has no force law for the push's Newton: the bundled hard-contact bridge was
// pushed 0.3 m through its joints (peak base shear 3.1 MN against 15.1 MN with its gap springs).
// Refused with the file, the link's entry and a way out, and nothing written.
TEST_F(PushoverCommand, AModelWithHardContactsIsRefusedNamingTheLink) {
  const Outcome outcome = pound(
      {"pushover", std::string(POUND_SOURCE_DIR) + "/models/three_span_bridge_hard_contact.json",
       "--node", "bridge.g1.n2", "--to", "0.3", "--out", path("out").string()});
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_TRUE(contains(outcome.err,
                       "three_span_bridge_hard_contact.json: /generators/0: link "
                       "'bridge.joint1' is a hard_contact"))
      << outcome.err;
  EXPECT_FALSE(std::filesystem::exists(path("out")));
}

}  // namespace
}  // namespace pound::testing
