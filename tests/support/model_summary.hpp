#pragma once
// Runs a model given as JSON text (its records found from `model_path`'s folder) without
// histories and returns its summary.json as JSON: what the tests of monitors compare with the
// nodes' histories.
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "app/model_run.hpp"

namespace pound::testing {

// The path of a bundled model (models/NAME.json), from which its records are found.
inline std::string bundled_model_path(const std::string& name) {
  return std::string(POUND_SOURCE_DIR) + "/models/" + name + ".json";
}

// A bundled model's JSON without its recorders (a summary needs none).
inline nlohmann::json bundled_model(const std::string& name) {
  std::ifstream file(bundled_model_path(name));
  nlohmann::json model = nlohmann::json::parse(file);
  model.erase("recorders");
  return model;
}

inline nlohmann::json model_summary(const std::string& model_text, const std::string& model_path) {
  app::RunRequest request;
  request.model_path = model_path;
  request.model_text = model_text;
  request.histories = false;
  return nlohmann::json::parse(app::run_model(request).summary.dump());
}

}  // namespace pound::testing
