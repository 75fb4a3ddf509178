// A run that diverges stops as failed with the time and the reason, keeping its histories, and
// never writes NaN: every step checks the state for NaN/Inf (the integrators) and the energy
// balance for energy the integration created (over 10 % of the largest term).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/process.hpp"

namespace pound::testing {
namespace {

// A mass on a spring, T = 1 s, released with a velocity: the energy stays 0.5 exactly.
std::string oscillator(const std::string& integrator, double time_step) {
  return fmt::format(R"({{
  "dimension": 1,
  "nodes": [{{"id": "ground", "x": 0}}, {{"id": "mass", "x": 1}}],
  "materials": [{{"id": "spring", "youngs_modulus": {}, "density": 0}}],
  "elements": [{{"id": "column", "type": "truss", "nodes": ["ground", "mass"], "material": "spring", "area": 1}}],
  "masses": [{{"node": "mass", "mass": 1}}],
  "supports": [{{"node": "ground", "fix": ["x"]}}],
  "initial_velocities": [{{"node": "mass", "x": 1}}],
  "analysis": {{"integrator": "{}", "time_step": {}, "duration": 200}},
  "recorders": [{{"type": "node", "nodes": ["mass"], "file": "mass.csv"}}]
}})",
                     4.0 * M_PI * M_PI, integrator, time_step);
}

class Divergence : public PoundProcess {};

// Newmark's linear acceleration is stable only up to dt = sqrt(3)/pi T = 0.551 T: at 0.7 T each
// step multiplies the amplitude, and the run must stop on the energy it creates, long before
// the numbers overflow.
TEST_F(Divergence, EnergyCreatedByAnUnstableStepStopsTheRun) {
  std::ofstream(path("model.json")) << oscillator("newmark_linear_acceleration", 0.7);
  const Outcome outcome =
      pound({"run", path("model.json").string(), "--out", path("out").string()});
  EXPECT_EQ(outcome.exit_code, 3) << outcome.err;
  EXPECT_NE(outcome.err.find("analysis failed at t = "), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("the integration is creating energy"), std::string::npos)
      << outcome.err;
  const nlohmann::json summary = nlohmann::json::parse(read_text(path("out/summary.json")));
  EXPECT_EQ(summary["status"], "failed");
  EXPECT_LT(summary["failure_time"].get<double>(), 200.0);
  // The history up to the failure is there, every value finite.
  std::istringstream csv(read_text(path("out/mass.csv")));
  std::string line;
  std::getline(csv, line);
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) EXPECT_TRUE(std::isfinite(std::stod(cell))) << line;
  }
  EXPECT_GE(rows, 2);
}

// The same oscillator at the same step with the average acceleration method (unconditionally
// stable, energy conserving) runs to the end.
TEST_F(Divergence, AStableIntegratorAtTheSameStepRunsToTheEnd) {
  std::ofstream(path("model.json")) << oscillator("newmark_average_acceleration", 0.7);
  const Outcome outcome =
      pound({"run", path("model.json").string(), "--out", path("out").string()});
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  const nlohmann::json summary = nlohmann::json::parse(read_text(path("out/summary.json")));
  EXPECT_EQ(summary["status"], "completed");
  const double error = summary["energy"]["worst_balance_error"].get<double>();
  std::cout << fmt::format(
      "average acceleration at dt = 0.7 T: worst energy balance error {:.1e}\n", error);
  EXPECT_LT(error, 1e-12);
}

// Central difference from rest under a record whose first sample is 0: its first step moves
// nothing while the velocity takes dt/2 a, which without the method's algorithmic energy was a
// 100 % balance error and stopped every such run at its first step as "creating energy".
TEST_F(Divergence, CentralDifferenceFromRestUnderARecordRunsToTheEnd) {
  nlohmann::json model = nlohmann::json::parse(oscillator("central_difference", 0.005));
  model.erase("initial_velocities");
  model["analysis"].erase("duration");  // the record's
  model["excitations"] = {
      {{"record", std::string(POUND_SOURCE_DIR) + "/ground_motions/synthetic_soft_01.AT2"},
       {"units", "g"}}};
  std::ofstream(path("model.json")) << model.dump();
  const Outcome outcome =
      pound({"run", path("model.json").string(), "--out", path("out").string()});
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  const nlohmann::json summary = nlohmann::json::parse(read_text(path("out/summary.json")));
  EXPECT_EQ(summary["status"], "completed");
  const double error = summary["energy"]["worst_balance_error"].get<double>();
  std::cout << fmt::format("central difference from rest: worst energy balance error {:.1e}\n",
                           error);
  EXPECT_LT(error, 1e-10);
  EXPECT_GT(summary["energy"]["input"].get<double>(), 0.0);
}

}  // namespace
}  // namespace pound::testing
