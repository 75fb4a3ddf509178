// How a model's records are read: the same record drives a model in seconds and the same model in
// milliseconds alike, and a time column without a column reads the values after it.
#include "app/model_loading.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "app/model_run.hpp"
#include "core/errors.hpp"

namespace pound::app {
namespace {

// One girder (1 t on 4e4 N/m: T = 0.99 s) against a wall across a 2 cm gap, under the bundled
// synthetic record, with time in `time_unit` ("s" or "ms") and every time given in it.
std::string girder_at_a_wall(const std::string& time_unit, const std::string& excitation) {
  const double second = time_unit == "ms" ? 1000.0 : 1.0;
  return fmt::format(R"({{
    "dimension": 1,
    "units": {{"length": "m", "time": "{}", "mass": "kg"}},
    "nodes": [{{"id": "ground", "x": 0}}, {{"id": "girder", "x": 1}}, {{"id": "wall", "x": 2}}],
    "supports": [{{"node": "ground", "fix": ["x"]}}, {{"node": "wall", "fix": ["x"]}}],
    "masses": [{{"node": "girder", "mass": 1000}}],
    "links": [
      {{"id": "pier", "nodes": ["ground", "girder"], "axis": [1],
        "law": {{"type": "elastic_spring", "stiffness": {}}}}},
      {{"id": "joint", "nodes": ["girder", "wall"], "axis": [1], "gap": 0.02,
        "law": {{"type": "kelvin_voigt", "stiffness": {}, "restitution": 0.65}}}}],
    "excitations": [{}],
    "analysis": {{"time_step": {}, "duration": {}}}}})",
                     time_unit, 4e4 / (second * second), 4e8 / (second * second), excitation,
                     0.002 * second, 8.0 * second);
}

RunOutcome run_text(const std::string& text) {
  RunRequest request;
  request.model_path = std::string(POUND_SOURCE_DIR) + "/models/girder_at_a_wall.json";
  request.model_text = text;
  request.histories = false;
  RunOutcome outcome = run_model(request);
  EXPECT_TRUE(outcome.failure.empty()) << outcome.failure;
  return outcome;
}

// Forces are kg m / s^2 in the one and kg m / ms^2 (MN) in the other: the same in newtons.
TEST(ModelLoading, AnAt2RecordDrivesAModelInMillisecondsAsInSeconds) {
  const std::string record = R"({"record": "../ground_motions/synthetic_firm_01.AT2",
                                 "units": "g", "scale": {"pga": 0.4}})";
  const RunOutcome seconds = run_text(girder_at_a_wall("s", record));
  const RunOutcome milliseconds = run_text(girder_at_a_wall("ms", record));
  const auto& in_s = seconds.case_summary;
  const auto& in_ms = milliseconds.case_summary;
  ASSERT_TRUE(in_s.impacts && in_ms.impacts && in_s.max_pounding_force && in_ms.max_pounding_force);
  EXPECT_GT(*in_s.impacts, 0);
  EXPECT_EQ(*in_ms.impacts, *in_s.impacts);
  const double newtons = *in_ms.max_pounding_force * 1e6;
  std::cout << "peak force " << *in_s.max_pounding_force << " N in s, " << newtons << " N in ms\n";
  EXPECT_NEAR(newtons, *in_s.max_pounding_force, 1e-6 * *in_s.max_pounding_force);
}

TEST(ModelLoading, ATimeColumnWithoutAColumnReadsTheColumnAfterIt) {
  const std::string folder = ::testing::TempDir();
  const std::string file = folder + "/time_and_acceleration.txt";
  {
    std::FILE* out = std::fopen(file.c_str(), "w");
    ASSERT_NE(out, nullptr);
    for (int k = 0; k <= 400; ++k)
      std::fprintf(out, "%.3f %.6f\n", 0.01 * k, 0.3 * std::sin(2.0 * M_PI * 0.01 * k));
    std::fclose(out);
  }
  const RunOutcome outcome = run_text(girder_at_a_wall(
      "ms", fmt::format(R"({{"record": "{}", "time_column": true, "units": "g"}})", file)));
  ASSERT_TRUE(outcome.case_summary.impacts);
  EXPECT_GT(*outcome.case_summary.impacts, 0);  // read as time: 1 Hz shaking at 0.3 g
}

}  // namespace
}  // namespace pound::app
