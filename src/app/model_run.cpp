#include "app/model_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>

#include "assembly/static_equilibrium.hpp"
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "core/errors.hpp"
#include "io/output.hpp"
#include "io/system_memory.hpp"
#include "model/ground_motion.hpp"
#include "results/energy_balance.hpp"
#include "results/monitors.hpp"
#include "results/recorders.hpp"
#include "verification/rod_impact.hpp"
#include "verification/rod_impact_report.hpp"

namespace pound::app {

namespace {

std::vector<std::unique_ptr<results::Recorder>> make_recorders(const builder::BuiltModel& built,
                                                               const model::DofMap& dofs,
                                                               const integrators::LinkSet& links) {
  std::vector<std::unique_ptr<results::Recorder>> recorders;
  for (const builder::ResolvedRecorder& spec : built.recorders) {
    std::vector<std::string> ids;
    if (spec.kind == builder::RecorderKind::link) {
      std::vector<results::LinkRows> rows;
      for (Index link : spec.items) {
        ids.push_back(built.model.links[static_cast<std::size_t>(link)].id);
        rows.push_back({links.row(link), links.has_friction(link)});
      }
      recorders.push_back(std::make_unique<results::LinkRecorder>(spec.file, rows, ids));
    } else {
      std::vector<std::vector<Index>> equations;
      for (Index node : spec.items) {
        ids.push_back(built.model.nodes[static_cast<std::size_t>(node)].id);
        std::vector<Index> per_direction;
        for (int d = 0; d < dofs.dofs_per_node(); ++d)
          per_direction.push_back(dofs.equation(node, d));
        equations.push_back(std::move(per_direction));
      }
      recorders.push_back(
          std::make_unique<results::NodeRecorder>(spec.file, std::move(equations), ids));
    }
  }
  return recorders;
}

io::Document link_document(const model::Link& link, const results::LinkSummary& s) {
  io::Document doc;
  doc.set("id", link.id)
      .set("impacts", s.impacts)
      .set("peak_force", s.peak_force)
      .set("peak_tension", s.peak_tension)
      .set("peak_penetration", s.peak_penetration)
      .set("peak_opening", s.peak_opening)
      .set("impulse", s.impulse)
      .set("work", s.work);
  if (s.first_contact >= 0.0)
    doc.set("first_contact", s.first_contact).set("last_contact", s.last_contact);
  return doc;
}

// The histories are held in memory until the run ends: refuse a run whose recorders would not
// fit (a long record at a fine step with many nodes recorded) before it starts. A table grows by
// doubling and is copied once for writing: three times its size at the peak.
void check_histories_fit(const std::vector<std::unique_ptr<results::Recorder>>& recorders,
                         const builder::AnalysisSpec& analysis, const std::string& model_path) {
  std::size_t columns = 0;
  for (const auto& recorder : recorders) columns += recorder->table().columns.size();
  if (columns == 0) return;
  const double steps = std::ceil(analysis.duration / analysis.time_step) + 1.0;
  const double needed = 3.0 * 8.0 * steps * static_cast<double>(columns);
  const std::optional<std::size_t> available = io::available_memory_bytes();
  constexpr double gib = 1024.0 * 1024.0 * 1024.0;
  if (available && needed > static_cast<double>(*available))
    throw InputError(
        model_path, "/recorders",
        fmt::format("recording {} columns over {:.0f} steps needs about {:.1f} GiB, "
                    "more than the {:.1f} GiB of memory available: record fewer "
                    "links or nodes, or a shorter duration",
                    columns, steps, needed / gib, static_cast<double>(*available) / gib));
}

// The numbers a batch row needs, from what the run recorded.
void summarise_case(const LoadedModel& loaded, const RunRequest& request,
                    const results::LinkSummaries& links, const results::DriftMonitors& drifts,
                    const results::JointMonitors& joints, const results::EnergyBalance& energy,
                    const integrators::TransientStatistics& stats, double end_time, double run_time,
                    RunOutcome& outcome) {
  const builder::BuiltModel& built = loaded.built;
  results::CaseSummary& c = outcome.case_summary;
  c.status = outcome.failure.empty() ? "completed" : "failed";
  c.reason = outcome.failure.empty() ? std::string()
                                     : fmt::format("analysis failed at t = {:.6g}: {}",
                                                   outcome.failure_time, outcome.failure);
  if (!loaded.records.empty() && !built.excitation_factors.empty()) {
    const double gravity = loaded.spec.units.gravity();
    const double factor = built.excitation_factors.front();
    const model::GroundMotion& record = loaded.records.front();
    c.pga_g = factor * record.peak() / gravity;
    c.intensity = request.intensity.type == "sa"
                      ? factor *
                            model::spectral_acceleration(record, request.intensity.period,
                                                         request.intensity.damping) /
                            gravity
                      : *c.pga_g;
  }
  c.end_time = end_time;
  c.steps = static_cast<double>(stats.steps);
  for (std::size_t k = 0; k < built.model.links.size(); ++k) {
    const results::LinkSummary& s = links.summaries()[k];
    const links::LinkRole role = built.model.links[k].role();
    const std::string& id = built.model.links[k].id;
    if (role == links::LinkRole::spring) continue;
    if (role == links::LinkRole::tension) {
      if (!c.max_restrainer_force || s.peak_tension > *c.max_restrainer_force) {
        c.max_restrainer_force = s.peak_tension;
        c.max_restrainer_link = id;
      }
      continue;
    }
    c.impacts = c.impacts.value_or(0.0) + s.impacts;
    if (!c.max_pounding_force || s.peak_force > *c.max_pounding_force) {
      c.max_pounding_force = s.peak_force;
      c.max_pounding_link = id;
    }
  }
  for (std::size_t k = 0; k < built.joint_monitors.size(); ++k) {
    const builder::JointMonitor& m = built.joint_monitors[k];
    const results::JointPeak& peak = joints.peaks()[k];
    c.max_joint_opening = std::max(c.max_joint_opening.value_or(0.0), peak.peak_opening);
    c.max_seat_movement = std::max(c.max_seat_movement.value_or(0.0), peak.peak_seat_movement);
    if (m.seat_width > 0.0) {
      c.min_unseating_margin =
          std::min(c.min_unseating_margin.value_or(std::numeric_limits<double>::infinity()),
                   m.seat_width - peak.peak_seat_movement);
      c.unseated = c.unseated.value_or(false) || peak.peak_seat_movement >= m.seat_width;
    }
  }
  for (std::size_t k = 0; k < built.drift_monitors.size(); ++k) {
    const builder::DriftMonitor& m = built.drift_monitors[k];
    const double drift = drifts.peaks()[k].peak_drift;
    c.max_drift_ratio = std::max(c.max_drift_ratio.value_or(0.0), drift / m.height);
    if (m.yield_drift)
      c.max_ductility = std::max(c.max_ductility.value_or(0.0), drift / *m.yield_drift);
  }
  c.energy_balance_error = energy.worst_balance_error();
  c.run_time_s = run_time;
}

}  // namespace

RunOutcome run_model(const RunRequest& request) {
  // Everything that can be wrong with the input is found before any output exists.
  const auto loading = std::chrono::steady_clock::now();
  const std::string& model_path = request.model_path;
  LoadedModel loaded = request.record ? load_model_with_record(model_path, *request.record)
                                      : load_model(model_path, request.motion);
  const builder::ModelSpec& spec = loaded.spec;
  builder::BuiltModel& built = loaded.built;
  if (request.max_steps > 0) built.analysis.max_steps = request.max_steps;
  built.analysis.time_limit = request.time_limit;
  std::unique_ptr<assembly::StructuralSystem> system;
  try {
    system = std::make_unique<assembly::StructuralSystem>(built.model);
  } catch (const InputError& error) {
    throw error.in_file(model_path);
  }
  builder::settle_time_step(built.analysis, built.model, *system, model_path);
  auto integrator = builder::make_integrator(built.analysis);
  integrators::TransientAnalysis analysis(*system, *integrator,
                                          builder::make_transient_settings(built.analysis));
  // Without histories nothing is recorded, not just not written.
  auto recorders = request.histories ? make_recorders(built, system->dofs(), system->links())
                                     : std::vector<std::unique_ptr<results::Recorder>>();
  check_histories_fit(recorders, built.analysis, model_path);
  std::vector<Index> normal_rows;
  for (Index k = 0; k < system->links().count(); ++k) normal_rows.push_back(system->links().row(k));
  results::LinkSummaries links(std::move(normal_rows));
  results::EnergyBalance energy(*system);
  const auto& dofs = system->dofs();
  std::vector<std::pair<Index, Index>> drift_equations;
  for (const builder::DriftMonitor& m : built.drift_monitors)
    drift_equations.emplace_back(dofs.equation(m.bottom, 0), dofs.equation(m.top, 0));
  results::DriftMonitors drifts(std::move(drift_equations));
  std::vector<results::JointMonitors::Where> joint_places;
  for (const builder::JointMonitor& m : built.joint_monitors)
    joint_places.push_back({system->links().row(m.link),
                            built.model.links[static_cast<std::size_t>(m.link)].gap,
                            dofs.equation(m.girder, 0), dofs.equation(m.seat, 0)});
  results::JointMonitors joints(std::move(joint_places));

  integrators::State state;
  state.velocity = system->initial_velocity(built.model);
  integrators::TransientStatistics stats;
  RunOutcome outcome;
  std::string& failure = outcome.failure;
  double& failure_time = outcome.failure_time;
  const auto started = std::chrono::steady_clock::now();
  const double setup_time = std::chrono::duration<double>(started - loading).count();
  try {
    if (built.analysis.static_initial_state)
      state.displacement = assembly::static_equilibrium(*system, state.time).displacement;
    stats = analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
      for (auto& recorder : recorders) recorder->record(s);
      links.record(s);
      energy.record(s);
      drifts.record(s);
      joints.record(s);
      // Energy the integration made up: an unstable step or an unresolved stiff contact. The
      // histories up to here are kept; the run stops rather than go on to a NaN.
      const double created = energy.terms().created_fraction();
      if (created > results::kEnergyGrowthLimit)
        throw SolveError(
            s.time, fmt::format("the structure holds {:.1f} % more energy than was put in (of the "
                                "largest energy term; limit {:.0f} %): the integration is "
                                "creating energy, so the time step is too large for the "
                                "integrator or for a stiff link",
                                100.0 * created, 100.0 * results::kEnergyGrowthLimit));
    });
  } catch (const SolveError& error) {
    failure = error.reason();
    failure_time = error.time();
    stats = analysis.statistics();  // up to the failure
  }
  const double run_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  io::Document& summary = outcome.summary;
  summary.set("model", model_path)
      .set("title", spec.title)
      .set("status", failure.empty() ? "completed" : "failed");
  if (!failure.empty()) summary.set("failure_time", failure_time).set("failure", failure);
  summary.set("integrator", integrator->name())
      .set("time_step", built.analysis.time_step)
      .set("duration", built.analysis.duration)
      .set("end_time", failure.empty() ? state.time : failure_time)
      .set("dofs", static_cast<long>(system->size()))
      .set("steps", stats.steps)
      .set("newton_iterations", stats.newton_iterations)
      .set("step_cuts", stats.step_cuts)
      .set("max_unbalanced_force", stats.max_unbalanced_force)
      .set("run_time_s", run_time);
  if (built.analysis.adaptive)
    summary.set("adaptive", io::Document()
                                .set("tolerance", built.analysis.adaptive->tolerance)
                                .set("rejected_steps", stats.rejected_steps)
                                .set("located_contacts", stats.located_contacts)
                                .set("smallest_step", stats.smallest_step)
                                .set("largest_step", stats.largest_step));
  std::vector<io::Document> link_documents;
  for (std::size_t k = 0; k < built.model.links.size(); ++k)
    link_documents.push_back(link_document(built.model.links[k], links.summaries()[k]));
  summary.set("links", link_documents);
  std::vector<io::Document> storey_documents, pier_documents, joint_documents;
  for (std::size_t k = 0; k < built.drift_monitors.size(); ++k) {
    const builder::DriftMonitor& m = built.drift_monitors[k];
    const results::DriftPeak& peak = drifts.peaks()[k];
    io::Document doc;
    doc.set("id", m.id)
        .set(m.kind == builder::DriftKind::pier ? "bridge" : "building", m.group)
        .set("height", m.height)
        .set("peak_drift", peak.peak_drift)
        .set("drift_ratio", peak.peak_drift / m.height)
        .set("time", peak.time);
    if (m.yield_drift) doc.set("ductility", peak.peak_drift / *m.yield_drift);
    (m.kind == builder::DriftKind::pier ? pier_documents : storey_documents).push_back(doc);
  }
  for (std::size_t k = 0; k < built.joint_monitors.size(); ++k) {
    const builder::JointMonitor& m = built.joint_monitors[k];
    const results::JointPeak& peak = joints.peaks()[k];
    io::Document doc;
    doc.set("id", m.id)
        .set("link", built.model.links[static_cast<std::size_t>(m.link)].id)
        .set("peak_opening", peak.peak_opening)
        .set("peak_closing", peak.peak_closing)
        .set("peak_seat_movement", peak.peak_seat_movement);
    if (m.seat_width > 0.0)
      doc.set("seat_width", m.seat_width)
          .set("unseating_margin", m.seat_width - peak.peak_seat_movement)
          .set("unseated", peak.peak_seat_movement >= m.seat_width);
    joint_documents.push_back(doc);
  }
  if (!storey_documents.empty()) summary.set("storeys", storey_documents);
  if (!pier_documents.empty()) summary.set("piers", pier_documents);
  if (!joint_documents.empty()) summary.set("joints", joint_documents);
  const results::EnergyTerms& e = energy.terms();
  io::Document energy_document;
  energy_document.set("input", e.input)
      .set("initial", e.initial)
      .set("kinetic", e.kinetic)
      .set("strain", e.strain)
      .set("damping", e.damping)
      .set("links", e.links)
      .set("balance_error", e.balance_error())
      .set("worst_balance_error", energy.worst_balance_error());
  summary.set("energy", energy_document);
  // Warnings for results an engineer should not trust as they are.
  std::vector<std::string>& warnings = outcome.warnings;
  // A record much longer than the analysis was read whole for nothing; say so, it may be a
  // mistaken duration.
  for (std::size_t k = 0; k < loaded.records.size(); ++k)
    if (loaded.records[k].duration() > 10.0 * built.analysis.duration)
      warnings.push_back(fmt::format(
          "record '{}' lasts {:.4g} s but the analysis stops at {:.4g} s: only its first {:.1f} % "
          "is used (is /analysis/duration what you meant?)",
          loaded.records[k].name, loaded.records[k].duration(), built.analysis.duration,
          100.0 * built.analysis.duration / loaded.records[k].duration()));
  for (std::size_t k = 0; k < built.joint_monitors.size(); ++k)
    if (built.joint_monitors[k].seat_width > 0.0 &&
        joints.peaks()[k].peak_seat_movement >= built.joint_monitors[k].seat_width)
      warnings.push_back(
          fmt::format("joint {}: the girder moved {:.4g} on a seat {:.4g} wide: unseated",
                      built.joint_monitors[k].id, joints.peaks()[k].peak_seat_movement,
                      built.joint_monitors[k].seat_width));
  if (energy.worst_balance_error() > 0.01)
    warnings.push_back(
        fmt::format("energy balance error reached {:.2f} % of the largest energy term: "
                    "a contact or a step was not resolved (reduce the time step)",
                    100.0 * energy.worst_balance_error()));
  summary.set("warnings", [&] {
    std::vector<io::Document> items;
    for (const std::string& w : warnings) items.push_back(io::Document().set("warning", w));
    return items;
  }());

  std::string verification_line;
  if (built.sole_rod_pair && failure.empty()) {
    // The model is one rod pair: compare with the exact solution, as `verify rod-impact` does.
    const auto* link_recorder = recorders.empty() ? nullptr : recorders.front().get();
    if (link_recorder && link_recorder->table().columns.size() >= 3 &&
        dynamic_cast<const results::LinkRecorder*>(link_recorder)) {
      const Table& history = link_recorder->table();
      const verification::RodPairNodes nodes(*built.sole_rod_pair, built, system->dofs());
      verification::RodImpactMetrics metrics =
          verification::rod_pair_metrics(*built.sole_rod_pair, nodes, history.values[0],
                                         history.values[1], history.values[2], state);
      metrics.run_time_s = run_time;
      metrics.steps = stats.steps;
      metrics.newton_iterations = stats.newton_iterations;
      summary.set("verification", verification::to_document(metrics));
      verification_line = fmt::format(
          "  against the exact solution: force_l2_error {:.4f}, duration_error {:+.4f}, "
          "separation_velocity_error {:+.4f}, peak_force_ratio {:.3f}\n",
          metrics.force_l2_error, metrics.duration_error, metrics.separation_velocity_error,
          metrics.peak_force_ratio);
    }
  }

  {
    std::string& report = outcome.report;
    outcome.headline =
        fmt::format("pound run {}: {} DOFs, {} steps, {} Newton iterations, {:.3f} s", model_path,
                    system->size(), stats.steps, stats.newton_iterations, run_time);
    // Contacts and restrainers one line each; structural springs (bearings) in one line.
    int springs = 0;
    double spring_force = 0.0;
    for (std::size_t k = 0; k < built.model.links.size(); ++k) {
      const results::LinkSummary& s = links.summaries()[k];
      const std::string law = system->links().law(static_cast<Index>(k)).name();
      const std::string& id = built.model.links[k].id;
      const links::LinkRole role = built.model.links[k].role();
      if (role == links::LinkRole::spring) {
        ++springs;
        spring_force = std::max({spring_force, s.peak_force, s.peak_tension});
      } else if (role == links::LinkRole::tension) {
        report +=
            fmt::format("  {} {}: taut {} time(s), peak tension {:.6g}, peak opening {:.4g}\n", law,
                        id, s.impacts, s.peak_tension, s.peak_opening);
      } else {
        report += fmt::format(
            "  contact {}: {} impact(s), peak force {:.6g}, peak penetration {:.4g}, impulse "
            "{:.6g}\n",
            id, s.impacts, s.peak_force, s.peak_penetration, s.impulse);
      }
    }
    if (springs > 0)
      report += fmt::format("  {} spring link(s) (bearings, hinges): largest force {:.6g}\n",
                            springs, spring_force);
    for (std::size_t k = 0; k < built.joint_monitors.size(); ++k) {
      const auto& m = built.joint_monitors[k];
      const auto& p = joints.peaks()[k];
      report += fmt::format(
          "  joint {}: opened {:.4g}, closed {:.4g}, moved {:.4g} on its seat{}\n", m.id,
          p.peak_opening, p.peak_closing, p.peak_seat_movement,
          m.seat_width > 0.0 ? fmt::format(" (seat {:.4g}, margin {:.4g})", m.seat_width,
                                           m.seat_width - p.peak_seat_movement)
                             : std::string());
    }
    for (std::size_t k = 0; k < built.drift_monitors.size(); ++k) {
      const auto& m = built.drift_monitors[k];
      const double drift = drifts.peaks()[k].peak_drift;
      report +=
          fmt::format("  {} {}: peak drift {:.4g} ({:.3f} % of {:.4g}){}\n",
                      m.kind == builder::DriftKind::pier ? "pier" : "storey", m.id, drift,
                      100.0 * drift / m.height, m.height,
                      m.yield_drift ? fmt::format(", ductility {:.2f}", drift / *m.yield_drift)
                                    : std::string());
    }
    report += verification_line;
    report += fmt::format(
        "  energy: input {:.6g}, initial {:.6g}, kinetic {:.6g}, strain {:.6g}, "
        "damping {:.6g}, links {:.6g}; balance error {:.2e}\n",
        e.input, e.initial, e.kinetic, e.strain, e.damping, e.links, energy.worst_balance_error());
  }
  for (const auto& recorder : recorders)
    outcome.histories.emplace_back(recorder->file(), recorder->table());
  outcome.setup_s = setup_time;
  summarise_case(loaded, request, links, drifts, joints, energy, stats,
                 failure.empty() ? state.time : failure_time, run_time, outcome);
  return outcome;
}

void write_run_outputs(const std::string& folder, const RunOutcome& outcome) {
  io::create_output_folder(folder);
  for (const auto& [file, table] : outcome.histories)
    io::write_csv_atomic((std::filesystem::path(folder) / file).string(), table);
  io::write_text_atomic((std::filesystem::path(folder) / "summary.json").string(),
                        outcome.summary.dump() + "\n");
}

}  // namespace pound::app
