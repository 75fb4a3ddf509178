#include "builder/build.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <optional>

#include "assembly/modal_analysis.hpp"
#include "assembly/structural_system.hpp"
#include "builder/element_resolver.hpp"
#include "builder/excitations.hpp"
#include "builder/generators.hpp"
#include "builder/link_resolver.hpp"
#include "builder/start_check.hpp"
#include "core/errors.hpp"
#include "integrators/central_difference.hpp"
#include "integrators/newmark.hpp"

namespace pound::builder {

std::unique_ptr<integrators::Integrator> make_integrator(const AnalysisSpec& analysis) {
  const integrators::ConvergenceTest test{analysis.relative_tolerance, analysis.absolute_tolerance,
                                          analysis.max_iterations};
  return analysis.integrator.make(test);
}

namespace {

// More steps than this cannot be counted (the step loop's count would overflow, and a double no
// longer holds every whole number) and would take decades anyway.
constexpr double kMostSteps = 1e15;

// A time step of 1e-300 or a duration of 1e300 would otherwise "complete" with no step taken.
void check_step_count(const AnalysisSpec& analysis, const std::string& source) {
  const double steps = analysis.step_count();
  if (!(steps <= kMostSteps))
    throw InputError(source, "/analysis/time_step",
                     fmt::format("{:g} over a duration of {:g} is {:.3g} steps, more than the "
                                 "{:g} a run can take",
                                 analysis.time_step, analysis.duration, steps, kMostSteps));
}

// A given step longer than the whole analysis is one step past its end, whose response nobody
// could read (verify refuses the same). An "auto" step is not checked: the user gave none.
void check_step_within_duration(const AnalysisSpec& analysis, const std::string& source) {
  if (analysis.duration > 0.0 && analysis.time_step > analysis.duration)
    throw InputError(source, "/analysis/time_step",
                     fmt::format("{:g} is longer than the analysis's duration of {:g}: the run "
                                 "would be a single step past its end (a time step is a small "
                                 "fraction of the duration, at most a record's sampling "
                                 "interval)",
                                 analysis.time_step, analysis.duration));
}

// Adaptive steps are time_step x 2^k between min_time_step and max_time_step: the first step
// must not be below the shortest, and some step of that grid must lie between the two (a
// min_time_step of 0.003 over a time_step of 0.002 left the run cutting a step of 0.004 for ever).
void check_adaptive_steps(const AnalysisSpec& analysis, const std::string& source) {
  if (!analysis.adaptive) return;
  const integrators::AdaptiveStepping& adaptive = *analysis.adaptive;
  if (adaptive.min_time_step > analysis.time_step)
    throw InputError(source, "/analysis/adaptive/min_time_step",
                     fmt::format("{:g} is above the time step {:g}, the first step an adaptive run "
                                 "takes: give a shortest step at most the time step",
                                 adaptive.min_time_step, analysis.time_step));
  const double shortest = adaptive.shortest(analysis.time_step),
               longest = adaptive.longest(analysis.time_step);
  if (shortest > longest)
    throw InputError(
        source, "/analysis/adaptive",
        fmt::format("no step of the time step {:g} times a power of 2 lies between "
                    "min_time_step {:g} and max_time_step {:g} (the steps an adaptive "
                    "run takes): widen the range",
                    analysis.time_step, adaptive.min_time_step, adaptive.max_time_step));
}

// The shortest sampling step of the model's records (infinite without records).
double shortest_record_step(const model::Model& model) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const model::UniformExcitation& e : model.excitations)
    shortest = std::min(shortest, e.motion.time_step);
  for (const model::SupportExcitation& e : model.support_excitations)
    shortest = std::min(shortest, e.motion.time_step);
  return shortest;
}

// A hard contact's impulse and its restitution are imposed through Newmark's update, which needs
// beta >= 1/4: with linear acceleration (beta = 1/6) a mass rebounding off a stop made up 25-100 %
// of its energy and a block on a hard floor sank 1 mm in 0.6 s (audit 70).
void refuse_hard_contacts_below_average_acceleration(const AnalysisSpec& analysis,
                                                     const model::Model& model,
                                                     const std::string& source) {
  const std::map<std::string, double> parameters = analysis.integrator.values();
  const auto beta = parameters.find("beta");
  if (beta == parameters.end() || beta->second >= 0.25) return;
  for (const model::Link& link : model.links)
    if (link.law && link.law->traits.constraint)
      throw InputError(
          source, "/analysis/integrator",
          fmt::format("{} (beta = {:.4g} < 1/4) cannot impose the hard contact '{}': its impulse "
                      "needs beta >= 1/4 (newmark_average_acceleration, hht, generalized_alpha) "
                      "or central difference",
                      analysis.integrator.label(), beta->second, link.id));
}

// An implicit step makes a hard contact's force an impulse between masses (Newmark): a row that
// moves a massless DOF has none to give it to.
void check_implicit_hard_contacts(const model::Model& model, assembly::StructuralSystem& system,
                                  const std::string& source) {
  const integrators::LinkSet& links = system.links();
  const Vector* lumped = system.lumped_mass();
  if (!lumped) return;
  const std::vector<char> impulsive = links.impulsive_hard_contact_rows(lumped);
  for (Index k = 0; k < links.count(); ++k) {
    const auto row = static_cast<std::size_t>(links.row(k));
    if (!links.law(k).is_hard_contact() || impulsive[row]) continue;
    const model::DofMap& dofs = system.dofs();
    const Index rows = links.rows(k);
    const auto moves = [&](Index equation) {
      for (Index r = 0; r < rows; ++r)
        if (links.connectivity().coeff(links.row(k) + r, equation) != 0.0) return true;
      return false;
    };
    for (Index node = 0; node < static_cast<Index>(model.nodes.size()); ++node)
      for (int d = 0; d < dofs.dofs_per_node(); ++d) {
        const Index equation = dofs.own_equation(node, d);
        if (equation < 0 || (*lumped)[equation] > 0.0 || !moves(equation)) continue;
        throw InputError(
            source, "/analysis/integrator",
            fmt::format("the hard contact '{}' pushes node '{}', which has no mass in direction "
                        "{}: an implicit step gives a hard contact's force as an impulse between "
                        "masses; add a mass there, or use a penalty law (extended_penalty) for "
                        "this contact",
                        k < static_cast<Index>(model.links.size())
                            ? model.links[static_cast<std::size_t>(k)].id
                            : fmt::format("#{}", k),
                        model.nodes[static_cast<std::size_t>(node)].id,
                        model::direction(d, model.dimension).words));
      }
  }
}

// A Hertz-type contact (hertz, hertz_damp, jankowski, bilinear_impact) has no stiffness until it
// touches: the stable step "in contact" cannot see it, and "auto" took steps longer than its
// impacts (a run of 1.7 s steps completed with a force 2,400 x the exact one). With a step given
// as a number, pound check and the run compare it with the impact's duration.
void refuse_auto_step_past_soft_contacts(const model::Model& model, const std::string& source) {
  std::vector<std::string> soft;
  for (const model::Link& link : model.links)
    if (link.role() == links::LinkRole::contact && link.law &&
        !link.law->traits.stiff_at_first_touch && !link.law->traits.constraint)
      soft.push_back(link.id);
  if (soft.empty()) return;
  throw InputError(
      source, "/analysis/time_step",
      fmt::format("central difference cannot find a stable step from the contact law of link "
                  "'{}'{}, which has no stiffness until it touches: give time_step as a number "
                  "(pound check compares it with the impact's duration), or use an implicit "
                  "integrator",
                  soft.front(),
                  soft.size() > 1 ? fmt::format(" (and {} more)", soft.size() - 1) : ""));
}

}  // namespace

std::optional<double> conditional_stable_step(const integrators::IntegratorChoice& integrator,
                                              assembly::StructuralSystem& system) {
  const std::optional<double> limit = integrator.stability_limit();
  const Vector* lumped = system.lumped_mass();
  if (integrator.is_explicit() || !limit || !lumped || !(lumped->array() > 0.0).all())
    return std::nullopt;
  try {
    const double omega = integrators::highest_frequency(system, true);
    if (omega > 0.0) return *limit / omega;
  } catch (const std::domain_error&) {
    // Past the number range: the run's own checks say what overflows.
  }
  return std::nullopt;
}

namespace {

// Linear acceleration (and any Newmark with beta < gamma / 2) grows without bound past its
// "<step> is above the stable limit <limit>", with as many digits as tell them apart (at six a
// step just past its limit read "0.0703891 is above the stable limit 0.0703891").
std::string step_above_limit(double step, double limit) {
  if (fmt::format("{:.6g}", step) != fmt::format("{:.6g}", limit))
    return fmt::format("{:.6g} is above the stable limit {:.6g}", step, limit);
  return fmt::format("{} is above the stable limit {}", step, limit);
}

// limit of omega dt, as central difference does past its step: the same refusal. Its damping
// term is implicit, so (with gamma = 1/2) the limit does not fall with damping.
void refuse_step_past_implicit_limit(const AnalysisSpec& analysis,
                                     assembly::StructuralSystem& system,
                                     const std::string& source) {
  const std::optional<double> limit = conditional_stable_step(analysis.integrator, system);
  if (!limit || !(analysis.longest_step() > *limit)) return;
  // An adaptive run's longest step: its max_time_step (16 steps by default) that passes.
  const bool adaptive = analysis.adaptive && analysis.time_step <= *limit;
  throw InputError(
      source, adaptive ? "/analysis/adaptive" : "/analysis/time_step",
      fmt::format("{}{} of {} ({:.4g} / omega_max with the links in contact): past it the "
                  "response grows without bound; use a smaller step, or "
                  "newmark_average_acceleration, stable at any step",
                  adaptive ? "the longest adaptive step, " : "",
                  step_above_limit(analysis.longest_step(), *limit), analysis.integrator.label(),
                  *analysis.integrator.stability_limit()));
}

}  // namespace

void settle_time_step(AnalysisSpec& analysis, const model::Model& model,
                      assembly::StructuralSystem& system, const std::string& source) {
  if (!analysis.integrator.is_explicit()) {
    check_implicit_hard_contacts(model, system, source);
    refuse_hard_contacts_below_average_acceleration(analysis, model, source);
    refuse_step_past_implicit_limit(analysis, system, source);
    return;
  }
  // Implicit methods carry massless DOFs (contact points, rotations) as static equations; the
  // explicit update divides by each DOF's own mass.
  const Vector* lumped = system.lumped_mass();
  if (!lumped && system.dofs().has_ties())
    throw InputError(source, "/analysis/integrator",
                     "central difference needs a diagonal mass, and this model's constraints "
                     "couple it (a mass tied to its master through a lever arm: a rigid "
                     "diaphragm's or rigid beam's slave away from its master); use an implicit "
                     "integrator, or equal_dofs / rigid_bar ties, which keep the mass diagonal");
  if (!lumped)
    throw InputError(source, "/analysis/integrator",
                     "central difference needs lumped masses, and this model has consistent "
                     "element masses: set \"mass\": \"lumped\" on its elements, or use an implicit "
                     "integrator");
  for (Index node = 0; node < static_cast<Index>(model.nodes.size()); ++node)
    for (int d = 0; d < system.dofs().dofs_per_node(); ++d)
      if (const Index row = system.dofs().own_equation(node, d);
          row >= 0 && !((*lumped)[row] > 0.0))
        throw InputError(source, "/analysis/integrator",
                         fmt::format("central difference needs a lumped mass on every free DOF, "
                                     "and node '{}' has none in direction {}: add a mass there, "
                                     "or use an implicit integrator",
                                     model.nodes[static_cast<std::size_t>(node)].id,
                                     model::direction(d, model.dimension).words));
  double limit = 0.0;
  try {
    limit = integrators::stable_time_step(system, true);
  } catch (const std::domain_error& error) {
    throw InputError(source, "/analysis/integrator", error.what());
  }
  // Nothing that vibrates (masses held only by hard contacts): no limit to report.
  if (std::isfinite(limit)) analysis.stable_time_step = limit;
  if (analysis.time_step_auto) {
    refuse_auto_step_past_soft_contacts(model, source);
    analysis.time_step = analysis.safety_factor * limit;
    // A step longer than a record's samples would step over its peaks.
    const double record_step = shortest_record_step(model);
    if (record_step < analysis.time_step) {
      analysis.time_step = record_step;
      analysis.time_step_is_record_step = true;
    }
    if (!std::isfinite(analysis.time_step))
      throw InputError(source, "/analysis/time_step",
                       "\"auto\" finds no stable step to take: nothing in the model vibrates at a "
                       "frequency above round-off (stiffnesses zero or vanishing against the "
                       "masses) and no record sets one; give the step as a number");
    check_step_count(analysis, source);
  } else if (analysis.time_step > limit) {
    throw InputError(source, "/analysis/time_step",
                     fmt::format("{} of central difference (2 / omega_max with the links in "
                                 "contact, less with damping); use \"auto\" or a smaller step",
                                 step_above_limit(analysis.time_step, limit)));
  }
}

integrators::TransientSettings make_transient_settings(const AnalysisSpec& analysis) {
  return {.time_step = analysis.time_step,
          .end_time = analysis.duration,
          .max_step_cuts = analysis.max_step_cuts,
          .max_steps = analysis.max_steps,
          .time_limit = analysis.time_limit,
          .adaptive = analysis.adaptive};
}

namespace {

// a1 K alone gives a mode of frequency w the ratio a1 w / 2, more in every higher mode: past 1 at
// the first, nothing in the structure can vibrate, and far past it the damping swamps the mass in
// the step's matrix (at a1 = 1e15 s on the bundled bridge the girders' mass is lost to round-off).
// Models whose modes cannot be found (none with mass, a massless mechanism) are not checked.
void check_stiffness_damping(double a1, const model::Model& model, const std::string& time,
                             const std::string& source) {
  if (!(a1 > 0.0)) return;
  std::vector<double> first;
  try {
    first = assembly::natural_periods(assembly::StructuralSystem(model), 1);
  } catch (const std::exception&) {
    return;  // the run's own checks name what is wrong with such a model
  }
  if (first.empty()) return;
  const double ratio = a1 * std::numbers::pi / first[0];
  if (ratio <= 1.0) return;
  // Near the largest double the ratio overflows: say so rather than print "inf".
  const std::string ratio_text =
      std::isfinite(ratio) ? fmt::format("{:.3g}", ratio) : "over 1e308 (too large to represent)";
  throw InputError(
      source, "/damping/stiffness_coefficient",
      fmt::format("a1 = {:.3g} {} gives the first mode (period {:.3g} {}) a damping ratio of {} "
                  "from the stiffness-proportional part alone, above critical (1): no mode of the "
                  "structure could vibrate. A ratio xi at period T takes a1 = xi T / pi ({:.3g} {} "
                  "for 5 % at the first mode), or give 'ratio' with 'periods' or 'modes'",
                  a1, time, first[0], time, ratio_text, 0.05 * first[0] / std::numbers::pi, time));
}

// a0 = 2 xi w1 w2 / (w1 + w2), a1 = 2 xi / (w1 + w2): the ratio xi at both frequencies.
model::RayleighDamping rayleigh_damping(const DampingSpec& damping, const model::Model& model,
                                        const std::string& time, const std::string& source) {
  if (damping.mass_coefficient || damping.stiffness_coefficient) {
    check_stiffness_damping(damping.stiffness_coefficient.value_or(0.0), model, time, source);
    return {damping.mass_coefficient.value_or(0.0), damping.stiffness_coefficient.value_or(0.0)};
  }
  std::array<double, 2> periods{};
  if (damping.periods) {
    periods = *damping.periods;
  } else {
    const int highest = std::max((*damping.modes)[0], (*damping.modes)[1]);
    const assembly::StructuralSystem system(model);
    std::vector<double> found;
    try {
      found = assembly::natural_periods(system, highest);
    } catch (const assembly::ModalAnalysisError& error) {
      throw InputError(
          source, "/damping/modes",
          fmt::format("the modes for Rayleigh damping cannot be found: {}", error.what()));
    }
    if (static_cast<int>(found.size()) < highest) {
      const auto dofs_with_mass =
          static_cast<Index>((system.mass_matrix().diagonal().array() > 0.0).count());
      throw InputError(
          source, "/damping/modes",
          fmt::format("mode {} asked for, the model has {} vibration mode{}: {}", highest,
                      found.size(), found.size() == 1 ? "" : "s",
                      assembly::fewer_modes_reason(system.size(), dofs_with_mass, highest,
                                                   static_cast<Index>(found.size()))));
    }
    periods = {found[static_cast<std::size_t>((*damping.modes)[0] - 1)],
               found[static_cast<std::size_t>((*damping.modes)[1] - 1)]};
  }
  const double w1 = 2.0 * std::numbers::pi / periods[0], w2 = 2.0 * std::numbers::pi / periods[1];
  return {2.0 * damping.ratio * w1 * w2 / (w1 + w2), 2.0 * damping.ratio / (w1 + w2)};
}

}  // namespace

namespace {

// Generators make scenes of one dimension only.
void check_generator_dimensions(const ModelSpec& spec) {
  if (spec.dimension != 1 && !spec.rod_pairs.empty())
    throw InputError(spec.source, fmt::format("/generators/{}", spec.rod_pair_generator_index[0]),
                     "rod_pair needs a 1-D scene (\"dimension\": 1)");
  for (const AdjacentBuildingsSpec& g : spec.building_pairs)
    if (spec.dimension == 1)
      throw InputError(spec.source, fmt::format("/generators/{}", g.generator_index),
                       "adjacent_buildings needs a 2-D or 3-D scene (\"dimension\": 2 or 3)");
  for (const GirderBridgeSpec& g : spec.bridges) {
    if (spec.dimension == 1)
      throw InputError(spec.source, fmt::format("/generators/{}", g.generator_index),
                       "girder_bridge needs a 2-D or 3-D scene (\"dimension\": 2 or 3)");
  }
}

// Masses, supports, loads and initial velocities: each names a node.
void resolve_nodal_data(const Resolver& resolver, model::Model& model) {
  const ModelSpec& spec = resolver.spec();
  const ModelSpec& user = resolver.user_spec();
  for (std::size_t k = 0; k < spec.masses.size(); ++k) {
    const MassSpec& mass = spec.masses[k];
    model.masses.push_back({resolver.node(mass.node, fmt::format("/masses/{}/node", k)), mass.mass,
                            mass.rotary_inertia,
                            mass.mass_damping
                                ? std::optional(model::RayleighDamping{*mass.mass_damping, 0.0})
                                : std::nullopt});
  }
  const Origin support = origin_of(user.supports.size(), "supports", spec.generated_from.supports);
  for (std::size_t k = 0; k < spec.supports.size(); ++k) {
    const SupportSpec& s = spec.supports[k];
    model.supports.push_back({resolver.node(s.node, support(k) + "/node"), s.fixed});
  }
  const Origin load = origin_of(user.loads.size(), "loads", spec.generated_from.loads);
  for (std::size_t k = 0; k < spec.loads.size(); ++k)
    model.loads.push_back({resolver.node(spec.loads[k].node, load(k) + "/node"),
                           {spec.loads[k].x, spec.loads[k].y, spec.loads[k].z}});
  const Origin velocity = origin_of(user.initial_velocities.size(), "initial_velocities",
                                    spec.generated_from.initial_velocities);
  if (!spec.initial_velocities.empty()) model.initial_velocity.assign(model.nodes.size(), {});
  std::map<Index, std::size_t> given;  // node -> the entry that gave its velocity
  for (std::size_t k = 0; k < spec.initial_velocities.size(); ++k) {
    const InitialVelocitySpec& v = spec.initial_velocities[k];
    const Index node = resolver.node(v.node, velocity(k) + "/node");
    if (auto [first, fresh] = given.emplace(node, k); !fresh)
      resolver.fail(velocity(k) + "/node",
                    fmt::format("node '{}' already has an initial velocity (at {})", v.node,
                                velocity(first->second)));
    model.initial_velocity[static_cast<std::size_t>(node)] = {v.x, v.y, v.z};
  }
}

model::ConstraintKind constraint_kind(ConstraintKind kind) {
  switch (kind) {
    case ConstraintKind::rigid_diaphragm:
      return model::ConstraintKind::rigid_diaphragm;
    case ConstraintKind::rigid_beam:
      return model::ConstraintKind::rigid_beam;
    case ConstraintKind::rigid_bar:
      return model::ConstraintKind::rigid_bar;
    case ConstraintKind::equal_dofs:
      break;
  }
  return model::ConstraintKind::equal_dofs;
}

// The first tied direction of `constraint` that `flags` (a support's, a velocity's) holds.
std::optional<int> first_shared(const model::Constraint& constraint,
                                const std::array<bool, 6>& flags, int dimension) {
  const std::array<bool, 6> tied = model::tied_directions(constraint, dimension);
  for (int d = 0; d < model::direction_count(dimension); ++d)
    if (tied[static_cast<std::size_t>(d)] && flags[static_cast<std::size_t>(d)]) return d;
  return std::nullopt;
}

// Slaves tied once, to a master no constraint ties (no chains), in a diaphragm's plane.
void check_constraint_nodes(const Resolver& resolver, const model::Model& model) {
  std::map<Index, std::string> slave_at, master_at;  // node -> where it is tied / a master
  for (std::size_t k = 0; k < model.constraints.size(); ++k)
    master_at.emplace(model.constraints[k].master, fmt::format("/constraints/{}", k));
  for (std::size_t k = 0; k < model.constraints.size(); ++k) {
    const model::Constraint& c = model.constraints[k];
    const model::Coordinates& master = model.nodes[static_cast<std::size_t>(c.master)].position;
    for (std::size_t i = 0; i < c.slaves.size(); ++i) {
      const std::string path = fmt::format("/constraints/{}/slaves/{}", k, i);
      const std::string& id = model.nodes[static_cast<std::size_t>(c.slaves[i])].id;
      if (c.slaves[i] == c.master) resolver.fail(path, fmt::format("'{}' is the master", id));
      if (const auto [first, fresh] = slave_at.emplace(c.slaves[i], path); !fresh)
        resolver.fail(path, fmt::format("node '{}' is already tied at {}; a node follows one "
                                        "master",
                                        id, first->second));
      if (const auto master_of = master_at.find(c.slaves[i]); master_of != master_at.end())
        resolver.fail(path, fmt::format("node '{}' is the master of {}: tie its slaves to '{}' "
                                        "directly (a tie of a tie is not taken)",
                                        id, master_of->second,
                                        model.nodes[static_cast<std::size_t>(c.master)].id));
      const model::Coordinates& at = model.nodes[static_cast<std::size_t>(c.slaves[i])].position;
      const double size = std::hypot(at[0] - master[0], at[1] - master[1], at[2] - master[2]);
      if (!std::isfinite(size))
        resolver.fail(path, fmt::format("node '{}' is farther from its master than numbers reach "
                                        "(the lever arm overflows)",
                                        id));
      if (c.kind != model::ConstraintKind::rigid_diaphragm) continue;
      const auto n = static_cast<std::size_t>(c.normal);
      const double out = at[n] - master[n];
      if (std::abs(out) > 1e-9 * (1.0 + size))
        resolver.fail(
            path, fmt::format("node '{}' is {:.6g} off the diaphragm's plane through "
                              "its master '{}' (its {} is {:.6g}, the master's {:.6g}): "
                              "a rigid diaphragm ties the nodes of one floor",
                              id, std::abs(out), model.nodes[static_cast<std::size_t>(c.master)].id,
                              "xyz"[n], at[n], master[n]));
    }
  }
}

// A tied DOF is not an unknown: neither a slave nor its master's tied DOFs take a support (the
// slave would not follow the ground, nor the floor its master), nor a slave an initial velocity.
void check_constraint_supports(const Resolver& resolver, const model::Model& model) {
  const ModelSpec& spec = resolver.spec();
  const Origin support =
      origin_of(resolver.user_spec().supports.size(), "supports", spec.generated_from.supports);
  for (std::size_t k = 0; k < model.constraints.size(); ++k) {
    const model::Constraint& c = model.constraints[k];
    for (std::size_t s = 0; s < model.supports.size(); ++s) {
      const model::Support& held = model.supports[s];
      const std::optional<int> d = first_shared(c, held.fixed, model.dimension);
      const bool slave = std::ranges::find(c.slaves, held.node) != c.slaves.end();
      if (!d || (!slave && held.node != c.master)) continue;
      const std::string& id = model.nodes[static_cast<std::size_t>(held.node)].id;
      const char* direction = model::direction(*d, model.dimension).words;
      resolver.fail(support(s) + "/fix",
                    slave ? fmt::format("node '{}' is tied to its master along {} by "
                                        "/constraints/{}: it moves with its master; leave out "
                                        "the support, or the node from the constraint",
                                        id, direction, k)
                          : fmt::format("node '{}' is the master of /constraints/{}, which ties "
                                        "{}: its slaves move with it, and a held master holds "
                                        "them; support the slaves (or their columns) themselves",
                                        id, k, direction));
    }
    if (model.initial_velocity.empty()) continue;
    for (Index slave : c.slaves) {
      const model::Coordinates& v = model.initial_velocity[static_cast<std::size_t>(slave)];
      const std::array<bool, 6> moving{v[0] != 0.0, v[1] != 0.0, v[2] != 0.0};
      if (const std::optional<int> d = first_shared(c, moving, model.dimension))
        resolver.fail(fmt::format("/constraints/{}", k),
                      fmt::format("node '{}' has an initial velocity along {}, which its tie "
                                  "gives from the master's: give the master's velocity",
                                  model.nodes[static_cast<std::size_t>(slave)].id,
                                  model::direction(*d, model.dimension).words));
    }
  }
}

std::vector<model::Constraint> resolve_constraints(const Resolver& resolver) {
  const ModelSpec& spec = resolver.spec();
  std::vector<model::Constraint> constraints;
  for (std::size_t k = 0; k < spec.constraints.size(); ++k) {
    const ConstraintSpec& c = spec.constraints[k];
    model::Constraint& made = constraints.emplace_back();
    made.kind = constraint_kind(c.type);
    made.master = resolver.node(c.master, fmt::format("/constraints/{}/master", k));
    for (std::size_t i = 0; i < c.slaves.size(); ++i)
      made.slaves.push_back(
          resolver.node(c.slaves[i], fmt::format("/constraints/{}/slaves/{}", k, i)));
    made.tied = c.dofs;
    made.normal = c.normal;
  }
  return constraints;
}

// A model that is one rod pair and nothing else: its exact solution applies.
std::optional<RodPairSpec> sole_rod_pair(const ModelSpec& user) {
  const bool only_rod_pair =
      user.rod_pairs.size() == 1 && user.nodes.empty() && user.building_pairs.empty() &&
      user.bridges.empty() && user.loads.empty() && user.elements.empty() && user.masses.empty() &&
      user.supports.empty() && user.initial_velocities.empty() && user.links.empty();
  if (!only_rod_pair) return std::nullopt;
  return user.rod_pairs.front();
}

model::Gravity gravity(const GravitySpec& spec, const UnitsSpec& units) {
  model::Gravity gravity{.direction = model::to_coordinates(spec.direction),
                         .acceleration = spec.acceleration.value_or(units.gravity())};
  if (spec.p_delta == PDeltaKind::chord) gravity.p_delta = model::GeometricStiffness::chord;
  if (spec.p_delta == PDeltaKind::consistent)
    gravity.p_delta = model::GeometricStiffness::consistent;
  return gravity;
}

}  // namespace

BuiltModel build(const ModelSpec& user_spec, const std::vector<model::GroundMotion>& motions,
                 const std::vector<std::optional<model::GroundMotion>>& second_motions) {
  check_generator_dimensions(user_spec);
  const ModelSpec spec = expand(user_spec);
  const Resolver resolver(user_spec, spec);
  BuiltModel built;
  model::Model& model = built.model;
  model.dimension = spec.dimension;
  for (const NodeSpec& node : spec.nodes)
    model.nodes.push_back({node.id, {node.x, node.y, node.z}});
  const Origin node_origin = origin_of(user_spec.nodes.size(), "nodes", spec.generated_from.nodes);
  for (std::size_t k = 0; k < spec.nodes.size(); ++k) built.node_origins.push_back(node_origin(k));
  model.elements = resolve_elements(resolver, model);
  resolve_nodal_data(resolver, model);
  model.constraints = resolve_constraints(resolver);
  check_constraint_nodes(resolver, model);
  check_constraint_supports(resolver, model);
  model.links = resolve_links(resolver, model);
  built.analysis = spec.analysis;
  ExcitationScaling scaling = resolve_excitations(resolver, motions, second_motions, model);
  built.excitation_factors = std::move(scaling.factors);
  built.excitation_peaks = std::move(scaling.peaks);
  built.uniform_excitation_sources = std::move(scaling.uniform_sources);
  built.units = spec.units.names();
  fit_analysis_to_records(built.analysis, model);
  if (!built.analysis.time_step_auto) {
    check_step_count(built.analysis, spec.source);
    check_step_within_duration(built.analysis, spec.source);
    check_adaptive_steps(built.analysis, spec.source);
  }
  if (spec.damping) {
    try {
      model.damping = rayleigh_damping(*spec.damping, model, spec.units.time, spec.source);
    } catch (const assembly::NotPositiveDefinite& failure) {
      throw not_held_error(built, model::DofMap(model), failure,
                           "the modal analysis for Rayleigh damping (/damping/modes)", spec.source);
    }
  }
  add_link_damping(resolver, model.damping, model.links);
  if (spec.gravity) {
    model.gravity = gravity(*spec.gravity, spec.units);
    built.analysis.static_initial_state = true;  // the record starts on the loaded structure
  }
  built.recorders = resolve_recorders(resolver, model.links.size());
  built.drift_monitors = resolve_drift_monitors(resolver);
  built.joint_monitors = resolve_joint_monitors(resolver);
  built.node_index = resolver.node_index();
  built.link_index = resolver.link_index();
  const Origin link_origin = origin_of(user_spec.links.size(), "links", spec.generated_from.links);
  for (std::size_t k = 0; k < model.links.size(); ++k) built.link_origins.push_back(link_origin(k));
  built.sole_rod_pair = sole_rod_pair(user_spec);
  return built;
}

ModelSize model_size(const ModelSpec& spec) {
  ModelSize size;
  auto add = [&size](std::size_t nodes, const std::string& path) {
    size.nodes += nodes;
    if (nodes > size.largest_nodes) {
      size.largest_nodes = nodes;
      size.largest_path = path;
    }
  };
  add(spec.nodes.size(), "/nodes");
  for (std::size_t k = 0; k < spec.rod_pairs.size(); ++k)
    add(static_cast<std::size_t>(spec.rod_pairs[k].left.elements) +
            static_cast<std::size_t>(spec.rod_pairs[k].right.elements) + 2,
        fmt::format("/generators/{}", spec.rod_pair_generator_index.at(k)));
  for (const AdjacentBuildingsSpec& pair : spec.building_pairs)
    add(2 * (pair.left.storeys.size() + pair.right.storeys.size() + 2),
        fmt::format("/generators/{}", pair.generator_index));
  for (const GirderBridgeSpec& bridge : spec.bridges) {
    const std::size_t spans = bridge.spans.size();
    add(spans * (static_cast<std::size_t>(bridge.girder.elements) + 3) +
            (spans + 1) * (static_cast<std::size_t>(bridge.pier.elements) + 3) + 8,
        fmt::format("/generators/{}", bridge.generator_index));
  }
  for (const BlockSpec& block : spec.blocks)
    add((static_cast<std::size_t>(block.columns) + 1) * (static_cast<std::size_t>(block.rows) + 1),
        fmt::format("/generators/{}", block.generator_index));
  for (const SurfaceSpec& surface : spec.surfaces)
    add(1, fmt::format("/surfaces/{}", surface.index));
  size.dofs = size.nodes * (spec.dimension == 1 ? 1 : spec.dimension == 2 ? 3 : 6);
  return size;
}

bool seated_under_weight(const model::Link& link, const BuiltModel& built) {
  const auto along_axis = [&](const model::Coordinates& force) {
    double dot = 0.0;
    for (std::size_t d = 0; d < force.size(); ++d) dot += force[d] * link.axis[d];
    return dot != 0.0;
  };
  const model::Model& model = built.model;
  const bool pressed =
      (model.gravity && model.gravity->acceleration != 0.0 &&
       along_axis(model.gravity->direction)) ||
      std::any_of(model.loads.begin(), model.loads.end(),
                  [&](const model::NodalLoad& load) { return along_axis(load.force); });
  return link.friction && !(link.gap > 0.0) && built.analysis.static_initial_state && pressed;
}

}  // namespace pound::builder
