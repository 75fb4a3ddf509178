#include "app/model_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <optional>

#include "app/run_report.hpp"
#include "assembly/modal_analysis.hpp"
#include "assembly/static_equilibrium.hpp"
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "builder/start_check.hpp"
#include "core/errors.hpp"
#include "core/stopwatch.hpp"
#include "io/output.hpp"
#include "io/output_paths.hpp"
#include "io/run_summary_document.hpp"
#include "io/system_memory.hpp"
#include "model/ground_motion.hpp"
#include "model/record_pair.hpp"
#include "results/run_summary.hpp"
#include "verification/model_check.hpp"
#include "verification/rod_impact_observer.hpp"
#include "verification/rod_impact_report.hpp"

namespace pound::app {
namespace {

// A model read, built and assembled with its integrator and what watches it: everything a run
// needs before its first step, every input error found.
struct PreparedRun {
  LoadedModel loaded;
  std::unique_ptr<assembly::StructuralSystem> system;
  std::unique_ptr<integrators::Integrator> integrator;
  std::unique_ptr<results::RunObservers> observers;
  std::unique_ptr<verification::RodImpactObserver> verification;
  std::vector<std::string> warnings;  // found before the run
  double setup_s = 0.0;
};

// What the solve left: the last state reached, its statistics and how it ended.
struct Solved {
  integrators::State state;
  integrators::TransientStatistics statistics;
  results::RunStatus status;
  double run_time = 0.0;
};

// A record much longer than the analysis was read whole for nothing; it may be a mistaken
// duration.
std::vector<std::string> record_warnings(const LoadedModel& loaded) {
  std::vector<std::string> warnings;
  const double duration = loaded.built.analysis.duration;
  const std::string& unit = loaded.spec.units.time;  // records are held in the model's time
  for (const model::GroundMotion& record : loaded.records)
    if (record.duration() > 10.0 * duration)
      warnings.push_back(fmt::format(
          "record '{}' lasts {:.4g} {} but the analysis stops at {:.4g} {}: only its first "
          "{:.1f} % is used (is /analysis/duration what you meant?)",
          record.name, record.duration(), unit, duration, unit,
          100.0 * duration / record.duration()));
  return warnings;
}

// Drift monitors read how far a storey still swings at the end over twice the structure's first
// period: a window a higher mode's ripple cannot fill. Without modes (a mechanism) they read the
// drift's last cycle.
void set_swing_window(const builder::BuiltModel& built, const assembly::StructuralSystem& system,
                      results::RunObservers& observers) {
  if (built.drift_monitors.empty()) return;
  try {
    const std::vector<double> periods = assembly::natural_periods(system, 1);
    if (!periods.empty() && std::isfinite(periods.front()) && periods.front() > 0.0)
      observers.set_swing_window(2.0 * periods.front());
  } catch (const std::exception&) {
  }
}

bool driven_by_records(const model::Model& model) {
  return !model.excitations.empty() || !model.support_excitations.empty();
}

// What scale_drivers scales in `model`, for the ensemble's report.
std::string drivers_named(const model::Model& model) {
  if (driven_by_records(model)) return "the records";
  std::vector<std::string> names;
  const auto moving = [](const model::Coordinates& v) {
    return v[0] != 0.0 || v[1] != 0.0 || v[2] != 0.0;
  };
  if (std::any_of(model.initial_velocity.begin(), model.initial_velocity.end(), moving))
    names.emplace_back("initial velocities");
  if (!model.loads.empty()) names.emplace_back("loads");
  if (model.gravity && model.gravity->acceleration != 0.0) names.emplace_back("gravity");
  if (names.empty()) return "nothing (no records, initial velocities, loads or gravity)";
  std::string text = "the " + names[0];
  for (std::size_t k = 1; k < names.size(); ++k)
    text += (k + 1 == names.size() ? " and " : ", ") + names[k];
  return text;
}

// An ensemble member's perturbation: the records' accelerations times `factor`, or in a model
// without them (a free vibration) what sets it moving, its initial velocities, nodal loads and
// gravity.
void scale_drivers(model::Model& model, double factor) {
  for (model::UniformExcitation& e : model.excitations)
    for (double& a : e.motion.acceleration) a *= factor;
  for (model::SupportExcitation& e : model.support_excitations)
    for (double& a : e.motion.acceleration) a *= factor;
  if (driven_by_records(model)) return;
  for (model::Coordinates& velocity : model.initial_velocity)
    for (double& v : velocity) v *= factor;
  for (model::NodalLoad& load : model.loads)
    for (double& f : load.force) f *= factor;
  if (model.gravity) model.gravity->acceleration *= factor;
}

PreparedRun prepare(const RunRequest& request) {
  const Stopwatch stopwatch;
  const std::string& model_path = request.model_path;
  PreparedRun run{request.record ? load_model_with_record(model_path, *request.record)
                  : request.model_text
                      ? load_model_text(*request.model_text, model_path, request.motion)
                      : load_model(model_path, request.motion)};
  if (request.before_run) request.before_run(run.loaded);
  builder::BuiltModel& built = run.loaded.built;
  if (request.max_steps) built.analysis.max_steps = *request.max_steps;
  if (request.record_factor != 1.0) {
    scale_drivers(built.model, request.record_factor);
    // The exact rod solution compared with it is linear in the rods' velocities.
    if (built.sole_rod_pair && !driven_by_records(built.model))
      for (builder::RodSpec* rod : {&built.sole_rod_pair->left, &built.sole_rod_pair->right})
        rod->initial_velocity *= request.record_factor;
  }
  built.analysis.time_limit = request.time_limit;
  try {
    run.system = std::make_unique<assembly::StructuralSystem>(built.model);
  } catch (const InputError& error) {
    throw error.in_file(model_path);
  }
  builder::settle_time_step(built.analysis, built.model, *run.system, model_path);
  run.integrator = builder::make_integrator(built.analysis);
  run.observers = std::make_unique<results::RunObservers>(built, *run.system, request.histories);
  results::check_histories_fit(run.observers->recorders(), built.analysis,
                               io::available_memory_bytes(), model_path);
  results::reserve_histories(run.observers->recorders(), built.analysis);
  run.verification =
      verification::RodImpactObserver::attach(built, run.system->dofs(), run.system->links());
  if (run.verification) run.observers->add(*run.verification);
  run.warnings = verification::check_model(built, built.analysis, *run.system, false).warnings;
  set_swing_window(built, *run.system, *run.observers);
  // After the diagnostics, which see the laws as built; the run's start commits them again. Not
  // before a static start, which must find them as built: the first step's start commits them
  // with the initial velocities (a friction anchor moved by its stick dashpot's c_t v0 made the
  // static solve of a launched block "slide away"), so it is tried on a system of its own.
  if (built.analysis.static_initial_state) {
    assembly::StructuralSystem trial(built.model);
    builder::check_first_step(built, built.analysis, trial, model_path);
  } else {
    builder::check_first_step(built, built.analysis, *run.system, model_path);
  }
  for (std::string& warning : record_warnings(run.loaded)) run.warnings.push_back(warning);
  run.setup_s = stopwatch.seconds();
  return run;
}

// Integrates to the end or to a failure; a failed analysis keeps what it reached.
Solved solve(PreparedRun& run, const RunRequest& request) {
  const builder::BuiltModel& built = run.loaded.built;
  const integrators::TransientSettings settings = builder::make_transient_settings(built.analysis);
  integrators::TransientAnalysis analysis(*run.system, *run.integrator, settings);
  Solved solved;
  solved.state.velocity = run.system->initial_velocity(built.model);
  const Stopwatch stopwatch;
  try {
    if (built.analysis.static_initial_state)
      solved.state.displacement =
          assembly::static_equilibrium(*run.system, solved.state.time).displacement;
    const auto record = [&](const integrators::State& s, const integrators::StepResult&) {
      run.observers->record(s);
    };
    if (request.progress) {
      const double start = solved.state.time, end = settings.end_time;
      request.progress(start, start, end);
      long steps = 0;
      solved.statistics = analysis.run(
          solved.state, [&](const integrators::State& s, const integrators::StepResult& result) {
            record(s, result);
            if (++steps % kProgressStride == 0) request.progress(s.time, start, end);
          });
    } else {
      solved.statistics = analysis.run(solved.state, record);  // no branch for a progress line
    }
    solved.status.end_time = solved.state.time;
  } catch (const SolveError& error) {
    solved.status = {error.reason(), error.time()};
    solved.statistics = analysis.statistics();  // up to the failure
  } catch (const assembly::NotPositiveDefinite& failure) {
    // The first step's matrix held (builder::check_first_step), a later step size's does not:
    // a cut step's, or the last, shorter one's. The time is the start of the step that failed.
    solved.status = {
        builder::not_held_error(built, run.system->dofs(), failure, "the matrix of a new step size",
                                run.loaded.spec.source)
            .reason(),
        solved.state.time};
    solved.statistics = analysis.statistics();
  }
  solved.run_time = stopwatch.seconds();
  return solved;
}

// Excitation k as applied: the factor on the record as read (with a batch's IDA factor), the
// resulting PGA in model units and in g, and who replaced the model's record (empty if none).
struct AppliedRecord {
  double factor = 1.0, pga = 0.0, pga_g = 0.0;
  std::string replaced_by;
  double pair_pga = 0.0;  // a pair's second component's, scaled by the same factor
};

AppliedRecord applied_record(const LoadedModel& loaded, std::size_t k) {
  const double factor = loaded.built.excitation_factors.at(k);
  const double pga = factor * loaded.records[k].peak();
  const auto& second = loaded.second_components.at(k);
  return {factor, pga, pga / loaded.spec.units.gravity(),
          k == 0 ? loaded.first_record_replaced_by : std::string(),
          second ? factor * second->motion.peak() : 0.0};
}

// The case's record as applied, in g: its peak and the set's intensity measure.
void summarise_record(const LoadedModel& loaded, const builder::IntensityMeasure& intensity,
                      results::CaseSummary& c) {
  if (loaded.records.empty() || loaded.built.excitation_factors.empty()) return;
  const AppliedRecord applied = applied_record(loaded, 0);
  c.pga_g = applied.pga_g;
  // The set's period is in seconds, the records in the model's unit of time.
  const double period = intensity.type == builder::IntensityKind::sa
                            ? intensity.period * loaded.spec.units.second()
                            : 0.0;
  if (const auto& second = loaded.second_components.front()) {
    // A pair: the larger component's PGA (the first alone read 0.38 g of a pair scaled to RotD50
    // 0.4 g whose second peaks at 0.55 g), and its RotD50 or the geometric mean of its
    // components' measures (period 0: PGA).
    c.pga_g = std::max(applied.pga_g, applied.pair_pga / loaded.spec.units.gravity());
    const model::PairSpectralAcceleration measures = model::pair_spectral_acceleration(
        model::make_component_pair(loaded.records.front(), second->motion), period,
        intensity.damping);
    c.intensity = applied.factor *
                  (intensity.pair == builder::PairMeasure::rot_d50 ? measures.rot_d50
                                                                   : measures.geometric_mean) /
                  loaded.spec.units.gravity();
    return;
  }
  c.intensity =
      intensity.type == builder::IntensityKind::sa
          ? applied.factor *
                model::spectral_acceleration(loaded.records.front(), period, intensity.damping) /
                loaded.spec.units.gravity()
          : applied.pga_g;
}

// The verification of a rod pair against the exact solution. The exact solution has limits of
// its own (event count, number range): beyond them the run keeps its results with a warning.
std::optional<verification::RodImpactMetrics> verify_rod_pair(const PreparedRun& run,
                                                              const Solved& solved,
                                                              std::vector<std::string>& warnings) {
  if (!run.verification || !solved.status.completed()) return std::nullopt;
  try {
    verification::RodImpactMetrics metrics = run.verification->metrics(solved.state);
    metrics.run_time_s = solved.run_time;
    metrics.steps = solved.statistics.steps;
    metrics.newton_iterations = solved.statistics.newton_iterations;
    return metrics;
  } catch (const std::exception& error) {
    warnings.push_back(fmt::format(
        "the exact solution of the rod pair could not be computed, so the run is not verified "
        "against it: {}",
        error.what()));
    return std::nullopt;
  }
}

std::string verification_line(const verification::RodImpactMetrics& metrics) {
  return fmt::format(
      "  against the exact solution: force_l2_error {:.4f}, duration_error {:+.4f}, "
      "separation_velocity_error {:+.4f}, peak_force_ratio {:.3f}\n",
      metrics.force_l2_error, metrics.duration_error, metrics.separation_velocity_error,
      metrics.peak_force_ratio);
}

// How excitation k was scaled: "as recorded", or its factor or target, then a batch's IDA scale
// (`ida_scale`, where not 1: `factor` beside it holds both, so a record scaled to Sa 0.5 g at
// x2 has Sa 1 g).
io::Document scaling_document(const builder::ExcitationSpec& e) {
  io::Document scaling;
  if (e.target_pga)
    scaling.set("target_pga_g", *e.target_pga);
  else if (e.target_sa)
    scaling.set("target_sa_g", *e.target_sa)
        .set("period", e.sa_period)
        .set("damping_ratio", e.sa_damping);
  else if (e.scale_factor)
    scaling.set("factor", *e.scale_factor);
  else
    scaling.set("as_recorded", true);
  if (e.extra_factor != 1.0) scaling.set("ida_scale", e.extra_factor);
  return scaling;
}

// Each excitation as applied, so that a run can be traced to its records: the file (as opened)
// and its SHA-1, format, units, the scaling asked for, the factor applied and the resulting PGA.
std::vector<io::Document> excitation_documents(const LoadedModel& loaded) {
  std::vector<io::Document> items;
  for (std::size_t k = 0; k < loaded.records.size(); ++k) {
    const AppliedRecord applied = applied_record(loaded, k);
    io::Document item;
    item.set("record", loaded.record_paths[k])
        .set("sha1", loaded.record_sources[k].sha1)
        .set("format", loaded.record_sources[k].format)
        .set("units", loaded.spec.excitations[k].units);
    // Which component of a columns file (a time column before it, if any).
    if (loaded.record_sources[k].format == "columns") {
      item.set("column", static_cast<long>(loaded.spec.excitations[k].column));
      if (loaded.spec.excitations[k].time_column) item.set("time_column", true);
    }
    item.set("points", static_cast<long>(loaded.records[k].acceleration.size()))
        .set("dt", loaded.records[k].time_step)
        .set("scaling", scaling_document(loaded.spec.excitations[k]))
        .set("factor", applied.factor)
        .set("pga", applied.pga)
        .set("pga_g", applied.pga_g);
    if (!applied.replaced_by.empty()) item.set("replaced_by", applied.replaced_by);
    if (const auto& second = loaded.second_components.at(k))
      // The pair's second component, scaled by the same factor; targets are the pair's RotD50.
      item.set("pair", io::Document()
                           .set("record", second->path)
                           .set("sha1", second->source.sha1)
                           .set("format", second->source.format)
                           .set("angle_deg", loaded.spec.excitations[k].pair->angle)
                           .set("pga", applied.pair_pga)
                           .set("pga_g", applied.pair_pga / loaded.spec.units.gravity()));
    items.push_back(item);
  }
  return items;
}

// The model's title, unless it may name a record that was replaced: then what ran.
std::string run_title(const LoadedModel& loaded, const std::string& model_path) {
  if (loaded.first_record_replaced_by.empty() || loaded.records.empty()) return loaded.spec.title;
  return fmt::format("{} under {} (record replaced by {})",
                     std::filesystem::path(model_path).stem().string(), loaded.records.front().name,
                     loaded.first_record_replaced_by);
}

// A line per excitation for the report: what was applied, from which file.
std::string excitation_lines(const LoadedModel& loaded) {
  std::string text;
  for (std::size_t k = 0; k < loaded.records.size(); ++k) {
    const AppliedRecord applied = applied_record(loaded, k);
    text += fmt::format(
        "  record {} (sha1 {}): scale factor {:.4g}, PGA {:.4g} g{}\n", loaded.record_paths[k],
        loaded.record_sources[k].sha1.substr(0, 12), applied.factor, applied.pga_g,
        applied.replaced_by.empty() ? "" : fmt::format(" (replaced by {})", applied.replaced_by));
    if (const auto& second = loaded.second_components.at(k))
      text += fmt::format("  paired with {} (sha1 {}) at {:g} deg, PGA {:.4g} g\n", second->path,
                          second->source.sha1.substr(0, 12), loaded.spec.excitations[k].pair->angle,
                          applied.pair_pga / loaded.spec.units.gravity());
  }
  return text;
}

// The summary of a run, with its excitations and its verification when there is one.
io::Document summary_document(const results::RunSummary& summary, const RunRequest& request,
                              const PreparedRun& run,
                              const std::optional<verification::RodImpactMetrics>& metrics) {
  io::Document document =
      io::to_document(summary, request.model_path, run_title(run.loaded, request.model_path));
  document.set("units", units_document(run.loaded.spec.units));
  if (!run.loaded.records.empty()) {
    document.set("excitations", excitation_documents(run.loaded));
    if (!run.loaded.first_record_replaced_by.empty())
      document.set("model_title", run.loaded.spec.title);
  }
  if (metrics) document.set("verification", verification::to_document(*metrics));
  return document;
}

// A completed run whose results overflowed (a load, mass, stiffness or record near the end of
// the number range) has not completed: its first non-finite result names the failure.
std::string overflow_failure(const std::vector<std::string>& non_finite) {
  return fmt::format(
      "a result is not finite ({}{}): a quantity of the model overflowed the number range (a load, "
      "mass, stiffness or record value far beyond physical ones?)",
      non_finite.front(),
      non_finite.size() > 1 ? fmt::format(" and {} more", non_finite.size() - 1) : "");
}

RunOutcome summarise(const RunRequest& request, const PreparedRun& run, const Solved& solved) {
  const builder::BuiltModel& built = run.loaded.built;
  results::RunSummary summary =
      results::summarise_run(built, *run.system, *run.observers, solved.status, solved.statistics,
                             run.integrator->name(), solved.run_time);
  summary.warnings.insert(summary.warnings.begin(), run.warnings.begin(), run.warnings.end());
  std::optional<verification::RodImpactMetrics> metrics =
      verify_rod_pair(run, solved, summary.warnings);
  RunOutcome outcome;
  outcome.perturbed = drivers_named(built.model);
  outcome.summary = summary_document(summary, request, run, metrics);
  if (summary.status.completed() && !outcome.summary.non_finite().empty()) {
    summary.status.failure = overflow_failure(outcome.summary.non_finite());
    metrics.reset();
    outcome.summary = summary_document(summary, request, run, metrics);
  }
  outcome.headline = run_headline(request.model_path, summary);
  outcome.report = excitation_lines(run.loaded) + run_report(summary, built.units) +
                   (metrics ? verification_line(*metrics) : "") + energy_line(summary, built.units);
  outcome.warnings = summary.warnings;
  outcome.failure = summary.status.failure;
  outcome.failure_time = summary.status.end_time;
  for (std::size_t k = 0; k < run.observers->recorders().size(); ++k) {
    const auto& recorder = run.observers->recorders()[k];
    outcome.histories.emplace_back(recorder->file(), recorder->take_table());
    const builder::ResolvedRecorder& spec = built.recorders.at(k);
    outcome.recorded.push_back({spec.kind, spec.envelope});
  }
  outcome.setup_s = run.setup_s;
  summarise_record(run.loaded, request.intensity, outcome.case_summary);
  results::summarise_case(summary, outcome.case_summary);
  return outcome;
}

}  // namespace

RunOutcome run_model(const RunRequest& request) {
  PreparedRun run = prepare(request);
  if (request.before_solve) request.before_solve(run.warnings);
  const Solved solved = solve(run, request);
  return summarise(request, run, solved);
}

// summary.json, ensemble.json and the recorders' CSVs in `out`: none may be the model, a record or
// another output (a record named like a recorder's file in the folder given as --out).
void check_run_outputs(const std::string& out, const RunRequest& request, const LoadedModel& loaded,
                       bool ensemble, const std::string& out_name) {
  namespace fs = std::filesystem;
  std::vector<io::NamedPath> inputs{{request.model_path, "the model"}};
  for (std::size_t k = 0; k < loaded.record_paths.size(); ++k)
    inputs.push_back({loaded.record_paths[k],
                      k == 0 && request.motion
                          ? request.motion->replaced_by
                          : fmt::format("{}: /excitations/{}/record", request.model_path, k)});
  for (std::size_t k = 0; k < loaded.second_components.size(); ++k)
    if (const auto& second = loaded.second_components[k])
      inputs.push_back(
          {second->path, fmt::format("{}: /excitations/{}/pair/record", request.model_path, k)});
  std::vector<io::NamedPath> outputs{{(fs::path(out) / "summary.json").string(), out_name}};
  if (ensemble) outputs.push_back({(fs::path(out) / "ensemble.json").string(), out_name});
  const auto& recorders = loaded.built.recorders;
  const bool named_in_model =
      loaded.spec.recorders_given && loaded.spec.recorders.size() == recorders.size();
  for (std::size_t k = 0; k < recorders.size(); ++k)
    outputs.push_back(named_in_model
                          ? io::NamedPath{(fs::path(out) / recorders[k].file).string(),
                                          fmt::format("/recorders/{}/file", k), request.model_path}
                          : io::NamedPath{(fs::path(out) / recorders[k].file).string(), out_name});
  io::check_outputs_apart(inputs, outputs);
}

void write_run_outputs(const std::string& folder, const RunOutcome& outcome,
                       const std::vector<std::pair<std::string, io::Document>>& extra) {
  io::create_output_folder(folder);
  io::remove_stale_temporaries(folder);  // of an earlier run killed with SIGKILL
  // All staged, then renamed into place with summary.json last: a folder with a summary.json has
  // the histories of that run, and an interrupted run leaves the earlier run's files.
  io::StagedFiles files;
  std::vector<std::pair<std::string, const Table*>> tables;
  for (const auto& [file, table] : outcome.histories)
    tables.emplace_back((std::filesystem::path(folder) / file).string(), &table);
  files.write_tables(tables);
  for (const auto& [file, document] : extra)
    files.write((std::filesystem::path(folder) / file).string(), document.dump() + "\n");
  files.write((std::filesystem::path(folder) / "summary.json").string(),
              outcome.summary.dump() + "\n");
  files.commit();
}

}  // namespace pound::app
