#include "verification/model_check.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "assembly/modal_analysis.hpp"
#include "integrators/central_difference.hpp"
#include "links/coulomb_friction.hpp"
#include "links/restitution.hpp"
#include "model/ground_motion.hpp"
#include "results/run_summary.hpp"
#include "verification/contact_energy_probe.hpp"

namespace pound::verification {
namespace {

// Whether the elements that meet the node carry a good part of its mass (a tenth of its own
// point mass, or any without one): the node is a point of a meshed body (a rod, a continuum), not
// a lumped mass on piers or storeys whose own mass is next to nothing beside it (30 kg of pier
// trusses under a 200 t girder made the girders' contact "meshed" and warned of its k-ratio).
bool meshed_at(const model::Model& model, Index node) {
  double element_mass = 0.0, point_mass = 0.0;
  for (const auto& element : model.elements) {
    const auto& nodes = element->nodes();
    if (std::find(nodes.begin(), nodes.end(), node) == nodes.end()) continue;
    const model::ElementMass mass = element->mass();
    // Its largest entry: its share at a node along one direction.
    element_mass += mass.is_consistent() ? mass.consistent.diagonal().cwiseAbs().maxCoeff()
                                         : mass.lumped.maxCoeff();
  }
  for (const model::NodalMass& m : model.masses)
    if (m.node == node) point_mass += m.mass;
  return element_mass > 0.1 * point_mass && element_mass > 0.0;
}

// An extended penalty's mass alpha2 between lumped masses: Suzuki & Toi's automatic alpha2 =
// alpha0 (m1 + m2) / (k1 + k2) matches the element masses of meshed bodies, but between girders
// on soft bearings it is 1e3-1e5 times the girders' (4e8 kg on two 400 t girders): the contact
// then carries that much fictitious mass, penetrates 0.1 m, and Newton fails at a release. Past
// ten times the end masses' (a contact lasting 3.3 times as long) it is warned of.
void warn_penalty_mass(const model::Link& link, const links::LinkLaw& law,
                       const assembly::StructuralSystem& system,
                       std::vector<std::string>& warnings) {
  const double alpha2 = law.clone()->set_trial({1e-9, 1e-9, 0.0}).mass;
  const double m_eff = system.link_context(link).effective_mass();
  if (!(alpha2 > 10.0 * m_eff) || !(m_eff > 0.0)) return;
  warnings.push_back(fmt::format(
      "link {}: its extended penalty's mass alpha2 = {:.4g} is {:.3g} times its end masses' "
      "effective mass {:.4g}: between lumped masses the contact carries that much mass of its own "
      "(the automatic alpha2 = alpha0 (m1 + m2) / (k1 + k2) is meant for meshed bodies); give "
      "alpha2 of the end masses' order or less (0: a penalty spring and its dashpot), or use "
      "kelvin_voigt "
      "or hertz_damp",
      link.id, alpha2, alpha2 / m_eff, m_eff));
}

// Kawashima's advice on a penalty spring's stiffness against the elements next to it. A spring
// far stiffer than the elements of meshed bodies rings inside their contact; between lumped
// masses held by massless piers or storeys (`meshed` false) that ratio is the contact's against
// the structure, large by design (the contact is the two masses on the link). A spring far
// softer lets the bodies pass through each other either way.
void warn_k_ratio(const LinkCheck& c, bool meshed, std::vector<std::string>& warnings) {
  const double ratio = c.stiffness / c.adjacent;
  if (ratio > 100.0 && meshed)
    warnings.push_back(
        fmt::format("link {}: k-ratio {:.3g}: a link this stiff against its neighbours "
                    "separates and recontacts inside the true contact with peaks many "
                    "times the exact force (Kawashima); use k-ratio ~1 or the extended "
                    "penalty",
                    c.id, ratio));
  if (ratio < 0.1)
    warnings.push_back(
        fmt::format("link {}: k-ratio {:.3g}: a link this soft lets the bodies "
                    "overlap and holds contact far too long (Kawashima)",
                    c.id, ratio));
}

// Whether the time step resolves the contact: Kawashima asks for 20 steps per contact. An
// adaptive run shortens its steps where a contact needs them, down to its shortest step.
void warn_contact_steps(const LinkCheck& c, const builder::AnalysisSpec& analysis,
                        std::vector<std::string>& warnings) {
  if (c.contact_duration == 0.0 || !(analysis.time_step > 0.0)) return;
  const std::string assumed =
      c.approach_velocity > 0.0
          ? fmt::format(
                " (a Hertz-type contact at an approach velocity of {:.3g}: twice the peak "
                "ground velocity or the initial closing velocity; faster impacts are shorter)",
                c.approach_velocity)
          : "";
  const double step = analysis.shortest_step();
  const char* which = analysis.adaptive         ? "the shortest adaptive step"
                      : analysis.time_step_auto ? "the \"auto\" time step"
                                                : "the time step";
  // "auto" is a fraction of the stable step, which a stiff contact itself sets at about 2 / omega
  // of the contact: half its duration pi / omega. Stable, yet the impact spans two steps.
  const std::string remedy =
      analysis.time_step_auto
          ? fmt::format(" (give /analysis/time_step as a number, at most {:.4g})",
                        c.contact_duration / 20.0)
          : "";
  if (step > 0.5 * c.contact_duration)
    warnings.push_back(
        fmt::format("link {}: {} {:.4g} is more than half the contact duration {:.4g}{}: the "
                    "impact is not resolved and the result is meaningless{}",
                    c.id, which, step, c.contact_duration, assumed, remedy));
  else if (step > c.contact_duration / 20.0)
    warnings.push_back(
        fmt::format("link {}: {} {:.4g} gives fewer than 20 steps per contact of {:.4g}{}; "
                    "Kawashima asks dt <= T_contact / 20{}",
                    c.id, which, step, c.contact_duration, assumed, remedy));
}

// k_h of a law that is F = k_h delta^1.5 at rest (Hertz, Hertz-damp, Jankowski), probed on a
// copy at two depths; nothing for any other law.
std::optional<double> hertz_stiffness(const links::LinkLaw& law) {
  constexpr double kDepth = 1e-4;
  const double shallow = law.clone()->set_trial({kDepth, 0.0, 0.0}).force;
  const double deep = law.clone()->set_trial({4.0 * kDepth, 0.0, 0.0}).force;
  if (!(shallow > 0.0) || std::abs(deep / shallow / 8.0 - 1.0) > 1e-9) return std::nullopt;
  return shallow / std::pow(kDepth, 1.5);
}

// A Hertz-type contact's (F = k_h delta^1.5) elastic impact of its end masses at
// `approach_velocity` (links::hertz_impact); none for any other law, or without the masses or the
// velocity to take.
std::optional<links::HertzImpact> hertz_impact_of(const model::Link& link,
                                                  const links::LinkLaw& law,
                                                  const assembly::StructuralSystem& system,
                                                  double approach_velocity) {
  if (link.law && link.law->traits.stiff_at_first_touch) return std::nullopt;
  const std::optional<double> k_h = hertz_stiffness(law);
  const double m_eff = system.link_context(link).effective_mass();
  if (!k_h || !(m_eff > 0.0) || !(approach_velocity > 0.0)) return std::nullopt;
  return links::hertz_impact(*k_h, m_eff, approach_velocity);
}

LinkCheck check_contact(const model::Link& link, const links::LinkLaw& law,
                        const assembly::StructuralSystem& system, double approach_velocity) {
  const links::LawTraits traits = link.law ? link.law->traits : links::LawTraits{};
  const links::LinkContext context = system.link_context(link);
  LinkCheck c{link.id, law.name(), traits.stiff_at_first_touch, traits.constraint};
  const links::LawResponse touch = law.clone()->set_trial({1e-9, 1e-9, 0.0});
  // Hertz-type laws stiffen with penetration: no stiffness or duration before the impact.
  if (c.stiff_at_first_touch) c.stiffness = touch.stiffness;
  const double k_i = context.fixed_i ? 0.0 : context.stiffness_i,
               k_j = context.fixed_j ? 0.0 : context.stiffness_j;
  c.adjacent = (k_i > 0.0 && k_j > 0.0) ? std::min(k_i, k_j) : std::max(k_i, k_j);
  if (c.adjacent > 0.0) c.automatic = links::ExtendedPenalty::automatic(context, 1e-3, 1.0);
  if (const auto* penalty = dynamic_cast<const links::ExtendedPenalty*>(&law))
    c.used = penalty->numbers();
  const double m_eff = context.effective_mass();
  // When the link is much stiffer than what holds its nodes (or they are bare masses), a
  // contact is the two end masses on the link: it lasts half a period of that pair. Against
  // comparably stiff neighbours (a rod at k-ratio ~1) the contact lasts as long as the
  // structure takes (a wave), so no duration is claimed.
  const bool link_governs = c.adjacent == 0.0 || c.stiffness >= 10.0 * c.adjacent;
  // The extended penalty's mass alpha2 moves with the pair: half a period of m_eff + alpha2 (it
  // was left out: 0.026 s claimed for a 0.103 s contact at alpha2 = 15 m_eff).
  if (c.stiffness > 0.0 && m_eff > 0.0 && link_governs)
    c.contact_duration = std::numbers::pi * std::sqrt((m_eff + touch.mass) / c.stiffness);
  else if (c.stiffness > 0.0 && m_eff > 0.0)
    c.no_duration =
        "it is not 10 x stiffer than the adjacent elements: the structure, not the link, sets how "
        "long a contact lasts";
  // A Hertz-type contact: its elastic impact's closed form, where the link at its peak
  // penetration is stiff against its neighbours.
  const std::optional<double> k_h = c.stiff_at_first_touch ? std::nullopt : hertz_stiffness(law);
  const std::optional<links::HertzImpact> impact =
      k_h ? hertz_impact_of(link, law, system, approach_velocity) : std::nullopt;
  if (impact) {
    const double peak_stiffness = 1.5 * *k_h * std::sqrt(impact->max_penetration);
    if (c.adjacent == 0.0 || peak_stiffness >= 10.0 * c.adjacent) {
      c.contact_duration = impact->duration;
      c.approach_velocity = approach_velocity;
    } else {
      c.no_duration = fmt::format(
          "its peak stiffness at an approach velocity of {:.3g} ({:.4g}) is not 10 x the adjacent "
          "elements' ({:.4g}): the structure, not the link, sets how long a contact lasts",
          approach_velocity, peak_stiffness, c.adjacent);
    }
  } else if (k_h && m_eff > 0.0) {
    c.no_duration =
        "no approach velocity to estimate it at (no record, no initial closing velocity)";
  }
  if (c.contact_duration == 0.0 && c.no_duration.empty() && !c.constraint && !(m_eff > 0.0))
    c.no_duration =
        "an end carries no lumped mass of its own (a point along a member, the structure's mass "
        "at other nodes), so there are no two masses to estimate it from";
  return c;
}

// The probes already run: links of one law spec in one context at one approach velocity (a
// building pair's pounding links storey by storey, a bridge's two abutments) make equal laws,
// which the probe finds the same (it is a few thousand steps of a two-mass model: a third of a
// Takeda pair's run when it was repeated for each of its 15 contacts).
struct ProbeMemo {
  struct Entry {
    links::LawSpec spec;
    links::LinkContext context;
    double approach_velocity = 0.0;
    std::optional<ContactEnergyProbe> probe;
  };
  std::vector<Entry> entries;
  std::size_t probes_run = 0;

  std::optional<ContactEnergyProbe> probe(const model::Link& link, const links::LinkLaw& law,
                                          const links::LinkContext& context,
                                          const builder::AnalysisSpec& analysis,
                                          double approach_velocity) {
    if (link.law_spec)
      for (const Entry& e : entries)
        if (e.approach_velocity == approach_velocity && e.context == context &&
            e.spec == *link.law_spec)
          return e.probe;
    ++probes_run;
    std::optional<ContactEnergyProbe> result =
        probe_contact_energy(law, context, analysis, approach_velocity);
    if (link.law_spec) entries.push_back({*link.law_spec, context, approach_velocity, result});
    return result;
  }
};

// An impact of the link's end masses at the run's integrator and step that creates more than
// kContactCreatedWarning of its approach energy.
void warn_created_energy(const model::Link& link, const links::LinkLaw& law,
                         const assembly::StructuralSystem& system,
                         const builder::AnalysisSpec& analysis, double approach_velocity,
                         ProbeMemo& memo, std::vector<std::string>& warnings) {
  if (link.law && link.law->traits.inertia) return;  // its engagements' work has no sign
  const std::optional<ContactEnergyProbe> probe =
      memo.probe(link, law, system.link_context(link), analysis, approach_velocity);
  if (!probe || !(probe->created_fraction > results::kContactCreatedWarning)) return;
  warnings.push_back(fmt::format(
      "link {}: an impact of its end masses at {:.3g} (twice the peak ground velocity or the "
      "initial closing velocity) creates up to {:.2f} % of its approach energy with this "
      "integrator and time step {:.4g} (contact {:.4g}, starting inside a step): reduce the "
      "step, or use a law that resolves the impact (the extended penalty)",
      link.id, approach_velocity, 100.0 * probe->created_fraction, analysis.time_step,
      probe->contact_duration));
}

// The largest peak ground velocity of the model's excitations, as applied.
double peak_ground_velocity(const model::Model& model) {
  double peak = 0.0;
  for (const model::UniformExcitation& e : model.excitations)
    peak = std::max(peak, model::GroundKinematics(e.motion, 0.0).peak_velocity());
  for (const model::SupportExcitation& e : model.support_excitations)
    peak = std::max(peak, model::GroundKinematics(e.motion, 0.0).peak_velocity());
  return peak;
}

// Linear acceleration's limit is computed where every DOF has a mass; with DOFs without one (a
// frame's rotations), the condensed system's highest frequency is not, and a step past it runs
// until the run's energy check stops it: say so, with the shortest period found (its modes).
void warn_uncomputed_implicit_limit(const builder::AnalysisSpec& analysis, ModelCheck& check) {
  const std::optional<double> limit = analysis.integrator.stability_limit();
  if (analysis.integrator.is_explicit() || !limit || check.implicit_stable_step) return;
  std::string against;
  if (!check.periods.empty()) {
    const double step = *limit / (2.0 * std::numbers::pi) * check.periods.back();
    against =
        fmt::format("; against the shortest period found, {:.4g} (contacts open), it is {:.4g}{}",
                    check.periods.back(), step,
                    analysis.longest_step() > step ? ", which the time step passes" : "");
  }
  check.warnings.push_back(fmt::format(
      "{} is stable only below {:.4g} / omega_max, which is not computed for a model with DOFs "
      "without mass (a frame's rotations, a node without mass){}: a step past it grows until the "
      "run stops it as creating energy; newmark_average_acceleration is stable at any step",
      analysis.integrator.label(), *limit, against));
}

// Each contact's approach velocity for its estimates: twice the largest peak ground velocity, or
// its initial closing velocity where larger.
Vector approach_velocities(const builder::BuiltModel& built, assembly::StructuralSystem& system) {
  const integrators::LinkSet& links = system.links();
  const double ground_velocity = peak_ground_velocity(built.model);
  Vector closing;
  links.project(system.initial_velocity(built.model), closing);
  Vector approach(links.count());
  for (Index k = 0; k < links.count(); ++k)
    approach[k] = std::max(2.0 * ground_velocity, std::abs(closing[links.row(k)]));
  return approach;
}

// The Hertz-type contacts (F = k_h delta^1.5, no stiffness at first touch) at their elastic
// impact's peak penetration and approach velocity: where the explicit step in contact is set
// (at first touch they add no stiffness, and the step found there depended on the units).
// `unknown`: some Hertz-type contact has no approach velocity to estimate it at.
std::vector<integrators::LinkRowState> hertz_peaks(const builder::BuiltModel& built,
                                                   assembly::StructuralSystem& system,
                                                   const Vector& approach, bool& unknown) {
  integrators::LinkSet& links = system.links();
  std::vector<integrators::LinkRowState> peaks;
  unknown = false;
  for (Index k = 0; k < links.count(); ++k) {
    const model::Link& link = built.model.links[static_cast<std::size_t>(k)];
    if (link.role() != links::LinkRole::contact || !link.law ||
        link.law->traits.stiff_at_first_touch)
      continue;
    if (const auto impact = hertz_impact_of(link, links.law(k), system, approach[k]))
      peaks.push_back({links.row(k), impact->max_penetration, approach[k]});
    else
      unknown = true;
  }
  return peaks;
}

void check_explicit_steps(const builder::BuiltModel& built, assembly::StructuralSystem& system,
                          const Vector& approach, ModelCheck& check) {
  const builder::AnalysisSpec& analysis = built.analysis;
  const bool lumped = system.lumped_mass() && (system.lumped_mass()->array() > 0.0).all();
  if (!lumped) {
    check.explicit_unavailable = !system.lumped_mass() && system.dofs().has_ties()
                                     ? "the constraints couple the masses through lever arms"
                                     : "a DOF has no lumped mass";
    return;
  }
  bool unknown = false;
  const std::vector<integrators::LinkRowState> peaks =
      hertz_peaks(built, system, approach, unknown);
  check.hertz_at_peak = !peaks.empty();
  check.hertz_without_stiffness = unknown;
  double refused_above = 0.0;
  try {
    check.explicit_step_open = integrators::stable_time_step(system, false);
    check.explicit_step_contact = integrators::stable_time_step(system, true, peaks);
    refused_above =
        peaks.empty() ? *check.explicit_step_contact : integrators::stable_time_step(system, true);
  } catch (const std::domain_error& error) {
    check.explicit_step_open.reset();
    check.explicit_unavailable = error.what();
    check.warnings.push_back(
        fmt::format("central difference cannot run this model: {}", error.what()));
    return;
  }
  if (!analysis.integrator.is_explicit() || analysis.time_step_auto) return;
  if (analysis.time_step > refused_above)
    check.warnings.push_back(
        fmt::format("time step {:.4g} is above the explicit stable limit "
                    "{:.4g}: the run will be refused",
                    analysis.time_step, refused_above));
  else if (analysis.time_step > *check.explicit_step_contact)
    check.warnings.push_back(fmt::format(
        "time step {:.4g} is above the explicit stable step {:.4g} with the Hertz-type contacts "
        "at their peak penetration (an impact at twice the peak ground velocity or the initial "
        "closing velocity): their impacts will not be resolved, and the run may create energy "
        "or stop",
        analysis.time_step, *check.explicit_step_contact));
}

// A step that spans a good part of the analysis or many samples of a record computes something,
// but not the response: a 100 s step on a 30 s record is one step. Ten is a loose bound (a
// record's peaks last a few samples; a response needs many steps), so a warning is meant.
void check_step_against_duration(const builder::BuiltModel& built,
                                 std::vector<std::string>& warnings) {
  constexpr double kFew = 10.0;
  const builder::AnalysisSpec& analysis = built.analysis;
  if (analysis.time_step_auto || !(analysis.time_step > 0.0)) return;
  if (analysis.duration > 0.0 && analysis.time_step > analysis.duration / kFew)
    warnings.push_back(fmt::format(
        "the time step {:.4g} is more than a tenth of the duration {:.4g}: the analysis takes "
        "only {:.0f} step(s) (is /analysis/time_step what you meant?)",
        analysis.time_step, analysis.duration, analysis.step_count()));
  auto check_record = [&](const model::GroundMotion& motion) {
    if (motion.time_step > 0.0 && analysis.time_step > kFew * motion.time_step)
      warnings.push_back(fmt::format(
          "the time step {:.4g} is {:.0f} times the sampling interval {:.4g} of record '{}': "
          "the record's peaks are stepped over",
          analysis.time_step, analysis.time_step / motion.time_step, motion.time_step,
          motion.name));
  };
  for (const model::UniformExcitation& e : built.model.excitations) check_record(e.motion);
  for (const model::SupportExcitation& e : built.model.support_excitations) check_record(e.motion);
}

// A run of more steps than this is over 20,000 times the bundled models' longest (43,364): most
// often a time step or a duration mistyped by powers of ten, and a run that would say nothing for
// hours. A warning, not a refusal (the builder refuses only an uncountable 1e15): a fine mesh under
// a long record may need it.
constexpr double kLongRunSteps = 1e9;

// "25 minutes", "3 hours", "12 days", "3 years": a wall time to the unit a reader thinks in.
std::string rough_duration(double seconds) {
  constexpr double kMinute = 60.0, kHour = 3600.0, kDay = 86400.0, kYear = 365.25 * kDay;
  if (seconds < 2.0 * kHour) return fmt::format("{:.0f} minutes", seconds / kMinute);
  if (seconds < 2.0 * kDay) return fmt::format("{:.0f} hours", seconds / kHour);
  if (seconds < 2.0 * kYear) return fmt::format("{:.0f} days", seconds / kDay);
  return fmt::format("{:.3g} years", seconds / kYear);
}

void warn_long_run(const builder::AnalysisSpec& analysis, std::vector<std::string>& warnings) {
  const double steps = analysis.step_count();
  if (!(steps > kLongRunSteps)) return;
  constexpr double kBridgeStep = 1e-6;  // [s] of wall time a step of a 60-DOF plane bridge
  warnings.push_back(fmt::format(
      "the analysis takes {:.3g} steps (a duration of {:.4g} over a time step of {:.4g}): at a "
      "microsecond a step, a plane bridge of 60 DOFs, that is about {}, and larger models take "
      "longer (is /analysis/time_step or /analysis/duration what you meant? --time-limit or "
      "\"max_steps\" bound a run)",
      steps, analysis.duration, analysis.time_step, rough_duration(steps * kBridgeStep)));
}

// A step limit below the steps the analysis takes stops the run as failed part way: said before
// it starts. An adaptive run takes at least the duration over its longest step.
void warn_step_limit(const builder::AnalysisSpec& analysis, std::vector<std::string>& warnings) {
  if (analysis.max_steps <= 0) return;
  const double longest = analysis.longest_step(), steps = analysis.fewest_steps();
  if (!(steps > static_cast<double>(analysis.max_steps))) return;
  warnings.push_back(fmt::format(
      "the analysis takes {}{:.15g} steps and the step limit is {} (\"max_steps\", or pound "
      "run --max-steps): the run stops as failed at {}t = {:.6g} of {:.6g}{} (is the limit what "
      "you meant?)",
      analysis.adaptive ? "at least " : "", steps, analysis.max_steps,
      analysis.adaptive ? "" : "about ", static_cast<double>(analysis.max_steps) * longest,
      analysis.duration, analysis.adaptive ? " at the latest" : ""));
}

}  // namespace

void warn_step_count(const builder::AnalysisSpec& analysis, std::vector<std::string>& warnings) {
  if (!(analysis.time_step > 0.0) || !(analysis.duration > 0.0)) return;
  warn_long_run(analysis, warnings);
  warn_step_limit(analysis, warnings);
}

namespace {

// An analysis that stops before a record's strongest shaking reports peaks of its start only (a
// duration cut short for a trial run, then kept).
void check_duration_reaches_peaks(const builder::BuiltModel& built,
                                  std::vector<std::string>& warnings) {
  const double duration = built.analysis.duration;
  // A moving support's record: at the first support it reaches.
  const auto check = [&](const model::GroundMotion& motion, double delay) {
    const double peak_time = motion.time_of_peak() + delay;
    const std::string& time = built.units.of(Dimension::time);
    if (duration > 0.0 && duration < peak_time)
      warnings.push_back(fmt::format(
          "the analysis stops at {:.4g} {}, before record '{}' reaches its largest acceleration "
          "(at {:.4g} {}): its strongest shaking is not analysed (is /analysis/duration what you "
          "meant?)",
          duration, time, motion.name, peak_time, time));
  };
  for (const model::UniformExcitation& e : built.model.excitations) check(e.motion, 0.0);
  for (const model::SupportExcitation& e : built.model.support_excitations) {
    double first = INFINITY;
    for (const auto& [node, delay] : e.supports) first = std::min(first, delay);
    check(e.motion, std::isfinite(first) ? first : 0.0);
  }
}

// A record scaled past any earthquake's peak is more often a slip of its units (cm/s2 read as
// m/s2 is 100 times too strong) or of its scale than an intent; the strongest records (Iwate-
// Miyagi 2008) peak at about 4 g. A warning, not a refusal: an incremental dynamic analysis may
// scale a record this far on purpose.
void check_record_peaks(const builder::BuiltModel& built, std::vector<std::string>& warnings) {
  constexpr double kStrongest = 5.0;  // g
  for (std::size_t k = 0; k < built.excitation_peaks.size(); ++k) {
    const builder::ScaledPeak& peak = built.excitation_peaks[k];
    if (peak.in_g > kStrongest)
      warnings.push_back(fmt::format(
          "/excitations/{}: record '{}' peaks at {:.3g} g as scaled, beyond any earthquake "
          "recorded (the strongest about 4 g): check its \"units\" (a record in cm/s2 read as "
          "m/s2 is 100 times too strong) and its scale; an incremental dynamic analysis scaled "
          "this far on purpose may ignore this",
          k, peak.record, peak.in_g));
  }
}

// A record along a direction in which every DOF with mass is held (the vertical of a floor whose
// z is fixed) loads nothing: every response is 0, which would pass for a result.
void check_excitations_load(const builder::BuiltModel& built,
                            const assembly::StructuralSystem& system,
                            std::vector<std::string>& warnings) {
  for (std::size_t k = 0; k < built.model.excitations.size(); ++k) {
    if (system.excitation_loads(k)) continue;
    const model::UniformExcitation& e = built.model.excitations[k];
    // A pair's two components are two of the model's excitations but one of the file's.
    const std::size_t entry =
        k < built.uniform_excitation_sources.size() ? built.uniform_excitation_sources[k] : k;
    warnings.push_back(fmt::format(
        "/excitations/{}: record '{}' acts along [{:.4g}], in which every DOF with mass is held: "
        "it loads nothing and every response to it is 0 (is its \"direction\" what you meant?)",
        entry, e.motion.name,
        fmt::join(e.direction.begin(), e.direction.begin() + built.model.dimension, ", ")));
  }
}

// A linear dashpot link (a viscous damper, or a spring's own dashpot) damps its end masses'
// relative motion with the time constant tau = m_eff / c. Central difference takes a dashpot's
// rate half a step ahead, first order: its decay is off by about dt / (2 tau) (a 1,000 t mass
// launched on a damper of c = 1e8 N s/m reached 60 % of its exact peak at dt = 0.8 tau, 90 % at
// 0.2 tau, 95 % at 0.1 tau), so past 0.1 tau it is warned of. The implicit steps' trapezoidal
// decay reaches the right stroke at any step (exact to 1e-4 at 0.8 tau) and does not oscillate
// until its amplification turns negative past 2 tau, where it is warned of. A nonlinear damper's
// tangent at rest is no measure of its decay, and contacts are held to their durations instead.
void warn_dashpot_steps(const builder::BuiltModel& built, const builder::AnalysisSpec& analysis,
                        const assembly::StructuralSystem& system,
                        std::vector<std::string>& warnings) {
  if (!(analysis.time_step > 0.0)) return;
  const double step = analysis.longest_step();
  const bool explicit_step = analysis.integrator.is_explicit();
  for (Index k = 0; k < system.links().count(); ++k) {
    const model::Link& link = built.model.links[static_cast<std::size_t>(k)];
    if (link.role() != links::LinkRole::spring) continue;
    const links::LinkLaw& law = system.links().law(k);
    const double slow = law.clone()->set_trial({0.0, 1e-9, 0.0}).damping;
    const double fast = law.clone()->set_trial({0.0, 1.0, 0.0}).damping;
    const double m_eff = system.link_context(link).effective_mass();
    if (!(slow > 0.0) || std::abs(fast - slow) > 1e-9 * slow || !(m_eff > 0.0)) continue;
    const double tau = m_eff / slow, bound = explicit_step ? 0.1 * tau : 2.0 * tau;
    if (!(step > bound)) continue;
    const std::string why =
        explicit_step
            ? fmt::format(
                  "central difference, whose dashpot rate is half a step ahead, is off by "
                  "about dt / (2 tau) = {:.0f} %",
                  100.0 * step / (2.0 * tau))
            : std::string("past 2 tau the implicit step's decay changes sign at every step");
    warnings.push_back(fmt::format(
        "link {}: its dashpot (c = {:.4g}) damps its end masses' relative motion with the time "
        "constant tau = m_eff / c = {:.4g}, and {} is {:.4g}: {} (a step of at most {:.4g} "
        "resolves it)",
        link.id, slow, tau, analysis.adaptive ? "the longest adaptive step" : "the time step", step,
        why, bound));
  }
}

// A friction coefficient above 1 holds more than the normal force sideways: no bearing or
// pounding surface does (sliding bearings 0.01-0.15, steel on steel 0.2-0.5, concrete on concrete
// 0.6-0.8), so it is most likely a typing slip; a warning, as a rough or keyed interface may be
// modelled so on purpose.
void warn_friction_coefficients(const assembly::StructuralSystem& system,
                                std::vector<std::string>& warnings) {
  const integrators::LinkSet& links = system.links();
  for (Index k = 0; k < links.count(); ++k) {
    const links::CoulombFriction* friction = links.friction(k);
    if (!friction || !(friction->coefficient() > 1.0)) continue;
    warnings.push_back(fmt::format(
        "link '{}': friction coefficient mu = {:.4g} is above 1, more than any bearing or "
        "pounding surface (sliding bearings 0.01-0.15, steel on steel 0.2-0.5, concrete on "
        "concrete 0.6-0.8): check the value",
        system.link_id(k), friction->coefficient()));
  }
}

}  // namespace

ModelCheck check_model(const builder::BuiltModel& built, const builder::AnalysisSpec& analysis,
                       assembly::StructuralSystem& system, bool with_periods) {
  const integrators::LinkSet& links = system.links();
  ModelCheck check{system.size(), system.dofs().dofs_per_node(), links.count()};
  check.dimension = built.model.dimension;
  for (Index node = 0; node < static_cast<Index>(built.model.nodes.size()); ++node)
    for (int d = 0; d < system.dofs().dofs_per_node(); ++d)
      if (system.dofs().own_equation(node, d) >= 0)
        ++check.dofs_by_direction[static_cast<std::size_t>(d)];
      else if (system.dofs().tied(node, d))
        ++check.tied_dofs;
  if (with_periods) {
    try {
      check.periods = assembly::natural_periods(system, 6);
    } catch (const std::exception& error) {  // the modal analysis's typed failures
      check.warnings.push_back(fmt::format("the periods cannot be found: {}", error.what()));
    }
  }
  const Vector approach = approach_velocities(built, system);
  check_explicit_steps(built, system, approach, check);
  check.implicit_stable_step = builder::conditional_stable_step(analysis.integrator, system);
  warn_uncomputed_implicit_limit(analysis, check);
  check_step_against_duration(built, check.warnings);
  warn_step_count(analysis, check.warnings);
  check_record_peaks(built, check.warnings);
  check_duration_reaches_peaks(built, check.warnings);
  check_excitations_load(built, system, check.warnings);
  warn_friction_coefficients(system, check.warnings);
  warn_dashpot_steps(built, analysis, system, check.warnings);
  ProbeMemo memo;
  for (Index k = 0; k < links.count(); ++k) {
    const model::Link& link = built.model.links[static_cast<std::size_t>(k)];
    if (link.role() != links::LinkRole::contact) continue;
    const LinkCheck c = check_contact(link, links.law(k), system, approach[k]);
    // A penalty spring without the extended penalty's mass: Kawashima's advice.
    const bool plain_penalty = link.law && link.law->traits.penalty &&
                               links.law(k).clone()->set_trial({1e-9, 1e-9, 0.0}).mass == 0.0;
    const bool meshed = meshed_at(built.model, link.node_i) || meshed_at(built.model, link.node_j);
    if (c.adjacent > 0.0 && c.stiff_at_first_touch && plain_penalty)
      warn_k_ratio(c, meshed, check.warnings);
    if (!meshed) warn_penalty_mass(link, links.law(k), system, check.warnings);
    // A lift-off that creates energy is still told after the run (the contacts' created
    // energy).
    if (!builder::seated_under_weight(link, built)) {
      // Between meshed bodies "auto" resolves the mesh, whose waves set how long an impact lasts
      // (the rod benchmark); the end masses' duration is the contact's between lumped masses.
      if (!(analysis.time_step_auto && meshed)) warn_contact_steps(c, analysis, check.warnings);
      warn_created_energy(link, links.law(k), system, analysis, approach[k], memo, check.warnings);
    }
    check.contacts.push_back(c);
  }
  check.contact_energy_probes = memo.probes_run;
  if (!check.periods.empty() && !analysis.time_step_auto &&
      analysis.time_step > check.periods.back() / 10.0)
    check.warnings.push_back(
        fmt::format("the time step {:.4g} resolves period {} of the model ({:.4g}, the "
                    "shortest found) with fewer than 10 steps",
                    analysis.time_step, check.periods.size(), check.periods.back()));
  return check;
}

}  // namespace pound::verification
