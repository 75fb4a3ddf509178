#pragma once
// `pound batch`: every (model, record, scale) case of a set, on a pool of worker threads and,
// under mpirun, over MPI ranks. Each case writes the outputs of `pound run` into its own folder
// <out>/<model>/<record>/x<scale>/ (plus case.csv, its summary row), built under <out>/.partial
// and renamed into place when complete, so a killed batch leaves only whole cases and --resume
// runs the rest (a case is whole with its completion marker, written last). Rank 0 holds a lock
// on <out> for the whole batch, so no second batch writes there meanwhile, and keeps a content
// hash of every input in batch_plan.json, so a resume never mixes the results of an edited
// input with the old ones. Rank 0 then writes batch_summary.csv (one row per case, in plan
// order) and batch_stats.json. Every number in them is independent of --jobs and of the number
// of ranks; only run_time_s varies.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/cluster.hpp"
#include "results/batch_statistics.hpp"
#include "results/case_summary.hpp"

namespace pound::app {

struct BatchProgress {
  std::size_t done = 0, total = 0, failed = 0;  // of this rank's cases still to run
  std::size_t running = 0;                      // cases in flight
  double running_done = 0.0;  // their fractions done (time of the record solved), summed
  double elapsed_s = 0.0;
  const results::CaseSummary* last = nullptr;  // the case just finished; none: cases in flight
};

struct BatchOptions {
  std::string set_path;
  // The set's JSON, when it is not read from set_path (which then names it in messages and is
  // where its relative paths start): the Python module's sets from dicts.
  std::optional<std::string> set_text;
  std::string out;
  int jobs = 0;         // worker threads per rank; 0: every core, or 1 per rank under MPI
  bool resume = false;  // keep the complete cases of an earlier run of the same set
  // Called after each case this rank runs, and while cases run (`last` null) every so many
  // steps of any of them, one call at a time. What it throws stops the batch (the cases in
  // flight at their next report, none of them written) and is thrown by run_batch.
  std::function<void(const BatchProgress&)> progress;
  // How the caller names `out` and `resume` in messages (the Python module's arguments).
  std::string out_name = "--out", resume_name = "--resume";
};

struct BatchReport {
  std::size_t cases = 0, resumed = 0, ran = 0;
  std::size_t completed = 0, failed = 0;  // over every case, resumed or not (root only)
  std::vector<std::string> warned;        // the completed cases whose results gave warnings
  int ranks = 1, jobs = 1;
  double wall_s = 0.0;    // of running the cases, on the slowest rank
  double worker_s = 0.0;  // summed over every case run (all ranks): reading, solving, writing
  double solve_s = 0.0;   // of that, in the time-step loop (recording included)
  double setup_s = 0.0;   // reading the model and record, building and assembling
  double write_s = 0.0;   // writing the case folders
  results::BatchStatistics statistics;  // root only
};

// Throws InputError (bad set, model or --out, or an input edited since the batch in --out began)
// before any case runs; io::OutputError if results cannot be written, io::FolderInUse (an
// OutputError) if another batch holds --out; Interrupted on Ctrl-C. A case that fails (bad record,
// analysis failure) does not stop the others.
BatchReport run_batch(const BatchOptions& options, const Cluster& cluster);

}  // namespace pound::app
