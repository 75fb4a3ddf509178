#pragma once
// Runs a model given as JSON text (its records found from `model_path`'s folder) without
// histories and returns its summary.json as JSON: what the tests of monitors compare with the
// nodes' histories.
#include <nlohmann/json.hpp>
#include <string>

#include "app/model_run.hpp"

namespace pound::testing {

inline nlohmann::json model_summary(const std::string& model_text, const std::string& model_path) {
  app::RunRequest request;
  request.model_path = model_path;
  request.model_text = model_text;
  request.histories = false;
  return nlohmann::json::parse(app::run_model(request).summary.dump());
}

}  // namespace pound::testing
