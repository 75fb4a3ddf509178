// `pound pushover`: the capacity curve of the bundled hinged bridge, written with its summary;
// bad requests are refused before anything is written.
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

}  // namespace
}  // namespace pound::testing
