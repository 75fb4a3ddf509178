#include "app/run_report.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace pound::app {
namespace {

// A spring or hinge that yielded: its peak and residual deformation, and what it dissipated.
std::string yielded_line(const results::LinkResult& link) {
  const std::optional<double> ductility = link.ductility();
  return fmt::format(
      "  {} {} yielded: peak {} {:.4g}{}, residual {:.4g}, hysteretic energy {:.6g}{}\n", link.law,
      link.id, link.rotational ? "rotation" : "deformation", link.peak_deformation(),
      ductility ? fmt::format(" ({:.2f} x yield)", *ductility)
                : fmt::format(" (plastic {:.4g})", link.peak_plastic_deformation().value_or(0.0)),
      link.summary.final_deformation, link.hysteretic_energy().value_or(0.0),
      link.viscous.work != 0.0 ? fmt::format(", damping energy {:.6g}", link.viscous.work)
                               : std::string());
}

// A bearing whose coupled shear yielded: the resultant's peak (and ductility) and residual, and
// what it dissipated; a biaxial hinge's bending: its plastic rotation about each tangent.
std::string shear_line(const results::LinkResult& link) {
  const results::ShearSummary& s = *link.summary.shear;
  const std::string demand =
      link.rotational
          ? fmt::format("peak rotation {:.4g} (plastic {:.4g} about t_1, {:.4g} about t_2)",
                        s.peak_deformation, link.shear_peak_plastic_deformation(0).value_or(0.0),
                        link.shear_peak_plastic_deformation(1).value_or(0.0))
          : fmt::format("peak deformation {:.4g} ({:.2f} x yield)", s.peak_deformation,
                        link.shear_ductility().value_or(0.0));
  return fmt::format("  {} {} yielded in {}: {}, residual {:.4g}, hysteretic energy {:.6g}\n",
                     link.shear->law, link.id, link.rotational ? "bending" : "shear", demand,
                     s.final_deformation, link.shear_hysteretic_energy().value_or(0.0));
}

// Contacts and restrainers one line each; yielded springs and hinges one line each; the other
// structural springs (bearings) in one line.
std::string link_lines(const results::RunSummary& run) {
  std::string text;
  int springs = 0;
  double spring_force = 0.0;
  for (const results::LinkResult& link : run.links) {
    const results::LinkSummary& s = link.summary;
    switch (link.role) {
      case links::LinkRole::spring:
        ++springs;
        spring_force = std::max({spring_force, s.peak_force, s.peak_tension});
        if (link.yield_deformation && link.peak_deformation() > *link.yield_deformation)
          text += yielded_line(link);
        if (link.shear_yields() && link.summary.shear->peak_ductility > 1.0)
          text += shear_line(link);
        if (link.summary.shear)
          spring_force = std::max(spring_force, link.summary.shear->peak_force);
        break;
      case links::LinkRole::tension:
        text += fmt::format("  {} {}: taut {} time(s), peak tension {:.6g}, peak opening {:.4g}\n",
                            link.law, link.id, s.impacts, s.peak_tension, s.peak_opening);
        break;
      case links::LinkRole::contact:
        text += fmt::format(
            "  contact {}: {} impact(s), peak force {:.6g}, peak penetration {:.4g}, impulse "
            "{:.6g}{}\n",
            link.id, s.impacts, s.peak_force, s.peak_penetration, s.impulse,
            // Between lumped masses a hard contact's impact is an impulse within one step.
            link.law == "hard_contact"
                ? " (hard contact: an impact of lumped masses lasts about a step, so its peak "
                  "force is that impact's impulse / dt)"
                : "");
        break;
    }
  }
  if (springs > 0)
    text += fmt::format("  {} spring link(s) (bearings, hinges, dampers): largest force {:.6g}\n",
                        springs, spring_force);
  return text;
}

std::string monitor_lines(const results::RunSummary& run) {
  std::string text;
  for (const results::JointResult& joint : run.joints) {
    const std::optional<double> margin = joint.margin();
    text += fmt::format(
        "  joint {}: opened {:.4g}, closed {:.4g}, moved {:.4g} on its seat{}{}, girder end "
        "acceleration {:.4g} (absolute)\n",
        joint.monitor.id, joint.peak.peak_opening, joint.peak.peak_closing,
        joint.peak.peak_seat_movement,
        margin ? fmt::format(" (seat {:.4g}, margin {:.4g})", joint.monitor.seat_width, *margin)
               : std::string(),
        joint.in_space ? fmt::format(", turned {:.4g} rad in plan", joint.peak.peak_plan_rotation)
                       : std::string(),
        joint.peak.peak_girder_acceleration);
  }
  for (const results::DriftResult& drift : run.drifts) {
    const builder::DriftMonitor& m = drift.monitor;
    const std::optional<double> ductility = drift.ductility();
    const std::optional<double> demand = drift.elastic_demand_ratio();
    text += fmt::format(
        "  {} {}: peak drift {:.4g} ({:.3f} % of {:.4g}), residual {:.4g}{}{}, {} acceleration "
        "{:.4g} (absolute){}{}\n",
        m.kind == builder::DriftKind::pier ? "pier" : "storey", m.id, drift.peak.peak_drift,
        100.0 * drift.peak.peak_drift / m.height, m.height, drift.peak.residual_drift,
        ductility ? fmt::format(", ductility {:.2f}", *ductility)
        : demand  ? fmt::format(", elastic, {:.2f} x its yield drift", *demand)
                  : std::string(),
        drift.curvature_ductility
            ? fmt::format(", curvature ductility {:.2f}", *drift.curvature_ductility)
            : std::string(),
        m.kind == builder::DriftKind::pier ? "top" : "floor", drift.peak.peak_acceleration,
        drift.peak_shear ? fmt::format(", {} {:.4g}",
                                       m.kind == builder::DriftKind::pier ? "base shear" : "shear",
                                       *drift.peak_shear)
                         : std::string(),
        drift.peak_base_moment ? fmt::format(", base moment {:.4g}", *drift.peak_base_moment)
                               : std::string());
    if (const std::optional<double> corner_ratio = drift.corner_ratio())
      text += fmt::format(
          "    at its corners: peak drift {:.4g} ({:.3f} %, corner {}{}), twist {:.4g} rad\n",
          drift.peak.peak_corner_drift, 100.0 * *corner_ratio, drift.peak.corner,
          drift.corner_amplification()
              ? fmt::format(", {:.2f} x the centre's", *drift.corner_amplification())
              : std::string(),
          drift.peak.peak_twist);
  }
  return text;
}

}  // namespace

std::string run_headline(const std::string& model_path, const results::RunSummary& run) {
  return fmt::format("pound run {}: {} DOFs, {} steps, {} Newton iterations, {:.3f} s", model_path,
                     run.dofs, run.statistics.steps, run.statistics.newton_iterations,
                     run.run_time_s);
}

std::string run_report(const results::RunSummary& run) {
  return step_line(run) + link_lines(run) + monitor_lines(run);
}

std::string step_line(const results::RunSummary& run) {
  const results::StepChoice& step = run.step_choice;
  if (!step.automatic || !step.stable_time_step) return {};
  const std::string rule =
      step.defaulted ? "no \"time_step\" given, so \"auto\"" : "\"time_step\": \"auto\"";
  if (step.record_step)
    return fmt::format(
        "  time step {:.4g}: the record's step, below {:g} x the stable step {:.4g} of {} ({})\n",
        run.time_step, step.safety_factor, *step.stable_time_step, run.integrator, rule);
  return fmt::format("  time step {:.4g}: {:g} x the stable step {:.4g} of {} ({})\n",
                     run.time_step, step.safety_factor, *step.stable_time_step, run.integrator,
                     rule);
}

std::string energy_line(const results::RunSummary& run) {
  const results::EnergyTerms& e = run.energy;
  const std::optional<double> hysteretic = run.hysteretic_energy();
  return fmt::format(
      "  energy: input {:.6g}, initial {:.6g}, kinetic {:.6g}, strain {:.6g}, "
      "damping {:.6g}, links {:.6g}{}; balance error {:.2e}; created by contacts {:.3g} "
      "({:.2f} % of the input)\n",
      e.input, e.initial, e.kinetic, e.strain, e.damping, e.links,
      hysteretic ? fmt::format(" (of which hysteretic {:.6g})", *hysteretic) : "",
      run.worst_balance_error, run.contact_created_energy(),
      100.0 * run.contact_created_fraction());
}

}  // namespace pound::app
