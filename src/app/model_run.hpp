#pragma once
// One analysis of a model file, from reading it to the results `pound run` writes: shared by
// `run` (one model) and `batch` (many cases, on threads and MPI ranks). Nothing here writes to
// the console, so cases can run side by side.
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/model_loading.hpp"
#include "builder/batch_spec.hpp"
#include "core/table.hpp"
#include "io/document.hpp"
#include "results/case_summary.hpp"

namespace pound::app {

struct RunRequest {
  std::string model_path;
  // The model's JSON, when it is not read from model_path (which then only names it in messages
  // and is where its records are found from): the Python module's models from dicts.
  std::optional<std::string> model_text;
  std::optional<MotionOverride> motion;           // `pound run --motion` and its options
  std::optional<builder::ExcitationSpec> record;  // a batch case's record (replaces `motion`)
  std::optional<long> max_steps;                  // none: the model's "max_steps"; 0: no limit
  double time_limit = 0.0;                        // [s] of solving, 0: none
  builder::IntensityMeasure intensity;            // for the case summary
  bool histories = true;                          // record and write the model's recorders
  // Every excitation's acceleration times this: an ensemble member's perturbation
  // (app/ensemble.hpp); 1 leaves the records as read. A model without records (a free
  // vibration) has its initial velocities, nodal loads and gravity scaled instead.
  double record_factor = 1.0;
  // Called once the model and its records are read, before the run: where the caller checks
  // that its outputs will not overwrite them (throwing InputError).
  std::function<void(const LoadedModel&)> before_run;
  // Called with the warnings found before the run (RunOutcome::warnings starts with them) just
  // before the solve: where `pound run` shows them, to a user who may wait long for the rest.
  std::function<void(const std::vector<std::string>&)> before_solve;
  // Called as the solve starts (time = start) and then every kProgressStride steps with the
  // analysis' time and its span: where `pound run` shows how far a long run has come.
  std::function<void(double time, double start, double end)> progress;
};

// Steps between calls of RunRequest::progress: counting them and the calls with their clock
// reads cost 0.7 % of the cheapest steps (two DOFs: 20 instructions of 2,900, callgrind; 0.85 %
// every 32 steps).
inline constexpr long kProgressStride = 64;

struct RunOutcome {
  io::Document summary;                                  // summary.json
  std::vector<std::pair<std::string, Table>> histories;  // file name, table
  // What each of `histories` records: the recorder's kind and whether it keeps an envelope.
  struct Recorded {
    builder::RecorderKind kind = builder::RecorderKind::link;
    bool envelope = false;
  };
  std::vector<Recorded> recorded;
  std::string headline;  // "pound run MODEL: DOFs, steps, Newton iterations, run time"
  std::string report;    // the lines `pound run` prints after the headline
  std::vector<std::string> warnings;
  std::string failure;  // empty when the analysis completed
  // What RunRequest::record_factor scales in this model: "the records", or without records
  // what sets it moving ("the initial velocities and loads", ...).
  std::string perturbed;
  double failure_time = 0.0;
  results::CaseSummary case_summary;  // status and responses; the caller names the case
  double setup_s = 0.0;  // reading the model and records, building, assembling (before the solve)
};

// Reads, builds and runs. Input errors throw InputError before anything runs; a failed analysis
// (SolveError) is an outcome with `failure` set and the histories up to then.
RunOutcome run_model(const RunRequest& request);

// Throws InputError when one of a run's outputs in `out` (summary.json, ensemble.json with
// `ensemble`, the recorders' files) would overwrite the model, a record or another output.
// `out_name`: how the caller names `out` in messages.
void check_run_outputs(const std::string& out, const RunRequest& request, const LoadedModel& loaded,
                       bool ensemble, const std::string& out_name = "--out");

// summary.json and the history CSVs into `folder` (created if needed): written under temporary
// names, then renamed into place together, summary.json last.
// `extra`: more JSON files (name, document) written with them, before summary.json.
void write_run_outputs(const std::string& folder, const RunOutcome& outcome,
                       const std::vector<std::pair<std::string, io::Document>>& extra = {});

}  // namespace pound::app
