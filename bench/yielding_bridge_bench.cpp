// Cost of yielding piers (issue 15): the bundled three-span bridge with elastic piers against the
// same bridge with Takeda base hinges, gravity and chord P-Delta
// (models/three_span_bridge_takeda.json), the same record and step. Counters: solve time per
// step of each (the best of 5 runs, histories off) and their ratio; goal: ratio <= 1.5. And per
// link row (22 links against 20), the comparison of issue 20: within 1.5 x.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "solve_rate.hpp"

namespace {

std::string bundled(const std::string& model) {
  return std::string(POUND_SOURCE_DIR) + "/models/" + model;
}

void yielding_bridge(benchmark::State& state) {
  pound::bench::SolveRate elastic, hinged;
  for (auto _ : state) {
    elastic = pound::bench::solve_rate(bundled("three_span_bridge.json"), 5);
    hinged = pound::bench::solve_rate(bundled("three_span_bridge_takeda.json"), 5);
  }
  if (!std::isfinite(elastic.seconds_per_step) || !std::isfinite(hinged.seconds_per_step))
    state.SkipWithError("a run failed");
  state.counters["us_per_step_elastic"] = 1e6 * elastic.seconds_per_step;
  state.counters["us_per_step_takeda"] = 1e6 * hinged.seconds_per_step;
  state.counters["ratio"] = hinged.seconds_per_step / elastic.seconds_per_step;
  // Issue 20: within 1.5 x of the elastic bridge per link row.
  state.counters["us_per_step_per_link_elastic"] = 1e6 * elastic.per_link();
  state.counters["us_per_step_per_link_takeda"] = 1e6 * hinged.per_link();
  state.counters["ratio_per_link"] = hinged.per_link() / elastic.per_link();
}
BENCHMARK(yielding_bridge)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
