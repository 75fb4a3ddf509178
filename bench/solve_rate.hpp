#pragma once
// Solve time per step of a model (histories off, the best of `repeats` runs) and its links, for
// the cost per step and link row that issue 20 compares across models.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "app/model_loading.hpp"
#include "app/model_run.hpp"
#include "assembly/structural_system.hpp"

namespace pound::bench {

struct SolveRate {
  double seconds_per_step = NAN;  // NaN when a run failed
  double links = 0.0;             // the summary's links
  double link_rows = 0.0;         // their rows: one each, and a shear's or friction's tangents
  double per_link() const { return seconds_per_step / links; }
  double per_link_row() const { return seconds_per_step / link_rows; }
};

inline SolveRate solve_rate(const std::string& model_path, int repeats) {
  app::RunRequest request;
  request.model_path = model_path;
  request.histories = false;
  SolveRate rate;
  double best = INFINITY;
  for (int k = 0; k < repeats; ++k) {
    const app::RunOutcome outcome = app::run_model(request);
    if (!outcome.failure.empty()) return {};
    best = std::min(best, *outcome.case_summary.run_time_s / *outcome.case_summary.steps);
    if (k == 0)
      rate.links =
          static_cast<double>(nlohmann::json::parse(outcome.summary.dump())["links"].size());
  }
  rate.seconds_per_step = best;
  rate.link_rows = static_cast<double>(
      assembly::StructuralSystem(app::load_model(model_path).built.model).links().size());
  return rate;
}

}  // namespace pound::bench
