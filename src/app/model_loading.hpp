#pragma once
// Reading a model file with its ground-motion records into a built model: what `run`, `modes`
// and `batch` share. Everything that can be wrong with the input is found here, before any
// output exists.
#include <optional>
#include <string>
#include <vector>

#include "builder/build.hpp"
#include "io/document.hpp"
#include "io/ground_motion_reader.hpp"
#include "model/ground_motion.hpp"

namespace pound::app {

struct LoadedModel {
  builder::ModelSpec spec;
  builder::BuiltModel built;
  std::vector<model::GroundMotion> records;      // of spec.excitations, as read (before scaling)
  std::vector<std::string> record_paths;         // the files they were read from (named only)
  std::vector<io::RecordSource> record_sources;  // their format and content hash
  // Per excitation, a pair's second component (none for a single record), read as its first.
  struct SecondComponent {
    model::GroundMotion motion;
    std::string path;
    io::RecordSource source;
  };
  std::vector<std::optional<SecondComponent>> second_components;
  // Who replaced the first excitation's record: "--motion", "the batch case", or empty.
  std::string first_record_replaced_by;
  // load_model_structure's: the directions of the excitations it left out (a pair's two), which
  // `pound modes` holds the 90 % of mass to.
  std::vector<model::Coordinates> unread_excitation_directions;
};

// `pound run --motion RECORD` and its options: the record replacing the model's first one, how to
// read it, and, when given, the scaling replacing the model's.
struct MotionOverride {
  std::string path;
  std::optional<std::string> units;  // of the file's values: "g", "m/s2", "cm/s2", "model"
  std::optional<int> column;
  std::optional<double> time_step;
  // One second in the unit of time of `time_step` and `times`, where it is not the model's (as
  // `pound run --dt` gives it): 1 for seconds (the Python module's Record.from_file, which knows
  // no model and takes a file's times in seconds; a Record of arrays with time_unit "s"), 1000
  // for "ms".
  std::optional<double> record_second;
  bool time_column = false;
  std::optional<double> scale_factor, target_pga;  // target in g
  // A record given as values (the Python module's arrays), still in `units` (default g), read
  // instead of a file; `path` then names it in outputs.
  std::optional<std::vector<double>> accelerations;
  std::vector<double> times;             // of the samples, when `time_step` is not given
  std::string replaced_by = "--motion";  // who replaced the record, for the run's report
};

// `motion_override`: a record path replacing the first excitation's record (or adding a uniform
// x excitation in g when the model has none), as `pound run --motion` does.
// When a model of `dofs` DOFs would not fit in the memory available: "need about X GiB, more
// than the Y GiB ..." (run, check and the verify benchmarks refuse it before allocating).
std::optional<std::string> memory_shortfall(double dofs);

// The model without its excitations (none of its records read): what `pound modes` and
// `pound pushover` need.
LoadedModel load_model_structure(const std::string& path);

// The units a model's numbers are in, as summary.json, check --json, modes --json and
// pushover.json give them.
io::Document units_document(const builder::UnitsSpec& units);
LoadedModel load_model(const std::string& path,
                       const std::optional<MotionOverride>& motion_override = {});

// Same from the model's JSON text, named `path` in messages; records relative to its folder.
LoadedModel load_model_text(const std::string& text, const std::string& path,
                            const std::optional<MotionOverride>& motion_override = {});

// A batch case: `record` (its path as the program opens it, format, units, scale and IDA
// factor; its times, a columns step and an Sa period, in seconds) replaces the first
// excitation's; the model keeps its direction, supports and wave passage. A model without
// excitations gets it as a uniform excitation along x.
LoadedModel load_model_with_record(const std::string& path, const builder::ExcitationSpec& record);

}  // namespace pound::app
