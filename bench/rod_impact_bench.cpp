// Speed of the rod-impact benchmark solve (issue: n = 1000 per rod, dt = h/C0, 3 T_I, 6,000
// steps, 2,002 DOFs; goal <= 20 ms on the 2-core development machine). The model is built once;
// each iteration integrates from the initial state, factorisation included.
#include <benchmark/benchmark.h>

#include "verification/rod_impact.hpp"
#include "verification/rod_impact_report.hpp"

namespace {

// range(0): elements per rod; range(1): 0 gap spring (k-ratio 1), 1 extended penalty (automatic);
// range(2): 0 average acceleration at dt = h/C0, 1 central difference at 0.9 of its stable step as
// stable_time_step computes it (0.586 h/C0 with the extended penalty in contact, its link's
// relative mode binding): dt = 0.527 h/C0, 11,380 steps.
void rod_impact_fine_mesh(benchmark::State& state) {
  pound::verification::RodImpactOptions options;
  options.pair =
      pound::verification::rod_impact_case("kawashima", static_cast<int>(state.range(0)), 1.0,
                                           state.range(1) == 0 ? "gap_spring" : "extended_penalty");
  const bool explicit_method = state.range(2) == 1;
  options.courant = 1.0;
  if (explicit_method) {
    options.integrator = pound::integrators::IntegratorChoice::preset("central_difference");
    options.stable_fraction = 0.9;
  }
  pound::verification::RodPairSimulation simulation(options);
  pound::verification::RodImpactResult result;
  long steps = 0;
  for (auto _ : state) {
    steps = simulation.solve(result).steps;
    benchmark::DoNotOptimize(result.force.data());
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["dofs"] = static_cast<double>(simulation.dofs());
  state.counters["us_per_step"] = benchmark::Counter(
      static_cast<double>(steps) * 1e-6,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(rod_impact_fine_mesh)
    ->ArgNames({"n", "extended_penalty", "explicit"})
    ->Args({1000, 0, 0})
    ->Args({1000, 1, 0})
    ->Args({1000, 1, 1})
    ->Args({100, 0, 0})
    ->Unit(benchmark::kMillisecond);

}  // namespace
