// Cost of the 3-D scenes per link row (issue 20: the inelastic and 3-D models within 1.5 x of the
// elastic bridge per link row): the bundled skewed 3-D bridge (models/skewed_bridge_3d.json:
// coupled yielding bearings, corner pounding, shear keys, a pair of records) and the eccentric
// buildings in 3-D (models/eccentric_buildings_3d.json: corner pounding) against the plane
// bridge (models/three_span_bridge.json), each the best of 5 runs, histories off. A link row is
// one force unknown: a bearing with a coupled shear has three (its axis and two tangents).
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "solve_rate.hpp"

namespace {

std::string bundled(const std::string& model) {
  return std::string(POUND_SOURCE_DIR) + "/models/" + model;
}

void space_models_per_link_row(benchmark::State& state) {
  pound::bench::SolveRate plane, bridge, buildings;
  for (auto _ : state) {
    plane = pound::bench::solve_rate(bundled("three_span_bridge.json"), 5);
    bridge = pound::bench::solve_rate(bundled("skewed_bridge_3d.json"), 5);
    buildings = pound::bench::solve_rate(bundled("eccentric_buildings_3d.json"), 5);
  }
  if (!std::isfinite(plane.seconds_per_step) || !std::isfinite(bridge.seconds_per_step) ||
      !std::isfinite(buildings.seconds_per_step))
    state.SkipWithError("a run failed");
  state.counters["rows_plane"] = plane.link_rows;
  state.counters["rows_skewed_3d"] = bridge.link_rows;
  state.counters["rows_eccentric_3d"] = buildings.link_rows;
  state.counters["us_per_step_per_row_plane"] = 1e6 * plane.per_link_row();
  state.counters["ratio_skewed_3d"] = bridge.per_link_row() / plane.per_link_row();
  state.counters["ratio_eccentric_3d"] = buildings.per_link_row() / plane.per_link_row();
}
BENCHMARK(space_models_per_link_row)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
