#include "app/run_report.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace pound::app {

std::string with_unit(double value, const std::string& unit, int digits) {
  return fmt::format("{:.{}g}{}{}", value, digits, unit.empty() ? "" : " ", unit);
}

namespace {

// Force x time: "N*s", and "kg*cm/s" for a force written out as "kg*cm/s^2" (not "kg*cm/s^2*s").
std::string impulse_unit(const std::string& force, const std::string& time) {
  if (force.empty()) return "";
  const std::string per_time_squared = "/" + time + "^2";
  if (force.ends_with(per_time_squared))
    return force.substr(0, force.size() - per_time_squared.size()) + "/" + time;
  return force + "*" + time;
}

// The units of what the report prints: energies in force x length (the moment's unit) and
// impulses in force x time.
struct ReportUnits {
  explicit ReportUnits(const UnitNames& names)
      : time(names.of(Dimension::time)),
        length(names.of(Dimension::length)),
        acceleration(names.of(Dimension::acceleration)),
        force(names.of(Dimension::force)),
        moment(names.of(Dimension::moment)),
        angle(names.of(Dimension::angle)),
        impulse(impulse_unit(force, time)) {}
  std::string time, length, acceleration, force, moment, angle, impulse;
  const std::string& energy() const { return moment; }
  // A link's deformation: a hinge's is a rotation.
  const std::string& deformation(bool rotational) const { return rotational ? angle : length; }
};

// A ratio to a yield value, to two decimals; in significant figures past 1e4, where an absurd
// yield value (a yield moment of 1e-6) made it hundreds of digits.
std::string ratio(double value) {
  return std::abs(value) < 1e4 ? fmt::format("{:.2f}", value) : fmt::format("{:.3g}", value);
}

// A spring or hinge that yielded: its peak and residual deformation, and what it dissipated.
std::string yielded_line(const results::LinkResult& link, const ReportUnits& units) {
  const std::optional<double> ductility = link.ductility();
  const std::string& deformation = units.deformation(link.rotational);
  return fmt::format(
      "  {} {} yielded: peak {} {}{}, residual {}, hysteretic energy {}{}\n", link.law, link.id,
      link.rotational ? "rotation" : "deformation", with_unit(link.peak_deformation(), deformation),
      ductility
          ? fmt::format(" ({} x yield)", ratio(*ductility))
          : fmt::format(" (plastic {})",
                        with_unit(link.peak_plastic_deformation().value_or(0.0), deformation)),
      with_unit(link.summary.final_deformation, deformation),
      with_unit(link.hysteretic_energy().value_or(0.0), units.energy(), 6),
      link.viscous.work != 0.0
          ? fmt::format(", damping energy {}", with_unit(link.viscous.work, units.energy(), 6))
          : std::string());
}

// A bearing whose coupled shear yielded: the resultant's peak (and ductility) and residual, and
// what it dissipated; a biaxial hinge's bending: its plastic rotation about each tangent.
std::string shear_line(const results::LinkResult& link, const ReportUnits& units) {
  const results::ShearSummary& s = *link.summary.shear;
  const std::string& deformation = units.deformation(link.rotational);
  const std::string demand =
      link.rotational
          ? fmt::format(
                "peak rotation {} (plastic {} about t_1, {} about t_2)",
                with_unit(s.peak_deformation, deformation),
                with_unit(link.shear_peak_plastic_deformation(0).value_or(0.0), deformation),
                with_unit(link.shear_peak_plastic_deformation(1).value_or(0.0), deformation))
          : fmt::format("peak deformation {} ({} x yield)",
                        with_unit(s.peak_deformation, deformation),
                        ratio(link.shear_ductility().value_or(0.0)));
  return fmt::format("  {} {} yielded in {}: {}, residual {}, hysteretic energy {}\n",
                     link.shear->law, link.id, link.rotational ? "bending" : "shear", demand,
                     with_unit(s.final_deformation, deformation),
                     with_unit(link.shear_hysteretic_energy().value_or(0.0), units.energy(), 6));
}

// Contacts and restrainers one line each; yielded springs and hinges one line each; the other
// structural springs (bearings) in one line, with the largest force of the translational ones and
// the largest moment of the hinges apart.
std::string link_lines(const results::RunSummary& run, const ReportUnits& units) {
  std::string text;
  int springs = 0, hinges = 0;
  double spring_force = 0.0, hinge_moment = 0.0;
  for (const results::LinkResult& link : run.links) {
    const results::LinkSummary& s = link.summary;
    switch (link.role) {
      case links::LinkRole::spring: {
        ++springs;
        hinges += link.rotational;
        double& largest = link.rotational ? hinge_moment : spring_force;
        largest = std::max({largest, s.peak_force, s.peak_tension});
        if (link.yield_deformation && link.peak_deformation() > *link.yield_deformation)
          text += yielded_line(link, units);
        if (link.shear_yields() && link.summary.shear->peak_ductility > 1.0)
          text += shear_line(link, units);
        if (link.summary.shear) largest = std::max(largest, link.summary.shear->peak_force);
        break;
      }
      case links::LinkRole::tension: {
        const std::optional<double> ductility = link.ductility();
        text += fmt::format(
            "  {} {}: taut {} time(s), peak tension {}, peak opening {}{}\n", link.law, link.id,
            s.impacts, with_unit(s.peak_tension, units.force, 6),
            with_unit(s.peak_opening, units.length),
            link.permanent_deformation > 0.0
                ? fmt::format(
                      ", yielded: permanent elongation {}{}",
                      with_unit(link.permanent_deformation, units.length),
                      ductility ? fmt::format(" (ductility {})", ratio(*ductility)) : std::string())
                : std::string());
        break;
      }
      case links::LinkRole::contact:
        if (link.seated)
          text += fmt::format("  bearing {}: seated under the weight, peak normal force {}, {}\n",
                              link.id, with_unit(s.peak_force, units.force, 6),
                              s.impacts > 1
                                  ? fmt::format("lifted off and landed {} time(s)", s.impacts - 1)
                                  : std::string("never lifted off"));
        else
          text += fmt::format(
              "  contact {}: {} impact(s), peak force {}, peak penetration {}, impulse {}{}\n",
              link.id, s.impacts, with_unit(s.peak_force, units.force, 6),
              with_unit(s.peak_penetration, units.length), with_unit(s.impulse, units.impulse, 6),
              // Between lumped masses a hard contact's impact is an impulse within one step.
              link.hard_contact()
                  ? " (hard contact: an impact of lumped masses lasts about a step, so its peak "
                    "force is that impact's impulse / dt)"
              : link.permanent_deformation > 0.0
                  ? fmt::format(", permanent deformation {}",
                                with_unit(link.permanent_deformation, units.length))
                  : std::string());
        if (link.friction && s.shear)
          text += fmt::format(
              "    friction: peak slide {}, residual slide {}, peak tangential force {}, work {}\n",
              with_unit(s.shear->peak_deformation, units.length),
              with_unit(s.shear->final_deformation, units.length),
              with_unit(s.shear->peak_force, units.force, 6),
              with_unit(s.shear->work, units.energy(), 6));
        break;
    }
  }
  if (springs > hinges)
    text += fmt::format("  {} spring link(s) (bearings, springs, dampers): largest force {}\n",
                        springs - hinges, with_unit(spring_force, units.force, 6));
  if (hinges > 0)
    text +=
        fmt::format("  {} rotational spring(s) (hinges, bearings in twist): largest moment {}\n",
                    hinges, with_unit(hinge_moment, units.moment, 6));
  return text;
}

std::string joint_line(const results::JointResult& joint, const ReportUnits& units) {
  const std::optional<double> margin = joint.margin();
  return fmt::format(
      "  joint {}: opened {}, closed {}, moved {} on its seat{}{}, girder end acceleration {} "
      "(absolute)\n",
      joint.monitor.id, with_unit(joint.peak.peak_opening, units.length),
      with_unit(joint.peak.peak_closing, units.length),
      with_unit(joint.peak.peak_seat_movement, units.length),
      margin
          ? fmt::format(" (seat {}, margin {})", with_unit(joint.monitor.seat_width, units.length),
                        with_unit(*margin, units.length))
          : std::string(),
      joint.in_space ? fmt::format(", turned {} in plan",
                                   with_unit(joint.peak.peak_plan_rotation, units.angle))
                     : std::string(),
      with_unit(joint.peak.peak_girder_acceleration, units.acceleration));
}

// A residual read while the storey still swings (by more than a tenth of the residual and a
// thousandth of the peak) is one point of that swing, not where it settles: say so.
std::string still_swinging(const results::DriftPeak& peak, const ReportUnits& units) {
  if (!(peak.end_swing > 0.1 * std::abs(peak.residual_drift) &&
        peak.end_swing > 1e-3 * peak.peak_drift))
    return {};
  return fmt::format(" (still swinging +-{} at the end: run past the record to let it settle)",
                     with_unit(peak.end_swing, units.length));
}

std::string drift_line(const results::DriftResult& drift, const ReportUnits& units) {
  const builder::DriftMonitor& m = drift.monitor;
  const bool pier = m.kind == builder::DriftKind::pier;
  const std::optional<double> ductility = drift.ductility();
  const std::optional<double> demand = drift.elastic_demand_ratio();
  std::string text = fmt::format(
      "  {} {}: peak drift {} ({:.3f} % of {}), residual {}{}{}{}, {}{}{}{}\n",
      pier ? "pier" : "storey", m.id, with_unit(drift.peak.peak_drift, units.length),
      100.0 * drift.peak.peak_drift / m.height, with_unit(m.height, units.length),
      with_unit(drift.peak.residual_drift, units.length), still_swinging(drift.peak, units),
      ductility ? fmt::format(", ductility {}{}", ratio(*ductility),
                              drift.resultant_ductility
                                  ? fmt::format(" ({} resultant of both directions)",
                                                ratio(*drift.resultant_ductility))
                                  : std::string())
      : demand ? fmt::format(", elastic, {} x its yield drift", ratio(*demand))
                : std::string(),
      drift.curvature_ductility
          ? fmt::format(", curvature ductility {}", ratio(*drift.curvature_ductility))
          : std::string(),
      pier ? "top" : "floor",
      drift.top_acceleration()
          ? fmt::format(" acceleration {} (absolute)",
                        with_unit(*drift.top_acceleration(), units.acceleration))
          : std::string(" without mass, its acceleration not reported"),
      drift.peak_shear ? fmt::format(", {} {}", pier ? "base shear" : "shear",
                                     with_unit(*drift.peak_shear, units.force))
                       : std::string(),
      drift.peak_base_moment
          ? fmt::format(", base moment {}", with_unit(*drift.peak_base_moment, units.moment))
          : std::string());
  if (const std::optional<double> corner_ratio = drift.corner_ratio())
    text +=
        fmt::format("    at its corners: peak drift {} ({:.3f} %, corner {}{}), twist {}\n",
                    with_unit(drift.peak.peak_corner_drift, units.length), 100.0 * *corner_ratio,
                    drift.peak.corner,
                    drift.corner_amplification()
                        ? fmt::format(", {} x the centre's", ratio(*drift.corner_amplification()))
                        : std::string(),
                    with_unit(drift.peak.peak_twist, units.angle));
  return text;
}

std::string monitor_lines(const results::RunSummary& run, const ReportUnits& units) {
  std::string text;
  for (const results::JointResult& joint : run.joints) text += joint_line(joint, units);
  for (const results::DriftResult& drift : run.drifts) text += drift_line(drift, units);
  return text;
}

}  // namespace

std::string run_headline(const std::string& model_path, const results::RunSummary& run) {
  return fmt::format("pound run {}: {} DOFs, {} steps, {} Newton iterations, solved in {:.3f} s",
                     model_path, run.dofs, run.statistics.steps, run.statistics.newton_iterations,
                     run.run_time_s);
}

std::string run_report(const results::RunSummary& run, const UnitNames& names) {
  const ReportUnits units(names);
  return step_line(run, names) + link_lines(run, units) + monitor_lines(run, units);
}

std::string automatic_step_words(bool defaulted) {
  return defaulted ? "no \"time_step\" given, so \"auto\"" : "\"time_step\": \"auto\"";
}

std::string step_line(const results::RunSummary& run, const UnitNames& names) {
  const std::string& time = names.of(Dimension::time);
  const results::StepChoice& step = run.step_choice;
  if (!step.automatic || !step.stable_time_step) return {};
  const std::string rule = automatic_step_words(step.defaulted);
  if (step.record_step)
    return fmt::format(
        "  time step {}: the record's step, below {:g} x the stable step {} of {} ({})\n",
        with_unit(run.time_step, time), step.safety_factor, with_unit(*step.stable_time_step, time),
        run.integrator, rule);
  return fmt::format("  time step {}: {:g} x the stable step {} of {} ({})\n",
                     with_unit(run.time_step, time), step.safety_factor,
                     with_unit(*step.stable_time_step, time), run.integrator, rule);
}

std::string energy_line(const results::RunSummary& run, const UnitNames& names) {
  const results::EnergyTerms& e = run.energy;
  const std::optional<double> hysteretic = run.hysteretic_energy();
  const std::string& unit = names.of(Dimension::moment);  // force x length
  return fmt::format(
      "  energy{}: input {:.6g}, initial {:.6g}, kinetic {:.6g}, strain {:.6g}, damping {:.6g}, "
      "links {:.6g}{}; balance error {:.2e}; created by contacts {:.3g} ({:.2f} % of the input)\n",
      unit.empty() ? "" : " [" + unit + "]", e.input, e.initial, e.kinetic, e.strain, e.damping,
      e.links, hysteretic ? fmt::format(" (of which hysteretic {:.6g})", *hysteretic) : "",
      run.worst_balance_error, run.contact_created_energy(),
      100.0 * run.contact_created_fraction());
}

}  // namespace pound::app
