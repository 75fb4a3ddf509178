#pragma once
// What `pound pushover` finds, for the command and the Python module alike: the model's constant
// loads first, then a lateral load pattern grown under displacement control until a node has
// moved the target along a direction (assembly/pushover.hpp). Nothing here prints or writes.
#include <optional>
#include <string>

#include "app/model_loading.hpp"
#include "core/table.hpp"
#include "io/document.hpp"

namespace pound::app {

struct PushoverRequest {
  std::string node;                                // the control node's id
  std::string direction = "x", pattern = "point";  // x or y; point, mass or triangular
  double target = 0.0;                             // the control node's displacement [L]
  int increments = 100;
  // How the caller names the settings in messages: "--node" on the command line, "node" in
  // Python.
  std::string option_prefix = "--";
  std::string name(const std::string& setting) const { return option_prefix + setting; }
};

// A setting out of its range (the target, direction, pattern or increments), or none.
struct PushoverRequestError {
  std::string setting, why;  // "to", "must be a finite, nonzero displacement"
};
std::optional<PushoverRequestError> pushover_request_error(const PushoverRequest& request);

struct PushoverFindings {
  Table curve;            // pushover.csv: displacement, base shear, iterations, link deformations
  io::Document document;  // pushover.json: stiffnesses, first yield, peak base shear
  std::string text;       // the summary's lines
  std::string stopped;    // why the push ended short of the target (a mechanism), or empty
};

// The push of `loaded` (its records left out). Throws InputError naming `model_path` and the
// setting (a bad node, direction, pattern or target, a hard contact, which has no force law to
// push against).
PushoverFindings pushover_findings(LoadedModel loaded, const std::string& model_path,
                                   const PushoverRequest& request);

// Throws InputError naming `out_name` when pushover.csv or pushover.json in `out` would be the
// model file.
void check_pushover_outputs(const std::string& out, const std::string& model_path,
                            const std::string& out_name);

// pushover.csv and pushover.json into `out` (created if needed), put in place together.
void write_pushover_outputs(const std::string& out, const PushoverFindings& push);

}  // namespace pound::app
