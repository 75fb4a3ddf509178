// Cost of yielding piers (issue 15): the bundled three-span bridge with elastic piers against the
// same bridge with Takeda base hinges, gravity and chord P-Delta
// (models/three_span_bridge_takeda.json), the same record and step. Counters: solve time per
// step of each (the best of 5 runs, histories off) and their ratio; goal: ratio <= 1.5.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "app/model_run.hpp"

namespace {

// Solve seconds per step of a bundled model, the best of `repeats` runs.
double seconds_per_step(const std::string& model, int repeats) {
  pound::app::RunRequest request;
  request.model_path = std::string(POUND_SOURCE_DIR) + "/models/" + model;
  request.histories = false;
  double best = INFINITY;
  for (int k = 0; k < repeats; ++k) {
    const pound::app::RunOutcome outcome = pound::app::run_model(request);
    if (!outcome.failure.empty()) return NAN;
    best = std::min(best, *outcome.case_summary.run_time_s / *outcome.case_summary.steps);
  }
  return best;
}

void yielding_bridge(benchmark::State& state) {
  double elastic = 0.0, hinged = 0.0;
  for (auto _ : state) {
    elastic = seconds_per_step("three_span_bridge.json", 5);
    hinged = seconds_per_step("three_span_bridge_takeda.json", 5);
  }
  if (!std::isfinite(elastic) || !std::isfinite(hinged)) state.SkipWithError("a run failed");
  state.counters["us_per_step_elastic"] = 1e6 * elastic;
  state.counters["us_per_step_takeda"] = 1e6 * hinged;
  state.counters["ratio"] = hinged / elastic;
}
BENCHMARK(yielding_bridge)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
