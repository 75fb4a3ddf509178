#include "io/run_summary_document.hpp"

#include <algorithm>

namespace pound::io {
namespace {

const char* role_name(links::LinkRole role) {
  switch (role) {
    case links::LinkRole::contact:
      return "contact";
    case links::LinkRole::tension:
      return "restrainer";
    case links::LinkRole::spring:
      return "spring";
  }
  return "";
}

// A contact or restrainer in the words of pounding: impacts (or times taut), the peak force in
// compression and in tension, penetration (a contact's: a restrainer's closing is the joint's,
// nothing it does) and opening, impulse, when in contact.
void add_pounding(const results::LinkSummary& s, links::LinkRole role, Document& doc) {
  doc.set("impacts", s.impacts).set("peak_force", s.peak_force).set("peak_tension", s.peak_tension);
  if (role != links::LinkRole::tension) doc.set("peak_penetration", s.peak_penetration);
  doc.set("peak_opening", s.peak_opening).set("impulse", s.impulse).set("work", s.work);
  if (s.first_contact >= 0.0)
    doc.set("first_contact", s.first_contact).set("last_contact", s.last_contact);
}

// A spring (bearing, hinge, storey, damper) in the words of springs: the largest force and
// deformation either way, and where it ended (a residual deformation after yielding).
void add_spring(const results::LinkResult& link, Document& doc) {
  const results::LinkSummary& s = link.summary;
  doc.set("peak_force", std::max(s.peak_force, s.peak_tension))
      .set("peak_deformation", link.peak_deformation())
      .set("residual_deformation", s.final_deformation)
      .set("work", s.work);
}

// A bearing's coupled shear (a hinge's bending across its axis): the resultant over its
// directions; an elliptic one's numbers along each tangent.
Document shear_document(const results::LinkResult& link) {
  const results::ShearSummary& s = *link.summary.shear;
  Document doc;
  doc.set("law", link.shear->law)
      .set("peak_force", s.peak_force)
      .set("peak_deformation", s.peak_deformation)
      .set("residual_deformation", s.final_deformation)
      .set("work", s.work);
  if (!link.shear->circular()) {
    doc.set("peak_deformations",
            std::vector<double>(s.peak_deformations.begin(), s.peak_deformations.end()));
    if (link.shear_yields())
      doc.set("yield_deformations",
              std::vector<double>{link.shear->numbers[0].yield_deformation(),
                                  link.shear->numbers[1].yield_deformation()});
  } else if (link.shear_yields()) {
    doc.set("yield_deformation", link.shear->numbers[0].yield_deformation());
  }
  if (const std::optional<double> ductility = link.shear_ductility())
    doc.set("ductility", *ductility);
  if (link.rotational && link.shear_yields())  // a hinge: theta_p about each tangent
    doc.set("peak_plastic_deformations",
            std::vector<double>{*link.shear_peak_plastic_deformation(0),
                                *link.shear_peak_plastic_deformation(1)});
  if (const std::optional<double> energy = link.shear_hysteretic_energy())
    doc.set("hysteretic_energy", *energy);
  if (link.shear_viscous.work != 0.0) doc.set("damping_energy", link.shear_viscous.work);
  return doc;
}

// A friction link's slide: the resultant over its tangents (one in a plane, two in a contact
// plane), the tangential force's largest, and their work, what friction dissipated with what a
// pendulum's restoring force holds at the end.
Document friction_document(const results::ShearSummary& s, bool in_plane) {
  Document doc;
  doc.set("peak_slide", s.peak_deformation)
      .set("residual_slide", s.final_deformation)
      .set("peak_tangential_force", s.peak_force)
      .set("work", s.work);
  if (in_plane)
    doc.set("peak_slides",
            std::vector<double>(s.peak_deformations.begin(), s.peak_deformations.end()));
  return doc;
}

Document link_document(const results::LinkResult& link) {
  const results::LinkSummary& s = link.summary;
  Document doc;
  doc.set("id", link.id).set("law", link.law).set("role", role_name(link.role));
  // A hinge: its forces are moments, its deformations rotations.
  if (link.rotational) doc.set("rotational", true);
  if (link.seated) doc.set("seated", true);  // a bearing under the weight, no pounding contact
  if (link.role == links::LinkRole::spring)
    add_spring(link, doc);
  else
    add_pounding(s, link.role, doc);
  if (link.passive_engagements) doc.set("created_energy", s.created_energy());
  // A yielded restrainer's plastic elongation, the backfill soil's permanent deformation.
  if (link.permanent_deformation > 0.0)
    doc.set("permanent_deformation", link.permanent_deformation);
  if (link.yield_deformation && link.role == links::LinkRole::tension) {  // beyond its slack
    doc.set("yield_elongation", *link.yield_deformation)
        .set("peak_elongation", link.peak_demand())
        .set("peak_plastic_elongation", *link.peak_plastic_deformation());
    if (const std::optional<double> ductility = link.ductility()) doc.set("ductility", *ductility);
    if (const std::optional<double> energy = link.hysteretic_energy())
      doc.set("hysteretic_energy", *energy);
  } else if (link.yield_deformation) {  // a yielding law: its demand and what it dissipated
    doc.set("yield_deformation", *link.yield_deformation)
        .set("peak_deformation", link.peak_deformation())
        .set("peak_plastic_deformation", *link.peak_plastic_deformation())
        .set("residual_deformation", s.final_deformation);
    if (const std::optional<double> ductility = link.ductility()) doc.set("ductility", *ductility);
    if (const std::optional<double> energy = link.hysteretic_energy())
      doc.set("hysteretic_energy", *energy);
  }
  // stiffness-proportional damping added to the link ("rayleigh"): its part of `work`
  if (link.viscous.work != 0.0) doc.set("damping_energy", link.viscous.work);
  if (link.shear && s.shear) doc.set("shear", shear_document(link));
  // Along each tangent only where the slide left the first: a plane scene written in 3-D gives
  // the plane's numbers (tests/app/plane_scene_in_space_test.cpp).
  if (link.friction && s.shear)
    doc.set("friction", friction_document(*s.shear, s.shear->peak_deformations[1] > 0.0));
  return doc;
}

Document drift_document(const results::DriftResult& drift) {
  const builder::DriftMonitor& m = drift.monitor;
  Document doc;
  doc.set("id", m.id)
      .set(m.kind == builder::DriftKind::pier ? "bridge" : "building", m.group)
      .set("height", m.height);
  // 3-D monitors that say so: along y, or watching a floor's corners (z up).
  if (m.axis)
    doc.set("axis", std::vector<double>(m.axis->begin(), m.axis->end()));
  else if (m.direction != 0 || !m.corners.empty())
    doc.set("direction", m.direction == 0 ? "x" : "y");
  doc.set("peak_drift", drift.peak.peak_drift)
      .set("drift_ratio", drift.ratio())
      .set("time", drift.peak.time);
  doc.set("residual_drift", drift.peak.residual_drift)
      .set("residual_drift_ratio", drift.residual_ratio())
      .set("end_swing", drift.peak.end_swing);
  if (const std::optional<double> acceleration = drift.top_acceleration())
    doc.set("peak_absolute_acceleration", *acceleration)
        .set("acceleration_time", drift.peak.acceleration_time);
  else
    doc.set("top_without_mass", true);
  if (const std::optional<double> ductility = drift.ductility()) doc.set("ductility", *ductility);
  if (drift.resultant_ductility) doc.set("resultant_ductility", *drift.resultant_ductility);
  if (const std::optional<double> demand = drift.elastic_demand_ratio())
    doc.set("elastic_demand_ratio", *demand);
  if (drift.curvature_ductility) doc.set("curvature_ductility", *drift.curvature_ductility);
  if (drift.peak_shear) doc.set("peak_shear", *drift.peak_shear);
  if (drift.peak_base_moment) doc.set("peak_base_moment", *drift.peak_base_moment);
  if (const std::optional<double> corner_ratio = drift.corner_ratio()) {
    doc.set("peak_corner_drift", drift.peak.peak_corner_drift)
        .set("corner", static_cast<int>(drift.peak.corner))
        .set("corner_drift_ratio", *corner_ratio)
        .set("corner_time", drift.peak.corner_time);
    if (const std::optional<double> amplification = drift.corner_amplification())
      doc.set("corner_amplification", *amplification);
    doc.set("peak_twist", drift.peak.peak_twist).set("twist_time", drift.peak.twist_time);
  }
  return doc;
}

Document joint_document(const results::JointResult& joint) {
  Document doc;
  doc.set("id", joint.monitor.id)
      .set("link", joint.link)
      .set("peak_opening", joint.peak.peak_opening)
      .set("peak_closing", joint.peak.peak_closing)
      .set("peak_seat_movement", joint.peak.peak_seat_movement)
      .set("peak_unseating_movement", joint.peak.peak_unseating_movement)
      .set("residual_opening", joint.peak.residual_opening)
      .set("peak_girder_acceleration", joint.peak.peak_girder_acceleration);
  if (joint.in_space) doc.set("peak_plan_rotation", joint.peak.peak_plan_rotation);
  if (const std::optional<double> margin = joint.margin())
    doc.set("seat_width", joint.monitor.seat_width)
        .set("unseating_margin", *margin)
        .set("unseated", joint.unseated());
  return doc;
}

Document energy_document(const results::RunSummary& run) {
  const results::EnergyTerms& e = run.energy;
  Document energy = Document()
                        .set("input", e.input)
                        .set("initial", e.initial)
                        .set("kinetic", e.kinetic)
                        .set("strain", e.strain)
                        .set("damping", e.damping)
                        .set("links", e.links);
  if (const std::optional<double> hysteretic = run.hysteretic_energy())
    energy.set("links_hysteretic", *hysteretic);  // the yielding links' part of `links`
  energy.set("contact_created", run.contact_created_energy())
      .set("contact_created_fraction", run.contact_created_fraction());
  return energy.set("balance_error", e.balance_error())
      .set("worst_balance_error", run.worst_balance_error);
}

// The run's header: how it ended, with what, in how many steps.
void set_status(const results::RunSummary& run, Document& summary) {
  summary.set("status", run.status.completed() ? "completed" : "failed");
  if (!run.status.completed())
    summary.set("failure_time", run.status.end_time).set("failure", run.status.failure);
  const integrators::TransientStatistics& stats = run.statistics;
  summary.set("integrator", run.integrator)
      .set("time_step", run.time_step)
      .set("duration", run.duration)
      .set("end_time", run.status.end_time)
      .set("dofs", static_cast<long>(run.dofs))
      .set("steps", stats.steps)
      .set("newton_iterations", stats.newton_iterations)
      .set("step_cuts", stats.step_cuts)
      .set("max_unbalanced_force", stats.max_unbalanced_force)
      .set("run_time_s", run.run_time_s);
  if (const results::StepChoice& step = run.step_choice; step.stable_time_step) {
    summary.set("stable_time_step", *step.stable_time_step).set("time_step_rule", step.rule);
    if (step.defaulted) summary.set("time_step_defaulted", true);
  }
  if (run.adaptive)
    summary.set("adaptive", Document()
                                .set("tolerance", run.adaptive->tolerance)
                                .set("rejected_steps", stats.rejected_steps)
                                .set("located_contacts", stats.located_contacts)
                                .set("smallest_step", stats.smallest_step)
                                .set("largest_step", stats.largest_step));
}

}  // namespace

Document to_document(const results::RunSummary& run, const std::string& model_path,
                     const std::string& title) {
  Document summary;
  summary.set("model", model_path).set("title", title);
  set_status(run, summary);
  summary.set("links", documents(run.links, link_document));
  std::vector<Document> storeys, piers;
  for (const results::DriftResult& drift : run.drifts)
    (drift.monitor.kind == builder::DriftKind::pier ? piers : storeys)
        .push_back(drift_document(drift));
  if (!storeys.empty()) summary.set("storeys", storeys);
  if (!piers.empty()) summary.set("piers", piers);
  if (!run.joints.empty()) summary.set("joints", documents(run.joints, joint_document));
  summary.set("energy", energy_document(run));
  summary.set("warnings", warning_documents(run.warnings));
  return summary;
}

}  // namespace pound::io
