// Speed of the block on a moving belt (issue 7): the 40 x 20 quad block of
// models/block_on_belt.json (1,722 DOFs, 41 belt contacts with friction, 21 springs) with
// explicit central difference at 0.8 of its stable step, one spring period at Pi = 1 (the block
// slides and vibrates, every contact active). Reported: steps per second of thread CPU time,
// the static initial state and the set-up included.
#include <benchmark/benchmark.h>

#include <ctime>

#include "io/model_reader.hpp"
#include "verification/block_belt.hpp"

namespace {

double thread_cpu_seconds() {
  timespec now{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

void block_belt_sweep_point(benchmark::State& state) {
  const pound::builder::ModelSpec spec =
      pound::io::read_model_file(POUND_SOURCE_DIR "/models/block_on_belt.json");
  pound::verification::BlockBeltOptions options;
  options.periods = 1.0;
  long steps = 0;
  double seconds = 0.0;
  for (auto _ : state) {
    const double start = thread_cpu_seconds();
    const pound::verification::BlockBeltPoint point =
        pound::verification::run_block_belt(spec, 1.0, options);
    seconds += thread_cpu_seconds() - start;
    steps += point.steps;
    benchmark::DoNotOptimize(point.friction_ratio);
  }
  state.counters["steps_per_s"] = static_cast<double>(steps) / seconds;
  state.counters["us_per_step"] = 1e6 * seconds / static_cast<double>(steps);
  state.counters["steps_per_period"] =
      static_cast<double>(steps) / static_cast<double>(state.iterations());
}
BENCHMARK(block_belt_sweep_point)->Unit(benchmark::kSecond)->Iterations(2);

}  // namespace
