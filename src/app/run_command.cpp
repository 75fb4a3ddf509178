#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <boost/program_options.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "app/ensemble.hpp"
#include "app/model_run.hpp"
#include "app/progress_line.hpp"
#include "io/ground_motion_reader.hpp"
#include "io/output.hpp"
#include "io/output_paths.hpp"

namespace pound::app {
namespace po = boost::program_options;

namespace {

constexpr const char* kRunUsage =
    R"(usage: pound run MODEL.json [--motion RECORD] [--out DIR] [--ensemble N]

Runs the time-history analysis of a model file (format: docs/model_format.md) and writes into
DIR (default out/<model name>):
  summary.json   run statistics and, per link: impacts, peak force, peak penetration, impulse,
                 work; for a model that is one rod_pair, the metrics against the exact solution
  <recorder>.csv the time histories the model's recorders ask for (default links.csv)
Nothing is written when the model is invalid (exit code 2). If the analysis fails (exit code 3)
the histories up to the failure are written and summary.json says "status": "failed".
With --ensemble N it also runs N copies with every record scaled by 1 + eps, 1 - eps, 1 + 2 eps,
... (eps = --perturbation) and writes ensemble.json: for every number of summary.json the
unperturbed value, the median, 16 and 84 % and range of the copies, and whether it is robust.
Pounding peaks after the first impacts are chaotic: read those as distributions.

options)";

}  // namespace

namespace {

// The options that say how to read and scale --motion's record.
constexpr const char* kMotionOptions[] = {"units", "column", "dt", "time-column", "scale", "pga"};

// --motion and its options; throws std::invalid_argument naming a bad option.
MotionOverride motion_override(const std::string& path, const po::variables_map& vm) {
  MotionOverride motion;
  motion.path = path;
  motion.time_column = vm.count("time-column") > 0;
  if (vm.count("units")) {
    motion.units = vm["units"].as<std::string>();
    try {
      (void)io::parse_acceleration_unit(*motion.units);
    } catch (const std::invalid_argument& unknown) {
      throw std::invalid_argument(std::string("--units: ") + unknown.what());
    }
  }
  if (vm.count("column")) {
    motion.column = vm["column"].as<int>();
    if (*motion.column < 1) throw std::invalid_argument("--column must be 1 or more");
  }
  auto positive = [&](const char* option) -> std::optional<double> {
    if (!vm.count(option)) return std::nullopt;
    const double value = vm[option].as<double>();
    if (!(value > 0.0) || !std::isfinite(value))
      throw std::invalid_argument(fmt::format("--{} must be a positive number", option));
    return value;
  };
  motion.time_step = positive("dt");
  motion.scale_factor = positive("scale");
  motion.target_pga = positive("pga");
  if (motion.scale_factor && motion.target_pga)
    throw std::invalid_argument("give --scale or --pga, not both");
  return motion;
}

// What is wrong with the command line, or empty.
std::string request_error(const RunRequest& request) {
  if (request.model_path.empty()) return "name a model file (see `pound run --help`)";
  if (request.max_steps && *request.max_steps < 0) return "--max-steps must be >= 0";
  if (!(request.time_limit >= 0.0) || !std::isfinite(request.time_limit))
    return "--time-limit must be a number of seconds >= 0";
  return {};
}

void print_warnings(std::span<const std::string> warnings) {
  for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
}

// Prints the run's report and its warnings but the first `printed` (shown before the solve); the
// exit code: 3 when the analysis failed.
int report_outcome(const RunOutcome& outcome, const std::string& model_path, const std::string& out,
                   bool quiet, std::size_t printed = 0) {
  if (!quiet) std::cout << outcome.headline << " -> " << out << "/\n" << outcome.report;
  print_warnings(std::span(outcome.warnings).subspan(std::min(printed, outcome.warnings.size())));
  if (!outcome.failure.empty()) {
    std::cerr << fmt::format(
        "error: {}: analysis failed at t = {:.6g}: {} (results up to then are in {}/)\n",
        model_path, outcome.failure_time, outcome.failure, out);
    return 3;
  }
  return 0;
}

// RunRequest::progress for `line`: its clock restarts as the solve starts.
std::function<void(double, double, double)> solve_progress(ProgressLine& line, std::string what) {
  return [&line, what, started = false](double time, double start, double end) mutable {
    if (!started) {  // the solve starts: its time counts from here
      line.restart();
      started = true;
      return;
    }
    line.update([&](double elapsed) {
      return "progress: " + what + solve_progress_text(time, start, end, elapsed);
    });
  };
}

}  // namespace

int run_command(const Arguments& arguments) {
  po::options_description options(kRunUsage);
  RunRequest request;
  EnsembleOptions ensemble;
  std::string out, motion;
  double progress_interval = 0.0;
  options.add_options()("help,h", "show this help")("out,o", po::value(&out),
                                                    "output folder (default out/<model name>)")(
      "motion", po::value(&motion),
      "ground-motion record (.AT2, or columns) replacing the model's first excitation's (its "
      "direction, supports and, without --scale or --pga, its scaling stay), or exciting the "
      "model along x when it has none; summary.json records the file, its SHA-1 and the PGA "
      "applied")("units", po::value<std::string>(),
                 "--motion: units of the file's values, g | m/s2 | cm/s2 | model (default: the "
                 "model's excitation's, else g)")(
      "column", po::value<int>(),
      "--motion: the column to read in a columns file, from 1 (default 1, or 2 with "
      "--time-column)")(
      "dt", po::value<double>(),
      "--motion: time step of a columns file that does not state it, in the model's "
      "time unit (s unless its units say ms)")(
      "time-column", "--motion: the first column of a columns file is time")(
      "scale", po::value<double>(), "--motion: multiply the record by this factor")(
      "pga", po::value<double>(), "--motion: scale the record to this peak acceleration [g]")(
      "max-steps", po::value<long>(),
      "stop with an error after this many steps (0: no limit, whatever the model's \"max_steps\"; "
      "default: the model's)")(
      "time-limit", po::value(&request.time_limit),
      "stop with an error after this many seconds of solving (0: no limit); the histories so far "
      "are kept")("ensemble", po::value(&ensemble.copies),
                  "also run this many copies with the records perturbed, for the spread of every "
                  "result (ensemble.json)")(
      "perturbation", po::value(&ensemble.perturbation)->default_value(1e-4, "1e-4"),
      "relative change of the records between copies, in (0, 0.01)")(
      "robust-spread", po::value(&ensemble.robust_spread)->default_value(0.05, "0.05"),
      "a result whose 16-84 % spread over the copies is within this share of its size is robust")(
      "jobs,j", po::value(&ensemble.jobs)->default_value(0, "every core"),
      "threads for the copies")(
      "progress", po::value(&progress_interval),
      "print how far the run has come every SECONDS, for logs (without it: on a terminal a line "
      "kept up to date once a run takes over 2 s, elsewhere nothing)")("quiet,q",
                                                                       "print nothing but errors");
  const auto parsed = parse_command_line(arguments, options, "model", request.model_path);
  if (!parsed) return 0;
  if (parsed->count("max-steps")) request.max_steps = (*parsed)["max-steps"].as<long>();
  const bool with_ensemble = parsed->count("ensemble") > 0;
  std::string error = request_error(request);
  if (error.empty() && with_ensemble)
    if (const auto wrong = ensemble_options_error(ensemble))
      error = fmt::format("{}: {}", wrong->option(), wrong->why);
  if (error.empty() && parsed->count("progress") &&
      !(progress_interval > 0.0 && std::isfinite(progress_interval)))
    error = "--progress must be a positive number of seconds";
  if (error.empty() && parsed->count("progress") && parsed->count("quiet"))
    error = "--progress asks for a line every so many seconds and --quiet for nothing: give one";
  for (const char* option : {"perturbation", "robust-spread", "jobs"})
    if (error.empty() && !with_ensemble && !(*parsed)[option].defaulted())
      error =
          fmt::format("--{} applies to the copies of --ensemble N only: add --ensemble N", option);
  for (const char* option : kMotionOptions)
    if (error.empty() && motion.empty() && parsed->count(option))
      error =
          fmt::format("--{} says how to read the record of --motion: add --motion RECORD", option);
  if (error.empty() && !motion.empty()) try {
      request.motion = motion_override(motion, *parsed);
    } catch (const std::invalid_argument& bad) {
      error = bad.what();
    }
  if (!error.empty()) {
    std::cerr << "pound run: " << error << "\n";
    return 1;
  }
  if (out.empty()) out = io::folder_named_after("out", request.model_path, "--out");
  request.before_run = [&](const LoadedModel& loaded) {
    check_run_outputs(out, request, loaded, with_ensemble);
  };

  // Everything that can be wrong with the input is found before any output exists.
  const bool quiet = parsed->count("quiet") > 0;
  // The warnings found before the run are shown at once: one of a run of days says so then.
  std::size_t printed = 0;
  request.before_solve = [&](const std::vector<std::string>& warnings) {
    // The input is good: a folder that cannot be made is said now, not after a long solve.
    io::create_output_folder(out);
    print_warnings(warnings);
    printed = warnings.size();
  };
  std::optional<ProgressLine> line;
  if (ProgressSettings settings;
      progress_settings(!quiet, progress_interval, ::isatty(STDERR_FILENO), settings))
    line.emplace(std::cerr, settings);
  if (line) request.progress = solve_progress(*line, with_ensemble ? "unperturbed run, " : "");
  if (!with_ensemble) {
    const RunOutcome outcome = run_model(request);
    if (line) line->finish();
    write_run_outputs(out, outcome);
    return report_outcome(outcome, request.model_path, out, quiet, printed);
  }
  const EnsembleResult result =
      run_ensemble(request, ensemble, [&](std::size_t done, std::size_t total) {
        if (!line) return;
        if (done == 0) {  // the copies start: their own time and rate
          line->finish();
          line->restart();
        }
        line->update([&](double elapsed) {
          return "progress: " + copies_progress_text(done, total, elapsed);
        });
      });
  if (line) line->finish();
  write_run_outputs(out, result.unperturbed,
                    {{"ensemble.json", ensemble_document(result, ensemble)}});
  const int code = report_outcome(result.unperturbed, request.model_path, out, quiet, printed);
  if (!quiet) std::cout << ensemble_report(result, ensemble);
  return code;
}

}  // namespace pound::app
