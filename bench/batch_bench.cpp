// Throughput of `pound batch` (issue 6): the three-span bridge under 20 records x 3 scales,
// with 1 and 2 worker threads, writing each case's histories (as `pound run` does) or not.
// Counters: cases per second, and the share of the workers' time spent outside the solve
// (reading the model and record, building, writing the case folder). Goals: 2 workers >= 1.8x
// the cases per second of 1, overhead < 5 %.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "app/batch.hpp"
#include "app/cluster.hpp"

namespace {

namespace fs = std::filesystem;

// range(0): worker threads; range(1): 1 to write every case's history CSVs, 0 for none.
void batch_three_span_bridge(benchmark::State& state) {
  // The set reads 16 of its records from ../shared beside the checkout.
  if (!fs::is_directory(std::string(POUND_SOURCE_DIR) + "/../shared/ground_motions")) {
    state.SkipWithError("../shared/ground_motions is not beside the checkout");
    for (auto _ : state) {
    }
    return;
  }
  const fs::path folder = fs::temp_directory_path() / "pound_batch_bench";
  fs::remove_all(folder);
  fs::create_directories(folder);
  // The set as shipped, its relative paths made absolute, with "histories" set as asked.
  const std::string bench = std::string(POUND_SOURCE_DIR) + "/bench";
  std::ifstream in(bench + "/bridge_20_records.json");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (std::size_t at = text.find("\"../"); at != std::string::npos; at = text.find("\"../", at))
    text.replace(at, 1, "\"" + bench + "/");
  text.insert(text.rfind('}'),
              state.range(1) ? ", \"histories\": true\n" : ", \"histories\": false\n");
  const std::string set = (folder / "set.json").string();
  std::ofstream(set) << text;

  const pound::app::Cluster cluster;
  pound::app::BatchReport report;
  for (auto _ : state) {
    state.PauseTiming();
    fs::remove_all(folder / "out");
    state.ResumeTiming();
    pound::app::BatchOptions options;
    options.set_path = set;
    options.out = (folder / "out").string();
    options.jobs = static_cast<int>(state.range(0));
    report = pound::app::run_batch(options, cluster);
  }
  fs::remove_all(folder);
  if (report.completed != report.cases) state.SkipWithError("a case failed");
  state.counters["cases"] = static_cast<double>(report.cases);
  state.counters["cases_per_s"] = static_cast<double>(report.ran) / report.wall_s;
  state.counters["overhead_pct"] = 100.0 * (1.0 - report.solve_s / report.worker_s);
  state.counters["write_pct"] = 100.0 * report.write_s / report.worker_s;
}
BENCHMARK(batch_three_span_bridge)
    ->ArgNames({"jobs", "histories"})
    ->Args({1, 0})
    ->Args({2, 0})
    ->Args({1, 1})
    ->Args({2, 1})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace
