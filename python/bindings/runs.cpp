#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "app/batch.hpp"
#include "app/cluster.hpp"
#include "app/ensemble.hpp"
#include "app/model_run.hpp"
#include "bindings/bindings.hpp"
#include "builder/batch_spec.hpp"
#include "core/errors.hpp"
#include "core/stopwatch.hpp"
#include "io/output.hpp"

namespace py = pybind11;

namespace pound::python {
namespace {

// The outcome of pound.run: its tables stay here, and the arrays NumPy sees are views of them.
struct RunResult {
  app::RunOutcome outcome;  // with an ensemble, the unperturbed run's
  double core_s = 0.0;      // in app::run_model and writing: what `pound run` spends too
  std::optional<std::string> ensemble_json;  // ensemble.json's text, with an ensemble
  std::string ensemble_report;               // the lines `pound run --ensemble` prints
};

// pound.run(ensemble=...): the copies and how they are read, checked as `pound run` checks its
// options, each named as the function's argument.
struct EnsembleArguments {
  std::optional<int> copies;
  double perturbation = 1e-4, robust_spread = 0.05;
  int jobs = 0;

  app::EnsembleOptions options() const {
    const app::EnsembleOptions options{*copies, perturbation, robust_spread, jobs};
    if (const auto error = app::ensemble_options_error(options))
      throw InputError("", error->argument, error->why);
    return options;
  }
};

const char* kind_name(builder::RecorderKind kind) {
  switch (kind) {
    case builder::RecorderKind::link:
      return "link";
    case builder::RecorderKind::node:
      return "node";
    case builder::RecorderKind::element:
      return "element";
    case builder::RecorderKind::spectrum:
      return "spectrum";
  }
  return "?";
}

// Each recorder's table as a dict: file, kind, envelope, columns, units, text columns and a
// read-only NumPy view of each numeric column, kept alive by the result `owner`.
py::list tables(const py::object& owner) {
  const RunResult& result = owner.cast<const RunResult&>();
  py::list list;
  for (std::size_t k = 0; k < result.outcome.histories.size(); ++k) {
    const auto& [file, table] = result.outcome.histories[k];
    py::list values;
    for (const std::vector<double>& column : table.values) {
      py::array_t<double> view(static_cast<py::ssize_t>(column.size()), column.data(), owner);
      py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
      values.append(view);
    }
    py::dict text_columns;
    for (const TextColumn& column : table.text_columns)
      text_columns[py::str(column.name)] = column.values;
    py::dict item;
    item["file"] = file;
    item["kind"] = kind_name(result.outcome.recorded.at(k).kind);
    item["envelope"] = result.outcome.recorded.at(k).envelope;
    item["columns"] = table.columns;
    item["units"] = table.units;
    item["text_columns"] = text_columns;
    item["values"] = values;
    list.append(item);
  }
  return list;
}

// pound.Record as `pound run --motion` takes it: a file with how to read it, or samples.
app::MotionOverride motion_from(const py::dict& record) {
  app::MotionOverride motion;
  motion.path = record["name"].cast<std::string>();
  motion.units = record["units"].cast<std::string>();
  if (!record["scale"].is_none()) motion.scale_factor = record["scale"].cast<double>();
  motion.replaced_by = "pound.run(record=...)";
  if (!record["time_step"].is_none()) motion.time_step = record["time_step"].cast<double>();
  if (!record["second"].is_none()) motion.record_second = record["second"].cast<double>();
  if (record.contains("accelerations")) {
    motion.accelerations = record["accelerations"].cast<std::vector<double>>();
    motion.times = record["times"].cast<std::vector<double>>();
    return motion;
  }
  motion.path = record["path"].cast<std::string>();
  motion.column = record["column"].cast<int>();
  motion.time_column = record["time_column"].cast<bool>();
  return motion;
}

// Seconds of solving between calls of pound.run's `progress`: often enough for a progress bar to
// move smoothly, seldom enough that taking the GIL costs nothing measurable.
constexpr double kProgressInterval = 0.2;

// pound.run(progress=...): `callback(time, end)` as the solve starts, then at most every
// kProgressInterval seconds (the clock read every kProgressStride steps), and once more as the run
// ends (RunProgress::finish): time == end when it completed, the failure's time when it failed.
// With an ensemble of `copies`, `callback(done, runs)` counts runs (the unperturbed one by the
// share of its record solved, then the copies as they end), and ends with done == runs. What the
// callback raises stops the run and reaches the caller.
class RunProgress {
 public:
  RunProgress(py::object callback, std::optional<int> copies)
      : callback_(std::move(callback)),
        runs_(copies ? std::optional<double>(*copies + 1.0) : std::nullopt) {}

  std::function<void(double, double, double)> observer() {
    return [this](double time, double start, double end) {
      end_ = end;
      if (runs_)
        call(end > start ? (time - start) / (end - start) : 1.0, *runs_, time == start);
      else
        call(time, end, time == start);
    };
  }
  // The copies of an ensemble: `done` of `total` ended.
  std::function<void(std::size_t, std::size_t)> copy_observer() {
    return [this](std::size_t done, std::size_t /*copies*/) {
      call(1.0 + static_cast<double>(done), *runs_, done == 0);
    };
  }
  // With the GIL held, after the run; nothing if the solve never started (bad input), nor when
  // the last call already said so.
  void finish(const app::RunOutcome& outcome) {
    if (!end_) return;
    const double total = runs_ ? *runs_ : *end_;
    const double done = runs_ || outcome.failure.empty() ? total : outcome.failure_time;
    if (last_ == std::pair(done, total)) return;
    callback_(done, total);
  }

 private:
  void call(double done, double total, bool always) {
    const auto now = std::chrono::steady_clock::now();
    if (!always && std::chrono::duration<double>(now - last_call_).count() < kProgressInterval)
      return;
    last_call_ = now;
    last_ = {done, total};
    const py::gil_scoped_acquire locked;
    callback_(done, total);
  }

  py::object callback_;
  std::optional<double> runs_;  // with an ensemble: the copies and the unperturbed run
  std::chrono::steady_clock::time_point last_call_;
  std::optional<double> end_;
  std::optional<std::pair<double, double>> last_;  // the last call's (done, total)
};

std::shared_ptr<RunResult> run(const std::optional<std::string>& text, const std::string& path,
                               const std::optional<py::dict>& record,
                               const std::optional<std::string>& out, std::optional<long> max_steps,
                               double time_limit, bool histories,
                               const std::optional<py::object>& progress_callback,
                               const EnsembleArguments& ensemble) {
  const std::optional<app::EnsembleOptions> ensemble_options =
      ensemble.copies ? std::optional(ensemble.options()) : std::nullopt;
  app::RunRequest request;
  request.model_path = path;
  request.model_text = text;
  if (record) request.motion = motion_from(*record);
  request.max_steps = max_steps;
  request.time_limit = time_limit;
  request.histories = histories;
  if (out) {
    request.before_run = [&](const app::LoadedModel& loaded) {
      app::check_run_outputs(*out, request, loaded, ensemble_options.has_value(), "out");
    };
    // The input is good: a folder that cannot be made is said now, not after a long solve.
    request.before_solve = [&](const std::vector<std::string>&) { io::create_output_folder(*out); };
  }
  std::optional<RunProgress> progress;
  if (progress_callback)
    request.progress = progress.emplace(*progress_callback, ensemble.copies).observer();
  auto result = std::make_shared<RunResult>();
  {
    const InterruptGuard guard;
    const py::gil_scoped_release unlocked;
    const Stopwatch stopwatch;
    if (ensemble_options) {
      const app::EnsembleResult spreads = app::run_ensemble(
          request, *ensemble_options,
          progress ? progress->copy_observer() : std::function<void(std::size_t, std::size_t)>());
      result->outcome = spreads.unperturbed;
      const io::Document document = app::ensemble_document(spreads, *ensemble_options);
      result->ensemble_json = document.dump();
      result->ensemble_report = app::ensemble_report(spreads, *ensemble_options);
      if (out) app::write_run_outputs(*out, result->outcome, {{"ensemble.json", document}});
    } else {
      result->outcome = app::run_model(request);
      if (out) app::write_run_outputs(*out, result->outcome);
    }
    result->core_s = stopwatch.seconds();
  }
  if (progress) progress->finish(result->outcome);
  return result;
}

// pound.batch(progress=...): `callback(done, total)` as the cases run, at most every
// kProgressInterval seconds (done counts the cases finished and the share solved of those in
// flight), and once more with done == total when the batch has ended. What the callback raises
// stops the batch and reaches the caller.
class BatchProgressCallback {
 public:
  explicit BatchProgressCallback(py::object callback) : callback_(std::move(callback)) {}

  // Called by the batch one call at a time, from its worker threads, the GIL released.
  std::function<void(const app::BatchProgress&)> observer() {
    return [this](const app::BatchProgress& progress) {
      total_ = static_cast<double>(progress.total);
      const auto now = std::chrono::steady_clock::now();
      if (last_ && std::chrono::duration<double>(now - last_call_).count() < kProgressInterval)
        return;
      last_call_ = now;
      last_ = {static_cast<double>(progress.done) + progress.running_done, total_};
      const py::gil_scoped_acquire locked;
      callback_(last_->first, last_->second);
    };
  }
  // With the GIL held, after a batch that ended: nothing if no case ran, nor when the last call
  // already said so.
  void finish() const {
    if (last_ && last_ != std::pair(total_, total_)) callback_(total_, total_);
  }

 private:
  py::object callback_;
  std::chrono::steady_clock::time_point last_call_;
  double total_ = 0.0;
  std::optional<std::pair<double, double>> last_;  // the last call's (done, total)
};

// The batch's report as a dict (its statistics are in <out>/batch_stats.json).
py::dict batch(const std::optional<std::string>& text, const std::string& path,
               const std::string& out, int jobs, bool resume,
               const std::optional<py::object>& progress_callback) {
  static const app::Cluster cluster;  // this process, or the ranks of mpirun
  app::BatchOptions options;
  options.set_path = path;
  options.set_text = text;
  options.out = out;
  options.jobs = jobs;
  options.resume = resume;
  options.out_name = "out";
  options.resume_name = "resume=True";
  std::optional<BatchProgressCallback> progress;
  if (progress_callback) options.progress = progress.emplace(*progress_callback).observer();
  app::BatchReport report;
  {
    const InterruptGuard guard;
    const py::gil_scoped_release unlocked;
    report = app::run_batch(options, cluster);
  }
  if (progress) progress->finish();
  py::dict result;
  result["cases"] = report.cases;
  result["resumed"] = report.resumed;
  result["ran"] = report.ran;
  result["completed"] = report.completed;
  result["failed"] = report.failed;
  result["ranks"] = report.ranks;
  result["jobs"] = report.jobs;
  result["wall_s"] = report.wall_s;
  result["solve_s"] = report.solve_s;
  return result;
}

}  // namespace

void bind_runs(py::module_& module) {
  py::class_<RunResult, std::shared_ptr<RunResult>>(module, "RunResult")
      .def_property_readonly("summary_json",
                             [](const RunResult& r) { return r.outcome.summary.dump(); })
      .def_property_readonly("warnings", [](const RunResult& r) { return r.outcome.warnings; })
      .def_property_readonly("failure", [](const RunResult& r) { return r.outcome.failure; })
      .def_property_readonly("failure_time",
                             [](const RunResult& r) { return r.outcome.failure_time; })
      .def_property_readonly("headline", [](const RunResult& r) { return r.outcome.headline; })
      .def_property_readonly("report", [](const RunResult& r) { return r.outcome.report; })
      .def_property_readonly("core_s", [](const RunResult& r) { return r.core_s; })
      .def_property_readonly("ensemble_json", [](const RunResult& r) { return r.ensemble_json; })
      .def_property_readonly("ensemble_report",
                             [](const RunResult& r) { return r.ensemble_report; })
      .def("tables", &tables, "Every recorder's table, its columns as read-only NumPy views.");
  module.def(
      "run",
      [](const std::optional<std::string>& text, const std::string& path,
         const std::optional<py::dict>& record, const std::optional<std::string>& out,
         std::optional<long> max_steps, double time_limit, bool histories,
         const std::optional<py::object>& progress, std::optional<int> ensemble,
         double perturbation, double robust_spread, int jobs) {
        return run(text, path, record, out, max_steps, time_limit, histories, progress,
                   {ensemble, perturbation, robust_spread, jobs});
      },
      py::arg("text"), py::arg("path"), py::arg("record"), py::arg("out"), py::arg("max_steps"),
      py::arg("time_limit"), py::arg("histories"), py::arg("progress"), py::arg("ensemble"),
      py::arg("perturbation"), py::arg("robust_spread"), py::arg("jobs"),
      "Runs a model as `pound run` does (the GIL released); writes to `out` when given.");
  module.def("batch", &batch, py::arg("text"), py::arg("path"), py::arg("out"), py::arg("jobs"),
             py::arg("resume"), py::arg("progress"),
             "Runs a batch set as `pound batch` does; returns its report.");
}

}  // namespace pound::python
