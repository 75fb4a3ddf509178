#include "app/batch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "app/ensemble.hpp"
#include "app/model_run.hpp"
#include "core/errors.hpp"
#include "core/stopwatch.hpp"
#include "io/batch_files.hpp"
#include "io/case_rows.hpp"
#include "io/document.hpp"
#include "io/folder_lock.hpp"
#include "io/ground_motion_reader.hpp"
#include "io/json_reader.hpp"
#include "io/model_reader.hpp"
#include "io/output.hpp"
#include "io/output_paths.hpp"
#include "io/set_reader.hpp"
#include "io/statistics_document.hpp"
#include "results/batch_quantities.hpp"

namespace pound::app {
namespace {

namespace fs = std::filesystem;
std::string scale_text(const builder::ExcitationSpec& e) {
  if (e.scale_factor) return fmt::format("factor {}", *e.scale_factor);
  if (e.target_pga) return fmt::format("pga {} g", *e.target_pga);
  if (e.target_sa)
    return fmt::format("sa {} g at {} s, damping {}", *e.target_sa, e.sa_period, e.sa_damping);
  return "as recorded";
}

// Every file the results depend on (the set, its models, its records), with its content hash.
std::vector<io::InputFile> input_files(const builder::SetSpec& set,
                                       const std::optional<std::string>& set_text) {
  std::vector<io::InputFile> inputs;
  // Each under one spelling, however the set or the command line typed it: --resume compares
  // them with the plan's.
  auto add = [&](const std::string& typed) {
    const std::string path = io::resolved_path(typed);
    for (const io::InputFile& known : inputs)
      if (known.path == path) return;
    inputs.push_back({path, io::file_hash(path)});
  };
  if (set_text)
    inputs.push_back({set.source, io::sha1_hex(*set_text)});
  else
    add(set.source);
  for (const builder::BatchModel& model : set.models) add(model.path);
  for (const builder::BatchRecord& record : set.records) {
    add(record.excitation.record);
    if (record.excitation.pair && record.excitation.pair->record)
      add(*record.excitation.pair->record);
  }
  return inputs;
}

// What the cases are, in order, and what their inputs hold: an earlier batch in the same folder
// is resumed only if this is unchanged.
std::string plan_text(const builder::SetSpec& set, const std::vector<builder::BatchCase>& cases,
                      const std::vector<io::InputFile>& inputs) {
  // Each model and record resolved once, not once per case.
  std::vector<std::string> models, records, pairs;
  for (const builder::BatchModel& model : set.models)
    models.push_back(io::resolved_path(model.path));
  for (const builder::BatchRecord& record : set.records) {
    const builder::ExcitationSpec& e = record.excitation;
    records.push_back(io::resolved_path(e.record));
    pairs.push_back(e.pair && e.pair->record ? io::resolved_path(*e.pair->record) : records.back());
  }
  std::vector<io::Document> items;
  for (const builder::BatchCase& c : cases) {
    const builder::ExcitationSpec& e = set.records[c.record].excitation;
    io::Document item;
    item.set("case", c.name)
        .set("model", models[c.model])
        .set("record", records[c.record])
        .set("format", e.format)
        .set("column", e.column)
        .set("units", e.units)
        .set("record_scale", scale_text(e))
        .set("scale", c.scale);
    if (e.pair)  // the pair's second component and angle decide the case too
      item.set("pair", io::Document()
                           .set("record", pairs[c.record])
                           .set("column", e.pair->column.value_or(e.column))
                           .set("angle_deg", e.pair->angle));
    items.push_back(item);
  }
  io::Document intensity;
  intensity.set("type", builder::intensity_name(set.intensity.type))
      .set("period", set.intensity.period)
      .set("damping", set.intensity.damping)
      .set("pair", builder::pair_measure_name(set.intensity.pair));
  return io::Document()
             .set("set", inputs.front().path)  // input_files puts it first, resolved
             .set("intensity_measure", intensity)
             .set("cases", items)
             .set("inputs",
                  io::documents(
                      inputs,
                      [](const io::InputFile& input) {
                        return io::Document().set("file", input.path).set("fnv1a_64", input.hash);
                      }))
             .dump() +
         "\n";
}

std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text;
}

struct CaseResult {
  std::size_t index = 0;
  std::string row;
  results::CaseSummary summary;
  double worker_s = 0.0;  // the whole case
  double setup_s = 0.0;   // reading and building (an ensemble's copies too)
  double solve_s = 0.0;   // solving (an ensemble's copies too)
  double write_s = 0.0;   // writing its folder
};

// A case's run, and with the set's ensemble its copies (one thread: the cases are the parallel
// work) with ensemble.json and, when the set asks for medians, the copies' medians in its row.
struct CaseRun {
  RunOutcome outcome;
  std::vector<std::pair<std::string, io::Document>> extra;  // ensemble.json
  double copies_setup_s = 0.0, copies_solve_s = 0.0;        // the ensemble's copies'
};

// `case_progress` (if any) is told the fraction of the case done: of its run, and with an
// ensemble of its run and copies, each an equal share.
CaseRun run_case_model(RunRequest request, const std::optional<builder::SetEnsemble>& set,
                       const std::function<void(double)>& case_progress) {
  const double shares = set ? 1.0 + static_cast<double>(set->copies) : 1.0;
  if (case_progress)
    request.progress = [&case_progress, shares](double time, double start, double end) {
      case_progress(end > start ? (time - start) / (end - start) / shares : 0.0);
    };
  if (!set) return {run_model(request), {}, 0.0, 0.0};
  const EnsembleOptions options{.copies = set->copies,
                                .perturbation = set->perturbation,
                                .robust_spread = set->robust_spread,
                                .jobs = 1};
  const auto copy_done = [&case_progress, shares](std::size_t done, std::size_t) {
    case_progress((1.0 + static_cast<double>(done)) / shares);
  };
  EnsembleResult result =
      run_ensemble(request, options,
                   case_progress ? copy_done : std::function<void(std::size_t, std::size_t)>());
  CaseRun run{result.unperturbed,
              {{"ensemble.json", ensemble_document(result, options)}},
              result.copies_setup_s,
              result.copies_solve_s};
  run.outcome.case_summary = result.row_summary(set->medians);
  return run;
}

// A case's record replaces the model's first excitation, so what is wrong with its scaling or
// pair (an all-zero record under a target, a pair column of a one-column file) is the set's
// record entry's, not the model's "/excitations/0".
InputError in_the_set(const InputError& error, const std::string& model_path,
                      const std::string& set_file, const std::string& record_path) {
  constexpr std::string_view kFirst = "/excitations/0";
  const std::string& where = error.where();
  if (error.file() != model_path || record_path.empty() || !where.starts_with(kFirst) ||
      (where.size() > kFirst.size() && where[kFirst.size()] != '/'))
    return error;
  return InputError(set_file, record_path + where.substr(kFirst.size()), error.reason());
}

// A case whose model or record cannot be read fails alone: an outcome saying why. So does one
// whose analysis fails before its first step (its static equilibrium under gravity not found):
// a failed case, as one that fails during its run, not a stop of the batch.
CaseRun run_or_report_input_error(const RunRequest& request,
                                  const std::optional<builder::SetEnsemble>& ensemble,
                                  const std::function<void(double)>& case_progress,
                                  const std::string& set_file, const std::string& record_path) {
  const auto stopped = [&](results::CaseStatus status, const std::string& reason) {
    RunOutcome outcome;
    outcome.case_summary.status = status;
    outcome.case_summary.reason = one_line(reason);
    outcome.summary.set("model", request.model_path)
        .set("status", results::status_name(status))
        .set("failure", outcome.case_summary.reason);
    return CaseRun{outcome, {}, 0.0, 0.0};
  };
  try {
    return run_case_model(request, ensemble, case_progress);
  } catch (const InputError& error) {
    return stopped(results::CaseStatus::input_error,
                   in_the_set(error, request.model_path, set_file, record_path).what());
  } catch (const SolveError& error) {
    CaseRun run = stopped(results::CaseStatus::failed, error.what());
    run.outcome.failure = error.reason();
    run.outcome.failure_time = error.time();
    run.outcome.case_summary.end_time = error.time();
    return run;
  }
}

// Runs one case into <out>/.partial, then moves it into place.
CaseResult run_case(const builder::SetSpec& set, const builder::BatchCase& c,
                    const std::string& out, int rank,
                    const std::function<void(double)>& case_progress) {
  const Stopwatch case_clock;
  RunRequest request;
  request.model_path = set.models[c.model].path;
  request.record = set.records[c.record].excitation;
  request.record->extra_factor = c.scale;
  request.intensity = set.intensity;
  request.histories = set.histories;
  CaseRun run = run_or_report_input_error(request, set.ensemble, case_progress, set.source,
                                          set.records[c.record].path);
  RunOutcome& outcome = run.outcome;
  results::CaseSummary& summary = outcome.case_summary;
  summary.name = c.name;
  summary.model = set.models[c.model].id;
  summary.record = set.records[c.record].id;
  summary.scale = c.scale;
  summary.reason = one_line(summary.reason);
  outcome.summary.set("batch_case", io::Document()
                                        .set("name", c.name)
                                        .set("set", set.source)
                                        .set("record", set.records[c.record].excitation.record)
                                        .set("scale", c.scale));
  const Stopwatch write_clock;
  const std::string temporary =
      (fs::path(out) / ".partial" / fmt::format("{}.r{}", c.index, rank)).string();
  io::remove_folder(temporary);
  write_run_outputs(temporary, outcome, run.extra);
  CaseResult result;
  result.index = c.index;
  result.row = io::case_row(summary);
  io::write_text_atomic((fs::path(temporary) / "case.csv").string(),
                        io::case_row_header() + "\n" + result.row + "\n");
  io::write_case_marker(temporary, c.name);  // last: until it is there, the case is not done
  io::move_folder_into_place(temporary, (fs::path(out) / c.name).string());
  // The row as it reads back, so statistics are the same whether a case ran now or is resumed.
  result.summary = io::parse_case_row(result.row, c.name);
  result.worker_s = case_clock.seconds();
  result.write_s = write_clock.seconds();
  result.setup_s = outcome.setup_s + run.copies_setup_s;
  result.solve_s = outcome.case_summary.run_time_s.value_or(0.0) + run.copies_solve_s;
  return result;
}

std::string plan_path(const std::string& out) {
  return (fs::path(out) / "batch_plan.json").string();
}

// The inputs whose content changed since the batch in `out` began, as "a, b".
std::string changed_inputs(const std::string& plan_file, const std::vector<io::InputFile>& inputs) {
  std::string changed;
  for (const io::InputFile& before : io::read_plan_inputs(plan_file))
    for (const io::InputFile& now : inputs)
      if (now.path == before.path && now.hash != before.hash)
        changed += (changed.empty() ? "" : ", ") + now.path;
  return changed;
}

// Checks, under the lock, that `out` can take this batch: empty or missing, or, with --resume,
// holding the same batch (its cases and the content of its inputs unchanged).
void check_out_folder(const BatchOptions& options, const std::string& plan,
                      const std::vector<io::InputFile>& inputs) {
  const std::string& out = options.out;
  const std::string plan_file = plan_path(out);
  if (io::is_file(plan_file)) {
    if (!options.resume)
      throw InputError(
          out, "",
          fmt::format("holds a batch already: add {} to finish it, or choose another {}",
                      options.resume_name, options.out_name));
    // Resuming after an edit would mix rows of the old and the new file in one summary.
    if (const std::string changed = changed_inputs(plan_file, inputs); !changed.empty())
      throw InputError(plan_file, "",
                       fmt::format("changed since the batch in {} began: {}; its results would "
                                   "mix with the new ones: choose another {}, or remove {} "
                                   "to start again",
                                   out, changed, options.out_name, out));
    if (io::read_text_file(plan_file) != plan)
      throw InputError(plan_file, "",
                       fmt::format("the cases of {} are not those of the batch in {} (the set, a "
                                   "record or a path changed): choose another {}, or remove {} "
                                   "to start again",
                                   options.set_path, out, options.out_name, out));
  } else if (!io::is_empty_but_for_lock(out)) {
    throw InputError(out, "",
                     "exists and is not a batch folder: choose another " + options.out_name);
  }
}

// Rank 0: locks `out` for this batch, checks it and writes the plan.
io::FolderLock lock_out_folder(const BatchOptions& options, const builder::SetSpec& set,
                               const std::vector<builder::BatchCase>& cases) {
  const std::string& out = options.out;
  // Nothing, not even the lock file, goes into a folder that is not a batch's.
  if (!io::is_file(plan_path(out)) && !io::is_empty_but_for_lock(out))
    throw InputError(out, "",
                     "exists and is not a batch folder: choose another " + options.out_name);
  io::create_output_folder(out);
  io::FolderLock lock(out);
  // Checked again under the lock: another batch may have started in the folder meanwhile.
  const std::vector<io::InputFile> inputs = input_files(set, options.set_text);
  const std::string plan = plan_text(set, cases, inputs);
  check_out_folder(options, plan, inputs);
  io::remove_folder((fs::path(out) / ".partial").string());  // cases a killed run left unfinished
  io::write_text_atomic(plan_path(out), plan);
  return lock;
}

// Rank 0 takes the lock (held until the batch ends) for every rank of this mpirun: the other
// ranks write only after it has, and all stop if it cannot.
std::optional<io::FolderLock> open_out_folder(const BatchOptions& options,
                                              const builder::SetSpec& set,
                                              const std::vector<builder::BatchCase>& cases,
                                              const Cluster& cluster) {
  std::optional<io::FolderLock> lock;
  std::exception_ptr failure;
  int exit_code = 0;  // of the failure, to pass on to the other ranks
  if (cluster.is_root()) {
    try {
      lock.emplace(lock_out_folder(options, set, cases));
    } catch (const InputError&) {
      failure = std::current_exception();
      exit_code = 2;
    } catch (const std::exception&) {
      failure = std::current_exception();
      exit_code = 4;
    }
  }
  exit_code = cluster.max(exit_code);
  if (failure) std::rethrow_exception(failure);
  const std::string why = fmt::format("rank 0 could not open {} (see its message)", options.out);
  if (exit_code == 2) throw InputError(options.out, "", why);
  if (exit_code != 0) throw io::OutputError(why);
  return lock;
}

// The row of a case an earlier run completed, if there is one: a case folder without its
// marker, or missing or short of a file the marker lists, runs again.
std::optional<std::string> completed_row(const builder::BatchCase& c, const std::string& out) {
  const std::string folder = (fs::path(out) / c.name).string();
  if (!io::is_complete_case(folder, c.name)) return std::nullopt;
  const std::string row_file = (fs::path(folder) / "case.csv").string();
  std::string row;
  try {
    if (io::read_case_file(row_file, row).name == c.name) return row;
  } catch (const InputError&) {
    // damaged: run it again
  }
  return std::nullopt;
}

// This rank's share of the cases still to run.
std::vector<const builder::BatchCase*> rank_share(
    const std::vector<const builder::BatchCase*>& pending, const Cluster& cluster) {
  std::vector<const builder::BatchCase*> mine;
  for (std::size_t k = 0; k < pending.size(); ++k)
    if (static_cast<int>(k % static_cast<std::size_t>(cluster.size())) == cluster.rank())
      mine.push_back(pending[k]);
  return mine;
}

// Thrown into the cases in flight once one case has stopped the batch.
class BatchStopped : public std::runtime_error {
 public:
  BatchStopped() : std::runtime_error("stopped with the batch") {}
};

// What this rank's workers did.
struct RankRun {
  std::vector<CaseResult> results;
  std::string fatal;           // why the workers stopped taking cases, if they did
  std::exception_ptr stopped;  // what stopped them: thrown again as it was, but an output error
  double wall_s = 0.0;
};

// Runs `mine` on `workers` threads, reporting each case to `progress`, and the cases in flight
// as they go.
RankRun run_cases(const builder::SetSpec& set, const std::vector<const builder::BatchCase*>& mine,
                  const BatchOptions& options, int rank, int workers) {
  RankRun run;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;  // guards what follows
  BatchProgress progress;
  progress.total = mine.size();
  // Each worker's case in flight: the fraction done, < 0 when it has none.
  std::vector<std::atomic<double>> in_flight(static_cast<std::size_t>(workers));
  for (std::atomic<double>& fraction : in_flight) fraction = -1.0;
  const Stopwatch wall_clock;
  const auto report = [&](const results::CaseSummary* last) {  // with `mutex` held
    progress.running = 0;
    progress.running_done = 0.0;
    for (const std::atomic<double>& fraction : in_flight)
      if (const double f = fraction.load(std::memory_order_relaxed); f >= 0.0) {
        ++progress.running;
        progress.running_done += f;
      }
    progress.elapsed_s = wall_clock.seconds();
    progress.last = last;
    options.progress(progress);
  };
  auto work = [&](std::size_t worker) {
    // While a case runs: its fraction, and a report unless another thread is reporting.
    const auto case_progress = [&, worker](double fraction) {
      in_flight[worker].store(fraction, std::memory_order_relaxed);
      if (const std::unique_lock lock(mutex, std::try_to_lock); lock) {
        if (stop) throw BatchStopped();  // another worker's case stopped the batch
        report(nullptr);
      }
    };
    while (!stop) {
      const std::size_t k = next++;
      if (k >= mine.size()) return;
      try {
        in_flight[worker] = 0.0;
        CaseResult result =
            run_case(set, *mine[k], options.out, rank,
                     options.progress ? case_progress : std::function<void(double)>());
        const std::lock_guard lock(mutex);
        in_flight[worker] = -1.0;  // with `done`: a report sees the case running or done
        run.results.push_back(std::move(result));
        ++progress.done;
        progress.failed += run.results.back().summary.status != results::CaseStatus::completed;
        if (options.progress) report(&run.results.back().summary);
      } catch (const std::exception& error) {
        in_flight[worker] = -1.0;
        // Results cannot be written (disk full, permissions), Ctrl-C, or the progress callback
        // threw: stop taking cases (those in flight stop at their next progress report).
        const std::lock_guard lock(mutex);
        if (run.fatal.empty()) {
          run.fatal = fmt::format("case {}: {}", mine[k]->name, error.what());
          run.stopped = std::current_exception();
        }
        stop = true;
      }
    }
  };
  {
    std::vector<std::jthread> pool;
    for (int w = 1; w < workers; ++w) pool.emplace_back(work, static_cast<std::size_t>(w));
    work(0);
  }
  run.wall_s = wall_clock.seconds();
  return run;
}

// This rank's rows ("R<index>\t<row>"), totals ("T<cases>\t<worker_s>\t<solve_s>\t<setup_s>\t
// <write_s>\t<wall_s>") and failure ("F<message>"), as rank 0 gathers them.
std::vector<std::string> rank_messages(const RankRun& run) {
  std::vector<std::string> messages;
  double worker_s = 0.0, solve_s = 0.0, setup_s = 0.0, write_s = 0.0;
  for (const CaseResult& r : run.results) {
    messages.push_back(fmt::format("R{}\t{}", r.index, r.row));
    worker_s += r.worker_s;
    solve_s += r.solve_s;
    setup_s += r.setup_s;
    write_s += r.write_s;
  }
  messages.push_back(fmt::format("T{}\t{}\t{}\t{}\t{}\t{}", run.results.size(), worker_s, solve_s,
                                 setup_s, write_s, run.wall_s));
  if (!run.fatal.empty()) messages.push_back("F" + one_line(run.fatal));
  return messages;
}

// On every rank: throws the first failure of any rank (rank 0 names it, the others may not know
// it). A rank's own failure is thrown as it was (Interrupted, what the progress callback threw, out
// of memory), but an output error, which is named with its case.
void throw_if_a_rank_failed(const Cluster& cluster, const RankRun& run,
                            const std::vector<std::string>& gathered) {
  const std::string& fatal = run.fatal;
  if (!cluster.any(!fatal.empty())) return;
  if (run.stopped) {
    try {
      std::rethrow_exception(run.stopped);
    } catch (const io::OutputError&) {
      throw io::OutputError(fatal);
    }
  }
  if (!cluster.is_root()) throw io::OutputError(fatal.empty() ? "another rank failed" : fatal);
  for (const std::string& m : gathered)
    if (m.front() == 'F') throw io::OutputError(m.substr(1));
}

// Rank 0: every rank's rows into `rows`, their counts and times into the report.
void read_messages(const std::vector<std::string>& gathered,
                   std::map<std::size_t, std::string>& rows, BatchReport& report) {
  for (const std::string& m : gathered) {
    const std::size_t tab = m.find('\t');
    if (m.front() == 'R') {
      rows[std::stoul(m.substr(1, tab - 1))] = m.substr(tab + 1);
    } else if (m.front() == 'T') {
      std::size_t ran = 0;
      double w = 0.0, s = 0.0, setup = 0.0, write = 0.0, wall = 0.0;
      std::sscanf(m.c_str(), "T%zu\t%lf\t%lf\t%lf\t%lf\t%lf", &ran, &w, &s, &setup, &write, &wall);
      report.ran += ran;
      report.worker_s += w;
      report.solve_s += s;
      report.setup_s += setup;
      report.write_s += write;
      report.wall_s = std::max(report.wall_s, wall);
    }
  }
}

// Rank 0: batch_summary.csv (the rows in plan order) and batch_stats.json, and the counts and
// statistics of the report.
void write_batch_results(const builder::SetSpec& set, const std::vector<builder::BatchCase>& cases,
                         const std::map<std::size_t, std::string>& rows, const std::string& out,
                         BatchReport& report) {
  if (rows.size() != cases.size())
    throw std::logic_error(fmt::format("batch: {} rows for {} cases", rows.size(), cases.size()));
  std::string csv = io::case_row_header() + "\n";
  std::vector<results::CaseSummary> summaries;
  for (const auto& [index, row] : rows) {
    csv += row + "\n";
    summaries.push_back(io::parse_case_row(row, cases[index].name));
    const results::CaseSummary& c = summaries.back();
    report.completed += c.status == results::CaseStatus::completed;
    if (c.status == results::CaseStatus::completed && c.warnings.value_or(0.0) > 0.0)
      report.warned.push_back(c.name);
  }
  report.failed = cases.size() - report.completed;
  report.statistics = results::batch_statistics(set, summaries);
  io::write_text_atomic((fs::path(out) / "batch_summary.csv").string(), csv);
  io::write_text_atomic((fs::path(out) / "batch_stats.json").string(),
                        io::to_document(report.statistics, set).dump() + "\n");
}

// The unit a model gives `dimension` in: a force's needs a mass unit, without which it is the
// length and time it is made of.
std::string unit_of(const builder::UnitsSpec& units, Dimension dimension) {
  if (dimension == Dimension::force && !units.mass)
    return fmt::format("(no mass unit; {}, {})", units.length, units.time);
  return units.names().of(dimension);
}

// A limit is one number, read in each model's units: over models that give its quantity in
// different units it would compare millimetres with metres (a limit of 0.03 on the joint opening
// of a model in mm exceeded by every case, and its fragility "not fitted"), so such a set is
// refused.
void refuse_limits_in_mixed_units(const builder::SetSpec& set,
                                  const std::vector<builder::ModelSpec>& specs) {
  if (specs.empty()) return;
  for (const builder::ResponseLimit& limit : set.limits) {
    const results::BatchQuantity* quantity = results::find_batch_quantity(limit.quantity);
    if (!quantity || quantity->dimension == Dimension::none) continue;
    const std::string first = unit_of(specs.front().units, quantity->dimension);
    for (std::size_t k = 1; k < specs.size(); ++k) {
      const std::string other = unit_of(specs[k].units, quantity->dimension);
      if (first != other)
        throw InputError(
            set.source, "/limits/" + limit.quantity,
            fmt::format("a limit is read in each model's units, and the set's models give {} in "
                        "different ones ('{}' in {}, '{}' in {}): split the set by units, or write "
                        "its models in one system",
                        limit.quantity, set.models[0].id, first, set.models[k].id, other));
    }
  }
}

}  // namespace

BatchReport run_batch(const BatchOptions& options, const Cluster& cluster) {
  // Everything wrong with the set or its models is found before anything is written.
  const builder::SetSpec set = options.set_text ? io::parse_set(*options.set_text, options.set_path)
                                                : io::read_set_file(options.set_path);
  std::vector<builder::ModelSpec> specs;
  for (const builder::BatchModel& model : set.models)
    specs.push_back(io::read_model_file(model.path));
  refuse_limits_in_mixed_units(set, specs);
  const std::vector<builder::BatchCase> cases = builder::plan_cases(set);
  const std::optional<io::FolderLock> lock = open_out_folder(options, set, cases, cluster);

  // Complete cases (a whole folder with its row) are kept; the rest run, shared out over ranks.
  std::map<std::size_t, std::string> rows;
  std::vector<const builder::BatchCase*> pending;
  for (const builder::BatchCase& c : cases) {
    const std::optional<std::string> row =
        options.resume ? completed_row(c, options.out) : std::nullopt;
    if (row)
      rows[c.index] = *row;
    else
      pending.push_back(&c);
  }
  cluster.barrier();  // every rank has looked before any case is rewritten
  const std::vector<const builder::BatchCase*> mine = rank_share(pending, cluster);

  BatchReport report;
  report.cases = cases.size();
  report.resumed = rows.size();
  report.ranks = cluster.size();
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  report.jobs = options.jobs > 0 ? options.jobs : cluster.size() > 1 ? 1 : static_cast<int>(cores);
  const int workers = std::max(1, std::min(report.jobs, static_cast<int>(mine.size())));
  const RankRun run = run_cases(set, mine, options, cluster.rank(), workers);
  report.wall_s = run.wall_s;

  // Rank 0 gathers every rank's rows and timings.
  const std::vector<std::string> gathered = cluster.gather(rank_messages(run));
  throw_if_a_rank_failed(cluster, run, gathered);
  if (!cluster.is_root()) return report;
  read_messages(gathered, rows, report);
  write_batch_results(set, cases, rows, options.out, report);
  return report;
}

}  // namespace pound::app
