// The lowest modes of large models (`pound modes`, `pound check`'s periods, Rayleigh damping from
// `"modes"`): Kawashima's free rod pair (models/rod_impact.json) meshed with n elements a rod,
// 2n + 2 DOFs, two rigid-body modes. `vibration_modes` (6 modes: shift-invert Lanczos past 300
// DOFs) against the dense solve of every mode (`modal_analysis`, up to 4,000 DOFs) that was used
// for all sizes before. Counter: milliseconds per solve.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <string>

#include "assembly/modal_analysis.hpp"
#include "builder/build.hpp"
#include "io/model_reader.hpp"

namespace {

pound::assembly::StructuralSystem rod_pair(long elements) {
  const std::string rod = fmt::format(
      R"({{"youngs_modulus": 100, "density": 0.1, "area": 1, "length": 10, "elements": {},
          "initial_velocity": 0.1, "far_end": "free"}})",
      elements);
  const std::string text = fmt::format(
      R"({{"dimension": 1, "generators": [{{"type": "rod_pair", "id": "rods", "left": {},
          "right": {}, "gap": 0.0, "law": {{"type": "gap_spring", "stiffness_ratio": 1.0}}}}],
          "analysis": {{"time_step": 0.003, "duration": 1}}}})",
      rod, rod);
  return pound::assembly::StructuralSystem(
      pound::builder::build(pound::io::parse_model(text, "rods.json")).model);
}

void lowest_modes(benchmark::State& state, bool dense) {
  const pound::assembly::StructuralSystem system = rod_pair(state.range(0));
  for (auto _ : state) {
    const pound::assembly::Modes modes = dense ? pound::assembly::modal_analysis(system)
                                               : pound::assembly::vibration_modes(system, 6);
    benchmark::DoNotOptimize(modes.omega_squared.data());
  }
  state.counters["dofs"] = static_cast<double>(system.size());
}

void lanczos_modes(benchmark::State& state) { lowest_modes(state, false); }
void dense_modes(benchmark::State& state) { lowest_modes(state, true); }

BENCHMARK(lanczos_modes)->Arg(500)->Arg(1000)->Arg(2500)->Unit(benchmark::kMillisecond);
BENCHMARK(dense_modes)->Arg(500)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
