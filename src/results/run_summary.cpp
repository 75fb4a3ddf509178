#include "results/run_summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string_view>

#include "assembly/beam_3d.hpp"
#include "core/errors.hpp"
#include "core/units.hpp"
#include "model/direction.hpp"
#include "results/spectrum_recorder.hpp"

namespace pound::results {
namespace {

GroundAcceleration ground_of(const assembly::StructuralSystem& system) {
  return {
      system.size(),
      [&system](double time, std::vector<double>& scales) { system.frame_scales(time, scales); },
      system.frame_shapes(),
      [&system](Index node, int direction, double time) {
        return system.support_acceleration(node, direction, time);
      }};
}

SupportMotion support_motion_of(const assembly::StructuralSystem& system) {
  if (system.moving_support_count() == 0) return {};
  std::vector<Vector> influences;
  for (std::size_t k = 0; k < system.moving_support_count(); ++k)
    influences.push_back(system.moving_support_influence(k));
  return {std::move(influences), [&system](double time, std::vector<double>& displacements) {
            system.moving_support_displacements(time, displacements);
          }};
}

std::unique_ptr<Quantities> link_quantities(const builder::BuiltModel& built,
                                            const integrators::LinkSet& links,
                                            const std::vector<Index>& items) {
  std::vector<std::string> ids;
  std::vector<LinkRows> rows;
  for (Index link : items) {
    const model::Link& spec = built.model.links[static_cast<std::size_t>(link)];
    ids.push_back(spec.id);
    rows.push_back({links.row(link), links.rows(link) - 1, spec.rotational});
  }
  return std::make_unique<LinkQuantities>(rows, ids);
}

// Appends weight x a DOF's terms to a sum of terms.
void add_scaled(std::vector<Term>& into, std::span<const model::DofTerm> terms, double weight) {
  for (const model::DofTerm& term : terms)
    into.push_back({term.equation, weight * term.coefficient});
}

// How (node, direction) is read: through its terms (none where fixed).
DofReading reading(const model::DofMap& dofs, Index node, int direction) {
  const std::span<const model::DofTerm> terms = dofs.terms(node, direction);
  return {terms.begin(), terms.end()};
}

// The directions a node moves in: its free DOFs (a floor of a shear building has no y or
// rotation), translations only if asked; a node fixed in every direction moves with its
// support, whose x is recorded.
std::vector<int> free_directions(const model::DofMap& dofs, Index node, bool translations_only) {
  std::vector<int> directions;
  for (int d = 0; d < dofs.dofs_per_node(); ++d)
    if (!dofs.terms(node, d).empty() &&
        !(translations_only && model::direction(d, dofs.dimension()).rotation))
      directions.push_back(d);
  if (directions.empty()) directions.push_back(0);
  return directions;
}

std::unique_ptr<Quantities> node_quantities(const builder::BuiltModel& built,
                                            const model::DofMap& dofs,
                                            const builder::ResolvedRecorder& spec,
                                            GroundAcceleration& ground) {
  std::vector<std::string> ids;
  std::vector<std::vector<DofReading>> readings;
  std::vector<std::vector<int>> directions;
  for (Index node : spec.items) {
    ids.push_back(built.model.nodes[static_cast<std::size_t>(node)].id);
    directions.push_back(free_directions(dofs, node, false));
    std::vector<DofReading>& per_direction = readings.emplace_back();
    for (int d : directions.back()) per_direction.push_back(reading(dofs, node, d));
  }
  return std::make_unique<NodeQuantities>(std::move(readings), std::move(directions),
                                          dofs.dimension(), spec.items, ids, spec.accelerations,
                                          ground);
}

// A node's free translational directions (x when it has none: its support's motion).
std::vector<SpectrumPlace> spectrum_places(const builder::BuiltModel& built,
                                           const model::DofMap& dofs,
                                           const std::vector<Index>& nodes) {
  std::vector<SpectrumPlace> places;
  for (Index node : nodes)
    for (int d : free_directions(dofs, node, true))
      places.push_back({built.model.nodes[static_cast<std::size_t>(node)].id,
                        reading(dofs, node, d), node, d,
                        model::direction(d, dofs.dimension()).symbol});
  return places;
}

// The terms of a node's displacement along a direction: its DOF's, and with moving supports the
// entry of each moving support that moves it (SupportMotion::total's, after the free DOFs), for a
// girder's movement on a moving seat or a pier's drift over a moving base in total motion.
struct DisplacementTerms {
  const model::DofMap& dofs;
  const assembly::StructuralSystem* moving = nullptr;  // the system, where supports move

  void add(Index node, int direction, double weight, std::vector<Term>& terms) const {
    add_scaled(terms, dofs.terms(node, direction), weight);
    if (!moving) return;
    for (std::size_t k = 0; k < moving->moving_support_count(); ++k)
      if (const double share = moving->moving_support_share(k, node, direction); share != 0.0)
        terms.push_back({moving->size() + static_cast<Index>(k), weight * share});
  }
};

DisplacementTerms displacement_terms(const assembly::StructuralSystem& system) {
  return {system.dofs(), system.moving_support_count() > 0 ? &system : nullptr};
}

// The end forces of elements `items` from their DOFs' displacements, read through `dofs` (with
// moving supports, the entries of their total motion).
std::unique_ptr<ElementQuantities> element_quantities(
    const builder::BuiltModel& built, const DisplacementTerms& dofs,
    const std::vector<Index>& items, std::vector<std::vector<std::size_t>> wanted = {}) {
  std::vector<std::shared_ptr<const model::Element>> elements;
  std::vector<std::vector<DofReading>> readings;
  for (Index item : items) {
    elements.push_back(built.model.elements[static_cast<std::size_t>(item)]);
    std::vector<DofReading>& each = readings.emplace_back();
    for (const model::ElementDof& dof : elements.back()->dofs())
      dofs.add(dof.node, dof.direction, 1.0, each.emplace_back());
  }
  return std::make_unique<ElementQuantities>(std::move(elements), std::move(readings),
                                             std::move(wanted));
}

std::unique_ptr<Recorder> make_recorder(const builder::BuiltModel& built,
                                        const assembly::StructuralSystem& system,
                                        const builder::ResolvedRecorder& spec,
                                        GroundAcceleration& ground) {
  if (spec.kind == builder::RecorderKind::spectrum)
    return std::make_unique<SpectrumRecorder>(
        spec.file, spectrum_places(built, system.dofs(), spec.items), spec.periods,
        spec.damping_ratios, ground, built.units);
  std::unique_ptr<Quantities> quantities =
      spec.kind == builder::RecorderKind::link ? link_quantities(built, system.links(), spec.items)
      : spec.kind == builder::RecorderKind::element
          ? element_quantities(built, DisplacementTerms{system.dofs()}, spec.items)
          : node_quantities(built, system.dofs(), spec, ground);
  if (spec.envelope)
    return std::make_unique<EnvelopeRecorder>(spec.file, std::move(quantities), built.units);
  return std::make_unique<HistoryRecorder>(spec.file, std::move(quantities), spec.sampling,
                                           built.units);
}

std::vector<std::unique_ptr<Recorder>> make_recorders(const builder::BuiltModel& built,
                                                      const assembly::StructuralSystem& system,
                                                      GroundAcceleration& ground) {
  std::vector<std::unique_ptr<Recorder>> recorders;
  for (const builder::ResolvedRecorder& spec : built.recorders)
    recorders.push_back(make_recorder(built, system, spec, ground));
  return recorders;
}

std::vector<Index> normal_rows(const integrators::LinkSet& links) {
  std::vector<Index> rows;
  for (Index k = 0; k < links.count(); ++k) rows.push_back(links.row(k));
  return rows;
}

// A bearing's coupled shear, or a friction link's tangential rows (its slide, which never
// yields: the summary's ductility stays 0).
std::vector<ShearRows> shear_rows(const integrators::LinkSet& links) {
  std::vector<ShearRows> rows(static_cast<std::size_t>(links.count()));
  for (Index k = 0; k < links.count(); ++k) {
    ShearRows& these = rows[static_cast<std::size_t>(k)];
    if (const links::CoupledShear* shear = links.shear(k)) {
      these.count = shear->tangents();
      for (std::size_t a = 0; a < these.yield_deformation.size(); ++a)
        these.yield_deformation[a] = shear->numbers()[a].yield_deformation();
    } else if (links.has_friction(k)) {
      these.count = links.rows(k) - 1;
      these.yield_deformation.fill(std::numeric_limits<double>::infinity());
    }
  }
  return rows;
}

// Adds sign x n . (u + theta x r) of `node` (a point r from it, rigidly tied to it), with
// n . (theta x r) = theta . (r x n).
void add_point_terms(Index node, const std::array<double, 3>& r, const std::array<double, 3>& n,
                     double sign, const DisplacementTerms& dofs, std::vector<Term>& terms) {
  const std::array<double, 6> along{n[0],
                                    n[1],
                                    n[2],
                                    r[1] * n[2] - r[2] * n[1],
                                    r[2] * n[0] - r[0] * n[2],
                                    r[0] * n[1] - r[1] * n[0]};
  for (int d = 0; d < std::min(6, dofs.dofs.dofs_per_node()); ++d) {
    if (along[static_cast<std::size_t>(d)] != 0.0)
      dofs.add(node, d, sign * along[static_cast<std::size_t>(d)], terms);
  }
}

// theta_z of `node` less that of `reference` (3-D scenes; nothing where both are held).
std::vector<Term> turn_in_plan(Index node, Index reference, const model::DofMap& dofs) {
  std::vector<Term> terms;
  for (const auto& [at, sign] : {std::pair{node, 1.0}, std::pair{reference, -1.0}})
    add_scaled(terms, dofs.terms(at, 5), sign);
  return terms;
}

// A storey's corner drifts along its direction (a corner c from the top node is c + X_top -
// X_bottom from the bottom node) and its twist about z (3-D floors).
void add_plan_terms(const builder::DriftMonitor& m, const model::Model& model,
                    const DisplacementTerms& dofs, DriftMonitors::Where& where) {
  const std::array<double, 3> n = m.along();
  const model::Coordinates& top = model.nodes[static_cast<std::size_t>(m.top)].position;
  const model::Coordinates& bottom = model.nodes[static_cast<std::size_t>(m.bottom)].position;
  for (const std::array<double, 3>& corner : m.corners) {
    std::array<double, 3> from_bottom = corner;
    for (std::size_t k = 0; k < 3; ++k) from_bottom[k] += top[k] - bottom[k];
    std::vector<Term>& terms = where.corners.emplace_back();
    add_point_terms(m.top, corner, n, 1.0, dofs, terms);
    add_point_terms(m.bottom, from_bottom, n, -1.0, dofs, terms);
  }
  where.twist = turn_in_plan(m.top, m.bottom, dofs.dofs);
}

// A drift along an axis n: n . (u_top - u_bottom), and the top's translations for its
// acceleration along n.
void add_axis_terms(const builder::DriftMonitor& m, const DisplacementTerms& dofs,
                    DriftMonitors::Where& where) {
  add_point_terms(m.top, {}, *m.axis, 1.0, dofs, where.drift);
  add_point_terms(m.bottom, {}, *m.axis, -1.0, dofs, where.drift);
  for (int d = 0; d < 3; ++d)
    where.top_along.emplace_back(reading(dofs.dofs, m.top, d),
                                 (*m.axis)[static_cast<std::size_t>(d)]);
}

std::vector<DriftMonitors::Where> drift_places(const builder::BuiltModel& built,
                                               const assembly::StructuralSystem& system) {
  const DisplacementTerms dofs = displacement_terms(system);
  std::vector<DriftMonitors::Where> places;
  for (const builder::DriftMonitor& m : built.drift_monitors) {
    DriftMonitors::Where& where = places.emplace_back(
        DriftMonitors::Where{reading(dofs.dofs, m.bottom, m.direction),
                             reading(dofs.dofs, m.top, m.direction), m.top, m.direction});
    if (m.axis) {
      add_axis_terms(m, dofs, where);
    } else if (dofs.moving) {  // the drift in total motion, a moving base's own included
      dofs.add(m.top, m.direction, 1.0, where.drift);
      dofs.add(m.bottom, m.direction, -1.0, where.drift);
    }
    if (!m.corners.empty()) add_plan_terms(m, built.model, dofs, where);
  }
  return places;
}

// A point r from the girder and the seat nodes moves across the support line (unit n) by
// n . (u_g + theta_g x r) - n . (u_s + theta_s x r).
std::vector<Term> point_movement(const builder::JointMonitor& m, const DisplacementTerms& dofs) {
  const std::array<double, 3> r = m.point.value_or(std::array<double, 3>{});
  std::vector<Term> terms;
  add_point_terms(m.girder, r, *m.direction, 1.0, dofs, terms);
  add_point_terms(m.seat, r, *m.direction, -1.0, dofs, terms);
  return terms;
}

// The sign of a girder's movement on its seat that opens its joint: moving the girder along the
// movement's direction (x, or the monitor's) changes the pounding link's penetration by
// d(delta) = sum of B's entries at the girder's translations along it; the opening way is the one
// that lowers delta. 0 where the link does not move with the girder.
double opening_sign(const builder::JointMonitor& m, const assembly::StructuralSystem& system) {
  const std::array<double, 3> along = m.direction.value_or(std::array<double, 3>{1.0, 0.0, 0.0});
  const Index row = system.links().row(m.link);
  const auto& connectivity = system.links().connectivity();
  double change = 0.0;
  for (int d = 0; d < std::min(3, system.dofs().dofs_per_node()); ++d) {
    if (model::direction(d, system.dofs().dimension()).rotation) continue;
    const double share = along[static_cast<std::size_t>(d)];
    if (share == 0.0) continue;
    for (const model::DofTerm& term : system.dofs().terms(m.girder, d))
      change += share * term.coefficient * connectivity.coeff(row, term.equation);
  }
  if (!(std::abs(change) > 1e-9)) return 0.0;
  return change > 0.0 ? -1.0 : 1.0;
}

std::vector<JointMonitors::Where> joint_places(const builder::BuiltModel& built,
                                               const assembly::StructuralSystem& system) {
  const DisplacementTerms dofs = displacement_terms(system);
  std::vector<JointMonitors::Where> places;
  for (const builder::JointMonitor& m : built.joint_monitors) {
    JointMonitors::Where& where = places.emplace_back(JointMonitors::Where{
        system.links().row(m.link), built.model.links[static_cast<std::size_t>(m.link)].gap,
        reading(system.dofs(), m.girder, 0), reading(system.dofs(), m.seat, 0), m.girder});
    if (m.direction) {
      where.movement = point_movement(m, dofs);
      where.plan_rotation = turn_in_plan(m.girder, m.seat, system.dofs());
    } else if (dofs.moving) {  // on a moving seat, in total motion
      dofs.add(m.girder, 0, 1.0, where.movement);
      dofs.add(m.seat, 0, -1.0, where.movement);
    }
    where.opening_sign = opening_sign(m, system);
  }
  return places;
}

// Stops the run when `fraction` of the largest energy term passes kEnergyGrowthLimit; `message`
// takes the percentage and the limit.
void stop_above_limit(double time, double fraction, fmt::format_string<double, double> message) {
  if (fraction > kEnergyGrowthLimit)
    throw SolveError(time, fmt::format(message, 100.0 * fraction, 100.0 * kEnergyGrowthLimit));
}

// A friction pendulum whose stick spring is soft against its dish. The spring slides
// d_y = mu N / k_t before the bearing slips, and at each reversal it gives back 2 mu N d_y that
// rigid-plastic friction would take: the last half swing's squared amplitude a^2 grows by
// 4 mu R d_y, so the residual displacement moves by sqrt(a^2 + 4 mu R d_y) - a, up to
// 2 sqrt(mu R d_y) (a free decay with k_t from 1e6 to 1e9 N/m follows this,
// tests/assembly/friction_pendulum_block_test.cpp). Warned past 2 % of the friction band mu R,
// d_y / (mu R) = N / (R k_t) > 1e-4, where the bearing slid past d_y (else it never slipped and
// has no reversal); N is the normal force at the end, where the residual is decided.
struct SoftStickSpring {
  const LinkResult* link = nullptr;
  double normal = 0.0, stick_slide = 0.0, band = 0.0, error = 0.0;
};

// The units the result warnings give their numbers in (the model's), each with its leading space,
// or "" where the model names none (forces without a mass unit).
struct WarningUnits {
  explicit WarningUnits(const UnitNames& names)
      : length(spaced(names.of(Dimension::length))),
        force(spaced(names.of(Dimension::force))),
        energy(spaced(names.of(Dimension::moment))),
        stiffness(force.empty() || length.empty() ? "" : force + "/" + length.substr(1)) {}
  static std::string spaced(const std::string& unit) { return unit.empty() ? "" : " " + unit; }
  std::string length, force, energy, stiffness;
};

std::optional<SoftStickSpring> soft_stick_spring(const LinkResult& link) {
  const double normal = link.summary.final_force;
  if (!link.pendulum || !link.summary.shear || !(normal > 0.0) ||
      !(link.pendulum->stick_stiffness > 0.0))
    return {};
  const PendulumNumbers& p = *link.pendulum;
  SoftStickSpring soft{&link, normal, p.coefficient * normal / p.stick_stiffness,
                       p.coefficient * p.radius};
  soft.error = 2.0 * std::sqrt(soft.band * soft.stick_slide);
  if (!(soft.error > 0.02 * soft.band) ||
      !(link.summary.shear->peak_deformation > soft.stick_slide))
    return {};
  return soft;
}

// One warning for the pendulums with soft stick springs: the worst's numbers, the others named.
std::string stick_spring_warning(std::vector<SoftStickSpring> soft, const WarningUnits& u) {
  std::stable_sort(soft.begin(), soft.end(), [](const auto& a, const auto& b) {
    return a.error / a.band > b.error / b.band;
  });
  const SoftStickSpring& worst = soft.front();
  const PendulumNumbers& p = *worst.link->pendulum;
  std::string text = fmt::format(
      "friction pendulum {}: its stick spring (stick_stiffness {:.4g}{}) slides d_y = {:.3g}{} "
      "before the bearing slips under mu N = {:.4g}{}, {:.2g} of the friction band mu R = {:.4g}"
      "{}; at each reversal the spring gives back energy Coulomb friction would take, so the "
      "residual displacement may be off by up to 2 sqrt(mu R d_y) = {:.3g}{} ({:.1f} % of mu R): "
      "a stick_stiffness of at least 1e4 x N/R = {:.3g}{} keeps that under 2 %",
      worst.link->id, p.stick_stiffness, u.stiffness, worst.stick_slide, u.length,
      p.coefficient * worst.normal, u.force, worst.stick_slide / worst.band, worst.band, u.length,
      worst.error, u.length, 100.0 * worst.error / worst.band, 1e4 * worst.normal / p.radius,
      u.stiffness);
  if (soft.size() > 1) {
    constexpr std::size_t kNamed = 5;
    std::string others;
    for (std::size_t k = 1; k < std::min(soft.size(), kNamed + 1); ++k)
      others += (k > 1 ? ", " : "") + soft[k].link->id;
    if (soft.size() > kNamed + 1) others += fmt::format(" and {} more", soft.size() - kNamed - 1);
    text += fmt::format(" (the same for {}, less far off)", others);
  }
  return text;
}

// A friction pendulum that slid far on its dish. The law is Zayas et al.'s small-displacement
// form N s / R; on the spherical dish the restoring force is N tan(theta) = N s / sqrt(R^2 - s^2),
// which the linear form falls short of by 1 - sqrt(1 - (s / R)^2) of it (2 % at s = 0.2 R), and
// the slider's rise s^2 / (2 R) is left out.
std::optional<std::string> dish_warning(const LinkResult& link, const WarningUnits& u) {
  if (!link.pendulum || !link.summary.shear) return {};
  const double slide = link.summary.shear->peak_deformation, radius = link.pendulum->radius;
  const double ratio = slide / radius;
  if (!(ratio > 0.2)) return {};
  const double short_by = ratio < 1.0 ? 1.0 - std::sqrt(1.0 - ratio * ratio) : 1.0;
  return fmt::format(
      "friction pendulum {}: it slid {:.4g}{}, {:.2f} of its radius R = {:.4g}{}, where the "
      "small-displacement pendulum's restoring force N s / R falls {:.1f} % short of the "
      "spherical dish's N s / sqrt(R^2 - s^2) and leaves out the slider's rise s^2 / (2 R) = "
      "{:.3g}{}: check that slide against the bearing's displacement capacity",
      link.id, slide, u.length, ratio, radius, u.length, 100.0 * short_by,
      slide * slide / (2.0 * radius), u.length);
}

// Whether the run has a pounding contact (a contact link not seated under its weight).
bool has_contacts(const RunSummary& run) {
  return std::any_of(run.links.begin(), run.links.end(), [](const LinkResult& link) {
    return link.role == links::LinkRole::contact && !link.seated;
  });
}

namespace {

// Central difference gives a hard impact's impulse J to the struck masses within one step, as an
// acceleration J / (m dt): a girder end's or a floor's peak acceleration then grows as 1 / dt
// (200, 400, 800, 1,600 m/s^2 at dt = 2, 1, 0.5, 0.25 ms in the audit, the impulses within 0.5 %),
// and is no physical number: a rigid impact's is infinite. (The implicit integrators leave the
// impulse out: theirs are the accelerations between impacts, as the docs say.)
std::optional<std::string> impulse_acceleration_warning(const RunSummary& run) {
  if (run.integrator != "central_difference" || (run.joints.empty() && run.drifts.empty()))
    return std::nullopt;
  std::string struck;
  for (const LinkResult& link : run.links)
    if (link.hard_contact() && link.summary.impacts > 0) {
      struck = link.id;
      break;
    }
  if (struck.empty()) return std::nullopt;
  return fmt::format(
      "hard contact {} struck under central difference, which gives each impact's impulse to "
      "the masses within one step: the peak accelerations of the girder ends and floors it "
      "strikes (and their histories and floor spectra) are that impulse / (m dt), growing as the "
      "step shrinks, not a physical peak; read the impulses, or give the contact a stiffness "
      "(a penalty law) for accelerations",
      struck);
}

}  // namespace

// Warnings for results an engineer should not trust as they are.
std::vector<std::string> result_warnings(const RunSummary& run, const UnitNames& names) {
  const WarningUnits u(names);
  std::vector<std::string> warnings;
  std::vector<SoftStickSpring> soft;
  for (const LinkResult& link : run.links)
    if (const std::optional<SoftStickSpring> found = soft_stick_spring(link))
      soft.push_back(*found);
  if (!soft.empty()) warnings.push_back(stick_spring_warning(std::move(soft), u));
  for (const LinkResult& link : run.links)
    if (std::optional<std::string> warning = dish_warning(link, u))
      warnings.push_back(std::move(*warning));
  if (std::optional<std::string> warning = impulse_acceleration_warning(run))
    warnings.push_back(std::move(*warning));
  for (const JointResult& joint : run.joints)
    if (joint.unseated())
      warnings.push_back(fmt::format(
          "joint {}: the girder moved {:.4g}{} away from the joint on a seat {:.4g}{} wide: "
          "unseated",
          joint.monitor.id, joint.peak.peak_unseating_movement, u.length, joint.monitor.seat_width,
          u.length));
  // Pounding drifts are a few percent; 10 % is far past what a model of small displacements (and
  // elastic storeys) describes, so such a number is not a result (a stiffness far too small?).
  // With P-Delta a yielded pier or storey whose post-yield stiffness is below P / h runs away
  // under its weight: that is a collapse, and its drifts (millions of percent) are not a demand.
  for (const DriftResult& drift : run.drifts)
    if (drift.largest_ratio() > 0.10)
      warnings.push_back(fmt::format(
          "{} {}: drift ratio {:.3g} %, far beyond what this small-displacement model describes: "
          "the result is meaningless there ({})",
          drift.monitor.kind == builder::DriftKind::pier ? "pier" : "storey", drift.monitor.id,
          100.0 * drift.largest_ratio(),
          run.p_delta && drift.largest_ductility().value_or(0.0) > 1.0
              ? "it yielded, and under gravity's P-Delta a post-yield stiffness below P/h runs "
                "away: read it as a collapse, not as a drift"
              : "a stiffness far too small?"));
  for (const DriftResult& drift : run.drifts)
    if (const std::optional<double> demand = drift.elastic_demand_ratio(); demand && *demand > 1.0)
      warnings.push_back(
          drift.monitor.kind == builder::DriftKind::pier
              ? fmt::format("pier {}: drift {:.2f} times its yield drift, but the pier is elastic "
                            "and cannot yield: this is not a ductility demand (give the bridge a "
                            "'pier_hinge' for one)",
                            drift.monitor.id, *demand)
              : fmt::format("storey {}: drift {:.2f} times the yield drift its monitor gives, but "
                            "the model does not yield there (\"yields\": false): this is not a "
                            "ductility demand",
                            drift.monitor.id, *demand));
  if (const double created = run.contact_created_fraction(); created > kContactCreatedWarning) {
    const LinkResult* most = nullptr;
    for (const LinkResult& link : run.links)
      if (link.passive_engagements &&
          (!most || link.summary.created_energy() > most->summary.created_energy()))
        most = &link;
    // A hard contact has no penalty to resolve: its impulse is exact, so what it made up is a
    // step that did not settle, not a stiffness.
    const bool hard = most->hard_contact();
    warnings.push_back(fmt::format(
        "contact links created {:.4g}{}, {:.2f} % of the energy put in (link {} {:.4g}{}): {}",
        run.contact_created_energy(), u.energy, 100.0 * created, most->id,
        most->summary.created_energy(), u.energy,
        hard ? "a hard contact's impulse takes energy and gives none back, so its constraint "
               "was not met within the step (contacts striking together that did not settle?); "
               "reduce the time step"
             : "a penalty contact that starts or ends inside a step gives back more than it "
               "took, so the pounding forces and what follows them are not to be trusted; "
               "reduce the time step, or use a law that resolves the impact (the extended "
               "penalty)"));
  }
  if (run.worst_balance_error > 0.01) {
    const std::string why =
        run.integrator_dissipates
            ? fmt::format(
                  "{} damps the highest modes by design and that loss is part of the "
                  "error, so it does not single out a contact or a step that was not "
                  "resolved; run newmark_average_acceleration, which conserves energy, "
                  "to see their share",
                  run.integrator)
        : has_contacts(run) ? "a contact or a step was not resolved (reduce the time step)"
                            : "a step was not resolved (reduce the time step)";
    warnings.push_back(
        fmt::format("energy balance error reached {:.2f} % of the largest energy "
                    "term: {}",
                    100.0 * run.worst_balance_error, why));
  }
  return warnings;
}

// A 3-D beam's base shear along the drift's direction e_d (V_y y' + V_z z' projected on it) and
// its moment about a = x' x e_d, the axis that shear bends it about (y for a column along z
// drifting along x), from its local axes; none for a member along the drift.
struct DriftWeights {
  std::vector<double> shear, moment;  // of (V_y, V_z) and (M_y, M_z); empty: the resultants
};
DriftWeights along_drift(const model::Element& element, const builder::DriftMonitor& monitor) {
  const auto* beam = dynamic_cast<const assembly::Beam3d*>(&element);
  if (!beam) return {};
  const Eigen::Matrix3d& axes = beam->axes();  // rows x', y', z'
  const std::array<double, 3> along = monitor.along();
  const Eigen::Vector3d drift(along[0], along[1], along[2]);
  const Eigen::Vector3d across = axes.row(0).transpose().cross(drift);
  if (!(across.norm() > 1e-12)) return {};
  const Eigen::Vector3d about = across.normalized();
  return {{axes.row(1).dot(drift), axes.row(2).dot(drift)},
          {axes.row(1).dot(about), axes.row(2).dot(about)}};
}

// The monitors whose drifts yield together (DriftMonitor::yields_with), each pair once, with
// their yield drifts.
std::vector<DriftMonitors::ResultantPair> resultant_pairs(
    const std::vector<builder::DriftMonitor>& monitors) {
  std::vector<DriftMonitors::ResultantPair> pairs;
  for (std::size_t k = 0; k < monitors.size(); ++k) {
    const builder::DriftMonitor& m = monitors[k];
    if (!m.yields_with || *m.yields_with <= k || !m.yields || !m.yield_drift) continue;
    const builder::DriftMonitor& partner = monitors[*m.yields_with];
    if (!partner.yield_drift) continue;
    pairs.push_back({k, *m.yields_with, *m.yield_drift, *partner.yield_drift});
  }
  return pairs;
}

}  // namespace

RunObservers::RunObservers(const builder::BuiltModel& built,
                           const assembly::StructuralSystem& system, bool histories)
    // Without histories nothing is recorded, not just not written.
    : ground_(ground_of(system)),
      support_(support_motion_of(system)),
      recorders_(histories ? make_recorders(built, system, ground_)
                           : std::vector<std::unique_ptr<Recorder>>()),
      links_(normal_rows(system.links()), shear_rows(system.links())),
      energy_(system, built.analysis.integrator.acceleration_energy(),
              built.analysis.integrator.is_explicit()),
      passive_links_(!system.has_link_motion()),
      drifts_(drift_places(built, system), ground_, support_.moving() ? &support_ : nullptr),
      joints_(joint_places(built, system), ground_, support_.moving() ? &support_ : nullptr) {
  drifts_.set_resultant_pairs(resultant_pairs(built.drift_monitors));
  if (!built.analysis.integrator.is_explicit()) {
    const std::vector<char> step_forces =
        system.links().impulsive_hard_contact_rows(system.lumped_mass());
    links_.set_step_forces(step_forces);
    energy_.set_step_forces(step_forces);
  }
  set_up_base_forces(built, system);
}

// Each base element's shears and moments at end i (V_i in a plane, Vy_i and Vz_i in space; M
// likewise), and the shears of the elements above it (a column cut where a floor strikes it),
// read once a step however many monitors share them (a storey's x and y).
void RunObservers::set_up_base_forces(const builder::BuiltModel& built,
                                      const assembly::StructuralSystem& system) {
  const auto is_shear = [](std::string_view name) {
    return name == "V_i" || name == "Vy_i" || name == "Vz_i";
  };
  const auto is_moment = [](std::string_view name) {
    return name == "M_i" || name == "My_i" || name == "Mz_i";
  };
  std::vector<Index> elements;
  std::vector<std::vector<std::size_t>> wanted;
  std::map<Index, std::size_t> first_place;  // of each element's values in base_row_
  std::size_t places = 0;
  // Element e's end-i shears and moments, their places in base_row_ (read once per element).
  const auto rows_of = [&](Index e, const builder::DriftMonitor& m) {
    const model::Element& element = *built.model.elements[static_cast<std::size_t>(e)];
    const auto names = element.end_force_names();
    std::vector<std::size_t> taken;
    for (std::size_t k = 0; k < names.size(); ++k)
      if (is_shear(names[k].name) || is_moment(names[k].name)) taken.push_back(k);
    const auto [first, added] = first_place.try_emplace(e, places);
    if (added) {
      elements.push_back(e);
      wanted.push_back(taken);
      places += taken.size();
    }
    BaseRows rows;
    for (std::size_t k = 0; k < taken.size(); ++k) {
      const std::string_view name = names[taken[k]].name;
      (is_shear(name) ? rows.shear : rows.moment).push_back(first->second + k);
    }
    const DriftWeights weights = along_drift(element, m);
    if (rows.shear.size() == 2 && rows.moment.size() == 2) {
      rows.shear_weights = weights.shear;
      rows.moment_weights = weights.moment;
    }
    return rows;
  };
  for (const builder::DriftMonitor& m : built.drift_monitors) {
    if (!m.base_element) {
      base_rows_.emplace_back();
      continue;
    }
    BaseRows rows = rows_of(*m.base_element, m);
    for (const Index upper : m.upper_elements) {
      const BaseRows above = rows_of(upper, m);
      rows.upper.push_back({above.shear, above.shear_weights});
    }
    base_rows_.push_back(std::move(rows));
  }
  if (!elements.empty()) {
    // Under moving supports from the total motion: a pier's base moves with its support.
    std::unique_ptr<ElementQuantities> forces =
        element_quantities(built, displacement_terms(system), elements, std::move(wanted));
    if (support_.moving()) forces->read_total_motion(&support_);
    base_forces_ = std::move(forces);
    base_row_.resize(base_forces_->names().size());
  }
}

void RunObservers::record(const integrators::State& state) {
  for (auto& recorder : recorders_) recorder->record(state);
  links_.record(state);
  energy_.record(state);
  if (const Vector* extra = energy_.extra_link_work()) links_.add_work(*extra);
  drifts_.record(state);
  if (base_forces_) record_base_forces(state);
  joints_.record(state);
  for (Observer* observer : extra_) observer->record(state);
  // Energy the integration made up: an unstable step or an unresolved stiff contact, which keeps
  // growing (or stays made up), unlike the few steps in which an explicit method starting from
  // rest shows its half-step velocity lag against an input still near 0. The histories up to
  // here are kept; the run stops rather than go on to a NaN.
  const double created = energy_.terms().created_fraction();
  steps_creating_ = created > kEnergyGrowthLimit ? steps_creating_ + 1 : 0;
  if (steps_creating_ >= kEnergyGrowthSteps)
    stop_above_limit(state.time, created,
                     "the structure holds {:.1f} % more energy than was put in (of the largest "
                     "energy term; limit {:.0f} %): the integration is creating energy, so the "
                     "time step is too large for the integrator or for a stiff link");
  if (passive_links_)
    stop_above_limit(state.time, energy_.terms().link_created_fraction(),
                     "the links have given the structure {:.1f} % of the largest energy term "
                     "(limit {:.0f} %), which passive links cannot do: a link is creating energy, "
                     "so the time step is too large for its stiffness (or its stiffness is "
                     "meaninglessly large)");
}

namespace {
// The resultant of one or two components (one: its magnitude exactly), or with weights their
// projection on one direction.
double resultant(const std::vector<double>& row, const std::vector<std::size_t>& components,
                 const std::vector<double>& weights) {
  if (!weights.empty())
    return std::abs(weights[0] * row[components[0]] + weights[1] * row[components[1]]);
  if (components.size() == 1) return std::abs(row[components[0]]);
  return std::hypot(row[components[0]], row[components[1]]);
}
}  // namespace

void RunObservers::record_base_forces(const integrators::State& state) {
  base_forces_->take(state, base_row_.data());
  for (std::optional<BaseRows>& rows : base_rows_) {
    if (!rows) continue;
    if (!rows->shear.empty())
      rows->peak_shear =
          std::max(rows->peak_shear, resultant(base_row_, rows->shear, rows->shear_weights));
    for (const BaseRows::Shear& upper : rows->upper)
      rows->peak_shear =
          std::max(rows->peak_shear, resultant(base_row_, upper.components, upper.weights));
    if (!rows->moment.empty())
      rows->peak_moment =
          std::max(rows->peak_moment, resultant(base_row_, rows->moment, rows->moment_weights));
  }
}

std::optional<double> RunObservers::base_shear(std::size_t monitor) const {
  const std::optional<BaseRows>& rows = base_rows_.at(monitor);
  if (!rows || rows->shear.empty()) return std::nullopt;
  return rows->peak_shear;
}

std::optional<double> RunObservers::base_moment(std::size_t monitor) const {
  const std::optional<BaseRows>& rows = base_rows_.at(monitor);
  if (!rows || rows->moment.empty()) return std::nullopt;
  return rows->peak_moment;
}

namespace {
// The states a fixed-step run records: the start and each step.
double recorded_states(const builder::AnalysisSpec& analysis) {
  return analysis.step_count() + 1.0;
}
}  // namespace

void reserve_histories(const std::vector<std::unique_ptr<Recorder>>& recorders,
                       const builder::AnalysisSpec& analysis) {
  const double steps = recorded_states(analysis);
  for (const auto& recorder : recorders) recorder->reserve(steps, analysis.duration);
}

void check_histories_fit(const std::vector<std::unique_ptr<Recorder>>& recorders,
                         const builder::AnalysisSpec& analysis,
                         std::optional<std::size_t> available, const std::string& model_path) {
  const double steps = recorded_states(analysis);
  double values = 0.0;
  for (const auto& recorder : recorders) values += recorder->held_values(steps, analysis.duration);
  if (values == 0.0) return;
  // 8 bytes per value held, up to 24 of decimal text (every table's text is formatted before any
  // is written), and a margin of 8 (a history that outgrows its reserved room doubles).
  const double needed = 40.0 * values;
  constexpr double gib = 1024.0 * 1024.0 * 1024.0;
  if (available && needed > static_cast<double>(*available))
    throw InputError(
        model_path, "/recorders",
        fmt::format("recording {:.3g} values over {:.0f} steps needs about {:.1f} GiB, "
                    "more than the {:.1f} GiB of memory available: record fewer "
                    "links or nodes, a shorter duration, or every k-th step (\"every\", "
                    "\"interval\")",
                    values, steps, needed / gib, static_cast<double>(*available) / gib));
}

std::optional<double> DriftResult::corner_ratio() const {
  if (monitor.corners.empty()) return std::nullopt;
  return peak.peak_corner_drift / monitor.height;
}

std::optional<double> DriftResult::corner_amplification() const {
  if (monitor.corners.empty() || !(peak.peak_drift > 0.0)) return std::nullopt;
  return peak.peak_corner_drift / peak.peak_drift;
}

std::optional<double> DriftResult::ductility() const {
  if (!monitor.yield_drift || !monitor.yields) return std::nullopt;
  return peak.peak_drift / *monitor.yield_drift;
}

std::optional<double> DriftResult::elastic_demand_ratio() const {
  if (!monitor.yield_drift || monitor.yields) return std::nullopt;
  return peak.peak_drift / *monitor.yield_drift;
}

std::optional<double> LinkResult::ductility() const {
  if (!yield_deformation || rotational) return std::nullopt;
  return peak_demand() / *yield_deformation;
}

std::optional<double> LinkResult::peak_plastic_deformation() const {
  if (!yield_deformation) return std::nullopt;
  return std::max(0.0, peak_demand() - *yield_deformation);
}

std::optional<double> LinkResult::hysteretic_energy() const {
  if (!yield_deformation || !initial_stiffness || !(*initial_stiffness > 0.0)) return std::nullopt;
  if (role == links::LinkRole::tension && *peak_plastic_deformation() == 0.0) return 0.0;
  // What the run's work left stored in the spring at the end less what it held at the start (a
  // static state's preload or yield, which the run's work does not include).
  return summary.work - viscous.work - (final_stored_energy - initial_stored_energy);
}

bool LinkResult::shear_yields() const {
  return shear && summary.shear && shear->numbers[0].yields();
}

std::optional<double> LinkResult::shear_ductility() const {
  if (!shear_yields() || rotational) return std::nullopt;
  return summary.shear->peak_ductility;
}

std::optional<double> LinkResult::shear_peak_plastic_deformation(std::size_t along) const {
  if (!shear_yields()) return std::nullopt;
  return std::max(
      0.0, summary.shear->peak_deformations[along] - shear->numbers[along].yield_deformation());
}

std::optional<double> LinkResult::shear_hysteretic_energy() const {
  if (!shear_yields()) return std::nullopt;
  double stored = 0.0;  // by the law, without the damping's force
  const ShearSummary& s = *summary.shear;
  for (std::size_t a = 0; a < shear->numbers.size(); ++a) {
    const links::ShearNumbers& numbers = shear->numbers[a];
    stored +=
        numbers.stored_energy(s.final_forces[a] - shear_viscous.force[a], s.final_deformations[a]) -
        numbers.stored_energy(s.initial_forces[a], s.initial_deformations[a]);
  }
  return summary.shear->work - shear_viscous.work - stored;
}

std::optional<double> RunSummary::hysteretic_energy() const {
  std::optional<double> total;
  for (const LinkResult& link : links)
    for (const std::optional<double> dissipated :
         {link.hysteretic_energy(), link.shear_hysteretic_energy()})
      if (dissipated) total = total.value_or(0.0) + *dissipated;
  return total;
}

double RunSummary::contact_created_energy() const {
  double created = 0.0;
  for (const LinkResult& link : links)
    if (link.passive_engagements) created += link.summary.created_energy();
  return created;
}

double RunSummary::contact_created_fraction() const {
  // Below the energies' round-off nothing was put in, and nothing created (a block at rest).
  const double put_in = std::max({std::abs(energy.input), energy.initial, energy.round_off});
  const double created = contact_created_energy();
  return put_in > 0.0 ? created / put_in : (created > 0.0 ? 1.0 : 0.0);
}

std::optional<double> JointResult::margin() const {
  if (!(monitor.seat_width > 0.0)) return std::nullopt;
  return monitor.seat_width - peak.peak_unseating_movement;
}

namespace {
// A drift monitor's hinge: its peak rotation and its yield rotation, its law's or its coupled
// bending's about one tangent; none where it does not yield.
struct HingeRotation {
  double peak = 0.0, yield = 0.0;
};
std::optional<HingeRotation> hinge_rotation(const RunSummary& run,
                                            const builder::DriftMonitor::Curvature& curvature) {
  const LinkResult& hinge = run.links[static_cast<std::size_t>(curvature.hinge)];
  if (curvature.hinge_direction == 0) {
    if (!hinge.yield_deformation) return std::nullopt;
    return HingeRotation{hinge.peak_demand(), *hinge.yield_deformation};
  }
  if (!hinge.shear_yields()) return std::nullopt;
  const auto along = static_cast<std::size_t>(curvature.hinge_direction - 1);
  return HingeRotation{hinge.summary.shear->peak_deformations[along],
                       hinge.shear->numbers[along].yield_deformation()};
}

// Whether the monitor's top node has no lumped mass along its drift (on every equation it moves
// with there): its acceleration is then a static DOF's. Not with a consistent mass.
bool top_without_mass(const assembly::StructuralSystem& system,
                      const builder::DriftMonitor& monitor) {
  const Vector* mass = system.lumped_mass();
  if (!mass) return false;
  const model::DofMap& dofs = system.dofs();
  const std::array<double, 6> along =
      model::over_directions(monitor.along(), false, dofs.dimension());
  for (int d = 0; d < dofs.dofs_per_node(); ++d) {
    if (along[static_cast<std::size_t>(d)] == 0.0) continue;
    for (const model::DofTerm& term : dofs.terms(monitor.top, d))
      if ((*mass)[term.equation] > 0.0) return false;
  }
  return true;
}

// The curvature ductility 1 + theta_p / (phi_y L_p) of a yielded hinge; below yield, the ratio of
// its peak rotation to its yield rotation (M / M_y for a bilinear hinge; below 1, as a
// displacement ductility below 1 is a demand ratio), not 1 as if the section were at yield.
std::optional<double> curvature_ductility(const RunSummary& run,
                                          const builder::DriftMonitor::Curvature& curvature) {
  const std::optional<HingeRotation> rotation = hinge_rotation(run, curvature);
  if (!rotation) return std::nullopt;
  const double plastic = std::max(0.0, rotation->peak - rotation->yield);  // theta_p
  if (plastic > 0.0)
    return 1.0 + plastic / (curvature.yield_curvature * curvature.plastic_hinge_length);
  if (!(rotation->yield > 0.0)) return std::nullopt;
  return rotation->peak / rotation->yield;
}
}  // namespace

RunSummary summarise_run(const builder::BuiltModel& built, const assembly::StructuralSystem& system,
                         const RunObservers& observers, RunStatus status,
                         const integrators::TransientStatistics& statistics,
                         const std::string& integrator, double run_time) {
  const builder::AnalysisSpec& analysis = built.analysis;
  RunSummary run{
      std::move(status),
      integrator,
      analysis.integrator.dissipates(),
      analysis.time_step,
      analysis.duration,
      run_time,
      {analysis.stable_time_step, analysis.time_step_auto, analysis.time_step_defaulted,
       analysis.safety_factor, analysis.time_step_is_record_step, analysis.time_step_rule()},
      system.size(),
      statistics,
      analysis.adaptive};
  const std::vector<results::LinkSummary>& link_summaries = observers.links().summaries();
  for (std::size_t k = 0; k < built.model.links.size(); ++k) {
    const model::Link& link = built.model.links[k];
    const links::LinkLaw& law = system.links().law(static_cast<Index>(k));
    LinkResult result{link.id, law.name(), link.role(), link_summaries[k], link.rotational};
    result.viscous = law.viscous_part();
    result.permanent_deformation = law.permanent_deformation();
    result.slack = law.slack();
    result.passive_engagements =
        link.role() != links::LinkRole::spring && !(link.law && link.law->traits.inertia);
    if ((result.yield_deformation = law.yield_deformation())) {
      // Of a fresh law (this one has yielded): at rest, or a restrainer taut below yield.
      const double at = link.role() == links::LinkRole::tension
                            ? -(result.slack + 0.5 * *result.yield_deformation)
                            : 0.0;
      const std::unique_ptr<links::LinkLaw> fresh = link.make_law(system.link_context(link));
      const LinkSummary& s = link_summaries[k];
      // The start's with a fresh law's history: at rest, or preloaded by a static state.
      const double start = s.initial_force, end = s.final_force - result.viscous.force;
      const std::optional<double> started = fresh->stored_energy(start, s.initial_deformation);
      const std::optional<double> ended = law.stored_energy(end, s.final_deformation);
      const double k0 = fresh->set_trial({at, 0.0, 0.0}).stiffness;
      result.initial_stiffness = k0;
      result.initial_stored_energy = started.value_or(start * start / (2.0 * k0));
      result.final_stored_energy = ended.value_or(end * end / (2.0 * k0));
    }
    result.shear = link.shear;
    result.friction = system.links().has_friction(static_cast<Index>(k));
    result.seated = builder::seated_under_weight(link, built);
    if (const links::CoulombFriction* friction = system.links().friction(static_cast<Index>(k)))
      if (const std::optional<double> radius = friction->radius())
        result.pendulum = {friction->coefficient(), *radius, friction->stick().stiffness};
    if (const links::CoupledShear* shear = system.links().shear(static_cast<Index>(k)))
      result.shear_viscous = shear->viscous_part();
    run.links.push_back(result);
  }
  for (std::size_t k = 0; k < built.drift_monitors.size(); ++k) {
    DriftResult drift{built.drift_monitors[k], observers.drifts().peaks()[k]};
    if (const auto& curvature = drift.monitor.curvature)
      drift.curvature_ductility = curvature_ductility(run, *curvature);
    drift.top_without_mass = top_without_mass(system, drift.monitor);
    if (drift.monitor.yields_with && drift.ductility())
      drift.resultant_ductility = drift.peak.peak_resultant_ratio;
    drift.peak_shear = observers.base_shear(k);
    // A storey's column carries only its storey stiffness: its moments mean nothing.
    if (drift.monitor.kind == builder::DriftKind::pier)
      drift.peak_base_moment = observers.base_moment(k);
    if (const std::optional<Index> link = drift.monitor.shear_link) {
      const LinkSummary& s = run.links[static_cast<std::size_t>(*link)].summary;
      const int along = drift.monitor.shear_link_direction;
      drift.peak_shear = along == 0 ? std::max(s.peak_force, s.peak_tension)
                                    : s.shear->peak_forces[static_cast<std::size_t>(along - 1)];
    }
    run.drifts.push_back(drift);
  }
  for (std::size_t k = 0; k < built.joint_monitors.size(); ++k) {
    const builder::JointMonitor& m = built.joint_monitors[k];
    run.joints.push_back({m, built.model.links[static_cast<std::size_t>(m.link)].id,
                          observers.joints().peaks()[k], m.direction.has_value()});
  }
  run.energy = observers.energy().terms();
  run.worst_balance_error = observers.energy().worst_balance_error();
  run.p_delta = built.model.gravity && built.model.gravity->p_delta.has_value();
  run.warnings = result_warnings(run, built.units);
  return run;
}

void summarise_case(const RunSummary& run, CaseSummary& c) {
  c.status = run.status.completed() ? CaseStatus::completed : CaseStatus::failed;
  c.reason = run.status.completed() ? std::string()
                                    : fmt::format("analysis failed at t = {:.6g}: {}",
                                                  run.status.end_time, run.status.failure);
  c.end_time = run.status.end_time;
  c.steps = static_cast<double>(run.statistics.steps);
  c.warnings = static_cast<double>(run.warnings.size());
  for (const LinkResult& link : run.links) {
    const LinkSummary& s = link.summary;
    // A seated bearing's normal force is its share of the weight, not a pounding force.
    if (link.role == links::LinkRole::spring || link.seated) continue;
    if (link.role == links::LinkRole::tension) {
      if (!c.max_restrainer_force || s.peak_tension > *c.max_restrainer_force) {
        c.max_restrainer_force = s.peak_tension;
        c.max_restrainer_link = s.peak_tension > 0.0 ? link.id : std::string();
      }
      continue;
    }
    c.impacts = c.impacts.value_or(0.0) + s.impacts;
    if (!c.max_pounding_force || s.peak_force > *c.max_pounding_force) {
      c.max_pounding_force = s.peak_force;
      // No link is named for a force of nothing (no contact engaged).
      c.max_pounding_link = s.peak_force > 0.0 ? link.id : std::string();
    }
  }
  for (const JointResult& joint : run.joints) {
    c.max_joint_opening = std::max(c.max_joint_opening.value_or(0.0), joint.peak.peak_opening);
    c.max_seat_movement =
        std::max(c.max_seat_movement.value_or(0.0), joint.peak.peak_seat_movement);
    c.max_deck_acceleration =
        std::max(c.max_deck_acceleration.value_or(0.0), joint.peak.peak_girder_acceleration);
    if (const std::optional<double> margin = joint.margin()) {
      c.min_unseating_margin = std::min(
          c.min_unseating_margin.value_or(std::numeric_limits<double>::infinity()), *margin);
      c.unseated = c.unseated.value_or(false) || joint.unseated();
    }
  }
  for (const DriftResult& drift : run.drifts) {
    c.max_drift_ratio = std::max(c.max_drift_ratio.value_or(0.0), drift.largest_ratio());
    if (const std::optional<double> acceleration = drift.top_acceleration())
      c.max_top_acceleration = std::max(c.max_top_acceleration.value_or(0.0), *acceleration);
    c.max_residual_drift_ratio =
        std::max(c.max_residual_drift_ratio.value_or(0.0), std::abs(drift.residual_ratio()));
    if (const std::optional<double> ductility = drift.largest_ductility())
      c.max_ductility = std::max(c.max_ductility.value_or(0.0), *ductility);
  }
  c.energy_balance_error = run.worst_balance_error;
  c.run_time_s = run.run_time_s;
}

}  // namespace pound::results
