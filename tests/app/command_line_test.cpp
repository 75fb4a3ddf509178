// The command-line parsing every subcommand shares: named options, one positional argument,
// --help printing the options, and what it refuses.
#include "app/command_line.hpp"

#include <gtest/gtest.h>

namespace pound::app {
namespace {

namespace po = boost::program_options;

po::options_description options() {
  po::options_description described("options");
  described.add_options()("help,h", "show this help")("count", po::value<int>()->default_value(6),
                                                      "how many modes")("json", "print JSON");
  return described;
}

TEST(CommandLine, ReadsOptionsAndThePositionalArgumentInAnyOrder) {
  std::string model;
  const auto parsed =
      parse_command_line({"--count", "3", "model.json", "--json"}, options(), "model", model);
  ASSERT_TRUE(parsed.has_value());
  EXPECT_EQ(model, "model.json");
  EXPECT_EQ((*parsed)["count"].as<int>(), 3);
  EXPECT_EQ(parsed->count("json"), 1u);
}

TEST(CommandLine, DefaultsHoldAndThePositionalMayBeAbsent) {
  std::string model;
  const auto parsed = parse_command_line({}, options(), "model", model);
  ASSERT_TRUE(parsed.has_value());
  EXPECT_EQ(model, "");
  EXPECT_EQ((*parsed)["count"].as<int>(), 6);
  EXPECT_EQ(parsed->count("json"), 0u);
}

TEST(CommandLine, HelpPrintsTheOptionsAndParsesNothing) {
  std::string model;
  ::testing::internal::CaptureStdout();
  const auto parsed = parse_command_line({"model.json", "--help"}, options(), "model", model);
  const std::string printed = ::testing::internal::GetCapturedStdout();
  EXPECT_FALSE(parsed.has_value());
  EXPECT_NE(printed.find("--count"), std::string::npos) << printed;
  EXPECT_EQ(printed.find("--model"), std::string::npos) << printed;  // the positional is hidden
}

TEST(CommandLine, RefusesUnknownOptionsBadValuesAndASecondPositional) {
  std::string model;
  EXPECT_THROW(parse_command_line({"--cuont", "3"}, options(), "model", model), po::error);
  EXPECT_THROW(parse_command_line({"--count", "three"}, options(), "model", model), po::error);
  EXPECT_THROW(parse_command_line({"a.json", "b.json"}, options(), "model", model), po::error);
}

}  // namespace
}  // namespace pound::app
