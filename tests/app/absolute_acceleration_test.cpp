// Issue 16: node recorders gave the acceleration relative to the ground, undocumented (a_x(0) =
// -a_g(0) was observed). They now write a_rel and a_abs. For a mass on a spring and dashpot the
// absolute acceleration is known from the equation of motion alone, m a_abs = -(c v + k u) with
// u and v relative to the support (a linear run without links satisfies it to rounding), under a
// uniform excitation and under a moving support; the support's own a_abs is the record's.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "app/model_run.hpp"
#include "support/tables.hpp"

namespace pound::app {
namespace {

namespace fs = std::filesystem;

constexpr double kMass = 2.0e5, kStiffness = 8.0e6, kMassDamping = 0.6;  // c = 0.6 m

// The run's node table of a mass on a truss spring to "ground", excited by the bundled record
// uniformly or by moving "ground", and its drift monitor's peak absolute acceleration.
struct Oscillator {
  Table nodes;
  double monitored_peak = 0.0;
  std::optional<double> batch_peak;  // the case's max_top_acceleration (batch_summary.csv)
};

Oscillator run_oscillator(bool moving_support) {
  const std::string record =
      (fs::path(POUND_SOURCE_DIR) / "ground_motions" / "synthetic_firm_01.AT2").string();
  const std::string excitation =
      moving_support
          ? fmt::format(R"({{"record": "{}", "units": "g", "supports": ["ground"]}})", record)
          : fmt::format(R"({{"record": "{}", "units": "g"}})", record);
  const std::string text = fmt::format(R"({{
    "dimension": 1,
    "nodes": [{{"id": "ground", "x": 0}}, {{"id": "mass", "x": 1}}],
    "materials": [{{"id": "spring", "youngs_modulus": {}, "density": 0}}],
    "elements": [{{"id": "spring", "type": "truss", "nodes": ["ground", "mass"],
                   "material": "spring", "area": 1}}],
    "masses": [{{"node": "mass", "mass": {}, "mass_damping": {}}}],
    "supports": [{{"node": "ground", "fix": ["x"]}}],
    "excitations": [{}],
    "analysis": {{"time_step": 0.005, "duration": 10}},
    "monitors": {{"drifts": [{{"id": "spring", "bottom": "ground", "top": "mass", "height": 1}}]}},
    "recorders": [{{"type": "node", "nodes": ["ground", "mass"], "file": "nodes.csv"}}]
  }})",
                                       kStiffness, kMass, kMassDamping, excitation);
  const fs::path folder =
      fs::temp_directory_path() / fmt::format("pound_absolute_{}_{}", moving_support, ::getpid());
  fs::create_directories(folder);
  std::ofstream(folder / "model.json") << text;
  RunRequest request;
  request.model_path = (folder / "model.json").string();
  const RunOutcome outcome = run_model(request);
  fs::remove_all(folder);
  EXPECT_TRUE(outcome.failure.empty()) << outcome.failure;
  const nlohmann::json summary = nlohmann::json::parse(outcome.summary.dump());
  return {outcome.histories.at(0).second,
          summary["storeys"][0]["peak_absolute_acceleration"].get<double>(),
          outcome.case_summary.max_top_acceleration};
}

using testing::column;

void expect_equation_of_motion(bool moving_support) {
  const Oscillator run = run_oscillator(moving_support);
  const Table& table = run.nodes;
  const auto& u = column(table, "mass.u_x");
  const auto& v = column(table, "mass.v_x");
  const auto& relative = column(table, "mass.a_rel_x");
  const auto& absolute = column(table, "mass.a_abs_x");
  const auto& ground = column(table, "ground.a_abs_x");
  double worst = 0.0, peak = 0.0, ground_difference = 0.0;
  for (std::size_t k = 0; k < u.size(); ++k) {
    const double expected = -(kMassDamping * v[k] + kStiffness / kMass * u[k]);
    worst = std::max(worst, std::abs(absolute[k] - expected));
    peak = std::max(peak, std::abs(absolute[k]));
    // The support moves with the ground: the frame's acceleration is the record's.
    ground_difference =
        std::max(ground_difference, std::abs(absolute[k] - relative[k] - ground[k]));
  }
  std::cout << (moving_support ? "moving support" : "uniform excitation")
            << ": peak absolute acceleration " << peak << ", largest error against -(c v + k u)/m "
            << worst << " (relative " << worst / peak << "), a_abs - a_rel - a_ground "
            << ground_difference << "\n";
  EXPECT_GT(peak, 1.0);
  EXPECT_LT(worst / peak, 1e-9);
  EXPECT_LT(ground_difference, 1e-12 * peak);
  // At rest at t = 0 the mass's absolute acceleration is 0, its relative one -a_g(0).
  EXPECT_NEAR(absolute.front(), 0.0, 1e-12);
  EXPECT_NEAR(relative.front(), -ground.front(), 1e-12);
  // The summary's peak floor acceleration is the recorded one's.
  EXPECT_EQ(run.monitored_peak, peak);
  EXPECT_EQ(run.batch_peak, peak);
}

TEST(AbsoluteAcceleration, UnderAUniformExcitationFollowsTheEquationOfMotion) {
  expect_equation_of_motion(false);
}

TEST(AbsoluteAcceleration, UnderAMovingSupportFollowsTheEquationOfMotion) {
  expect_equation_of_motion(true);
}

}  // namespace
}  // namespace pound::app
