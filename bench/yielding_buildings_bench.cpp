// Cost of yielding storeys (issue 15): a 20-storey and a 15-storey building 5 cm apart, floors at
// the same heights, with elastic storey columns against the same pair with Takeda storey links
// (their damping a1 k_0, or a1 times their committed tangent, inside the storey links), gravity
// and chord P-Delta; the same record (the bundled synthetic soft-ground record at PGA 0.4 g) and
// step. Counters: solve time per step of each (the best of 5 runs, histories off) and their
// ratios to the elastic pair; and its cost per step and link row against the bundled elastic
// bridge's (issue 20: within 1.5 x).
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "solve_rate.hpp"

namespace {

// One building's storeys: 3.2 m high, stiffness tapering up, yield shears from a base shear
// coefficient over an inverted triangle when `yielding`.
std::string storeys(int count, double mass, double base_stiffness, bool yielding) {
  const double g = 9.80665, coefficient = 0.15;
  double weighted = 0.0;
  for (int s = 1; s <= count; ++s) weighted += mass * s;
  std::string text;
  double above = 0.0;
  for (int s = count; s >= 1; --s) {
    above += mass * s;
    const double stiffness = base_stiffness * (1.0 - 0.5 * (s - 1) / count);
    const std::string law =
        yielding ? fmt::format(R"(, "law": {{"type": "takeda", "yield_force": {:.6g}, )"
                               R"("hardening_ratio": 0.05}})",
                               coefficient * count * mass * g * above / weighted)
                 : "";
    text =
        fmt::format(R"({{"height": 3.2, "mass": {}, "stiffness": {}{}}})", mass, stiffness, law) +
        (text.empty() ? "" : ", ") + text;
  }
  return text;
}

// `storey_damping` of the yielding pair: "initial" or "committed".
std::string pair_model(bool yielding, const std::string& storey_damping = "initial") {
  const std::string damping =
      yielding ? fmt::format(R"("storey_damping": "{}", )", storey_damping) : "";
  return fmt::format(R"({{"dimension": 2, "units": {{"length": "m", "time": "s"}},
    "generators": [{{"type": "adjacent_buildings", "id": "pair", "separation": 0.05,
      "left": {{{}"damping_ratio": 0.05, "storeys": [{}]}},
      "right": {{{}"damping_ratio": 0.05, "storeys": [{}]}},
      "law": {{"type": "jankowski", "stiffness": 2.75e9, "restitution": 0.65}}}}],
    {}
    "excitations": [{{"record": "{}/ground_motions/synthetic_soft_01.AT2", "units": "g",
                      "scale": {{"pga": 0.4}}}}],
    "analysis": {{"time_step": 0.002}}}})",
                     damping, storeys(20, 3.0e5, 6.0e8, yielding), damping,
                     storeys(15, 2.5e5, 4.0e8, yielding),
                     yielding ? R"("gravity": {"p_delta": "chord"},)" : "", POUND_SOURCE_DIR);
}

// Solve time per step and links of a model given as text, the best of `repeats` runs.
pound::bench::SolveRate text_rate(const std::string& text, int repeats) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / fmt::format("pound_bench_{}.json", ::getpid());
  std::ofstream(file) << text;
  const pound::bench::SolveRate rate = pound::bench::solve_rate(file.string(), repeats);
  std::filesystem::remove(file);
  return rate;
}

void yielding_buildings(benchmark::State& state) {
  pound::bench::SolveRate bridge, elastic_rate, yielding_rate, committed_rate;
  for (auto _ : state) {
    bridge = pound::bench::solve_rate(POUND_SOURCE_DIR "/models/three_span_bridge.json", 5);
    elastic_rate = text_rate(pair_model(false), 5);
    yielding_rate = text_rate(pair_model(true), 5);
    committed_rate = text_rate(pair_model(true, "committed"), 5);
  }
  const double elastic = elastic_rate.seconds_per_step, yielding = yielding_rate.seconds_per_step,
               committed = committed_rate.seconds_per_step;
  if (!std::isfinite(elastic) || !std::isfinite(yielding) || !std::isfinite(committed) ||
      !std::isfinite(bridge.seconds_per_step))
    state.SkipWithError("a run failed");
  state.counters["us_per_step_elastic"] = 1e6 * elastic;
  state.counters["us_per_step_takeda"] = 1e6 * yielding;
  state.counters["us_per_step_takeda_committed"] = 1e6 * committed;
  state.counters["ratio"] = yielding / elastic;
  state.counters["ratio_committed"] = committed / elastic;
  // Issue 20: within 1.5 x of the elastic bridge per link row (50 links: 35 storeys, 15 contacts).
  state.counters["us_per_step_per_link_takeda"] = 1e6 * yielding_rate.per_link();
  state.counters["us_per_step_per_link_bridge"] = 1e6 * bridge.per_link();
  state.counters["per_link_vs_bridge"] = yielding_rate.per_link() / bridge.per_link();
}
BENCHMARK(yielding_buildings)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
