// Speed on realistic models (issue 20 item 1): the solve of the bundled three-span bridge
// (59 DOFs, 20 links, 16,667 steps) and of the two SDOF girders (2 DOFs, one Kelvin-Voigt gap
// link), histories off, the best of 7 runs in one process (restitution calibration is cached
// after the first). Counters: milliseconds per run and microseconds per step.
// Goals (issue 20): bridge <= 15 ms, two SDOF girders <= 0.7 ms per 4,000 steps.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "app/model_run.hpp"

namespace {

struct SolveTime {
  double seconds = INFINITY;
  double steps = 0.0;
};

SolveTime best_solve(const std::string& model, int repeats) {
  pound::app::RunRequest request;
  request.model_path = std::string(POUND_SOURCE_DIR) + "/models/" + model;
  request.histories = false;
  SolveTime best;
  for (int k = 0; k < repeats; ++k) {
    const pound::app::RunOutcome outcome = pound::app::run_model(request);
    if (!outcome.failure.empty()) return {NAN, 0.0};
    best.seconds = std::min(best.seconds, *outcome.case_summary.run_time_s);
    best.steps = *outcome.case_summary.steps;
  }
  return best;
}

void solve_bundled(benchmark::State& state, const std::string& model, double reference_steps) {
  SolveTime best;
  for (auto _ : state) best = best_solve(model, 7);
  if (!std::isfinite(best.seconds)) state.SkipWithError("a run failed");
  state.counters["ms_per_run"] = 1e3 * best.seconds;
  state.counters["us_per_step"] = 1e6 * best.seconds / best.steps;
  state.counters["ms_per_reference_run"] = 1e3 * best.seconds / best.steps * reference_steps;
}

// The reference runs: the bridge's own 16,667 steps; 4,000 steps of the two girders.
void three_span_bridge_solve(benchmark::State& state) {
  solve_bundled(state, "three_span_bridge.json", 16667);
}
void two_sdof_girders_solve(benchmark::State& state) {
  solve_bundled(state, "two_sdof_girders.json", 4000);
}
BENCHMARK(three_span_bridge_solve)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(two_sdof_girders_solve)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
