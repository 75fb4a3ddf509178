#include "builder/build.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "assembly/modal_analysis.hpp"
#include "assembly/structural_system.hpp"
#include "builder/element_resolver.hpp"
#include "builder/generators.hpp"
#include "core/errors.hpp"
#include "integrators/central_difference.hpp"
#include "integrators/newmark.hpp"
#include "links/law_registry.hpp"

namespace pound::builder {
namespace {

class Resolver {
 public:
  Resolver(const ModelSpec& spec) : spec_(spec) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw InputError(spec_.source, path, what);
  }

  // Registers ids of one array; `origin(k)` names where entry k came from.
  template <typename Item, typename Origin>
  std::map<std::string, Index> index_ids(const std::vector<Item>& items, const char* kind,
                                         Origin origin) const {
    std::map<std::string, Index> index;
    for (std::size_t k = 0; k < items.size(); ++k) {
      auto [it, inserted] = index.emplace(items[k].id, static_cast<Index>(k));
      if (!inserted)
        fail(origin(k), fmt::format("duplicate {} id '{}' (also at {})", kind, items[k].id,
                                    origin(static_cast<std::size_t>(it->second))));
    }
    return index;
  }

  Index node(const std::map<std::string, Index>& nodes, const std::string& id,
             const std::string& path) const {
    auto found = nodes.find(id);
    if (found == nodes.end()) fail(path, fmt::format("node '{}' does not exist", id));
    return found->second;
  }

 private:
  const ModelSpec& spec_;
};

// Path of entry k of an expanded array: the user's own entries keep their path; generated ones
// point at their generator.
std::function<std::string(std::size_t)> origin_of(std::size_t user_count, const char* array,
                                                  const std::vector<std::string>& generated_from) {
  return [user_count, array, &generated_from](std::size_t k) {
    if (k < user_count) return fmt::format("/{}/{}", array, k);
    return generated_from[k - user_count];
  };
}

}  // namespace

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
  const double steps = analysis.duration / analysis.time_step;
  if (!(steps <= kMostSteps))
    throw InputError(source, "/analysis/time_step",
                     fmt::format("{:g} over a duration of {:g} is {:.3g} steps, more than the "
                                 "{:g} a run can take",
                                 analysis.time_step, analysis.duration, steps, kMostSteps));
}

}  // namespace

void settle_time_step(AnalysisSpec& analysis, const model::Model& model,
                      assembly::StructuralSystem& system, const std::string& source) {
  if (!analysis.integrator.is_explicit()) return;
  // Implicit methods carry massless DOFs (contact points, rotations) as static equations; the
  // explicit update divides by each DOF's own mass.
  const Vector* lumped = system.lumped_mass();
  if (!lumped)
    throw InputError(source, "/analysis/integrator",
                     "central difference needs lumped masses, and this model has consistent "
                     "element masses: set \"mass\": \"lumped\" on its elements, or use an implicit "
                     "integrator");
  for (Index node = 0; node < static_cast<Index>(model.nodes.size()); ++node)
    for (int d = 0; d < system.dofs().dofs_per_node(); ++d)
      if (const Index row = system.dofs().equation(node, d); row >= 0 && !((*lumped)[row] > 0.0))
        throw InputError(
            source, "/analysis/integrator",
            fmt::format("central difference needs a lumped mass on every free DOF, "
                        "and node '{}' has none in direction {}: add a mass there, "
                        "or use an implicit integrator",
                        model.nodes[static_cast<std::size_t>(node)].id, model::direction_name(d)));
  double limit = 0.0;
  try {
    limit = integrators::stable_time_step(system, true);
  } catch (const std::domain_error& error) {
    throw InputError(source, "/analysis/integrator", error.what());
  }
  if (analysis.time_step_auto) {
    analysis.time_step = analysis.safety_factor * limit;
    check_step_count(analysis, source);
  } else if (analysis.time_step > limit) {
    throw InputError(source, "/analysis/time_step",
                     fmt::format("{:.6g} is above the stable limit {:.6g} of central difference "
                                 "(2 / omega_max with the links in contact); use \"auto\" or a "
                                 "smaller step",
                                 analysis.time_step, limit));
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

// The records, scaled as the spec says (targets in g), along their directions.
void add_excitations(const ModelSpec& spec, const std::vector<model::GroundMotion>& motions,
                     const std::map<std::string, Index>& nodes, model::Model& model,
                     std::vector<double>& factors) {
  if (motions.size() != spec.excitations.size())
    throw std::invalid_argument("build: one ground motion per excitation is needed");
  const double gravity = spec.units.gravity();
  for (std::size_t k = 0; k < motions.size(); ++k) {
    const ExcitationSpec& e = spec.excitations[k];
    model::GroundMotion motion = motions[k];
    const std::string path = fmt::format("/excitations/{}/scale", k);
    if (!(motion.peak() > 0.0) && (e.target_pga || e.target_sa))
      throw InputError(spec.source, path,
                       fmt::format("record '{}' is all zeros: it cannot be scaled "
                                   "to a target",
                                   motion.name));
    double factor = e.scale_factor.value_or(1.0);
    if (e.target_pga) factor = model::scale_to_peak(motion, *e.target_pga * gravity);
    if (e.target_sa)
      factor = model::scale_to_spectral_acceleration(motion, *e.target_sa * gravity, e.sa_period,
                                                     e.sa_damping);
    model::scale(motion, factor * e.extra_factor);
    factors.push_back(factor * e.extra_factor);
    const model::Coordinates direction{e.direction[0],
                                       e.direction.size() > 1 ? e.direction[1] : 0.0};
    if (e.supports.empty()) {
      model.excitations.push_back({std::move(motion), direction});
      continue;
    }
    model::SupportExcitation moving{std::move(motion), direction, {}};
    for (std::size_t s = 0; s < e.supports.size(); ++s) {
      const std::string where = fmt::format("/excitations/{}/supports/{}", k, s);
      auto found = nodes.find(e.supports[s]);
      if (found == nodes.end())
        throw InputError(spec.source, where,
                         fmt::format("node '{}' does not exist", e.supports[s]));
      const Index node = found->second;
      // Only a support can be moved: every direction the record acts in must be fixed there.
      bool held = false;
      for (const model::Support& support : model.supports)
        if (support.node == node)
          held = (direction[0] == 0.0 || support.fixed[0]) &&
                 (direction[1] == 0.0 || support.fixed[1]);
      if (!held)
        throw InputError(
            spec.source, where,
            fmt::format("node '{}' is not a support fixed along the excitation's direction",
                        e.supports[s]));
      const double x = model.nodes[static_cast<std::size_t>(node)].position[0];
      const double delay =
          e.apparent_velocity ? std::abs(x - e.wave_origin) / *e.apparent_velocity : 0.0;
      moving.supports.emplace_back(node, delay);
    }
    model.support_excitations.push_back(std::move(moving));
  }
}

// a0 = 2 xi w1 w2 / (w1 + w2), a1 = 2 xi / (w1 + w2): the ratio xi at both frequencies.
model::RayleighDamping rayleigh_damping(const DampingSpec& damping, const model::Model& model,
                                        const std::string& source) {
  if (damping.mass_coefficient || damping.stiffness_coefficient)
    return {damping.mass_coefficient.value_or(0.0), damping.stiffness_coefficient.value_or(0.0)};
  std::array<double, 2> periods{};
  if (damping.periods) {
    periods = *damping.periods;
  } else {
    const int highest = std::max((*damping.modes)[0], (*damping.modes)[1]);
    const assembly::StructuralSystem system(model);
    const std::vector<double> found = assembly::natural_periods(system, highest);
    if (static_cast<int>(found.size()) < highest)
      throw InputError(source, "/damping/modes",
                       fmt::format("mode {} asked for, the model has {} vibration modes", highest,
                                   found.size()));
    periods = {found[static_cast<std::size_t>((*damping.modes)[0] - 1)],
               found[static_cast<std::size_t>((*damping.modes)[1] - 1)]};
  }
  const double w1 = 2.0 * std::numbers::pi / periods[0], w2 = 2.0 * std::numbers::pi / periods[1];
  return {2.0 * damping.ratio * w1 * w2 / (w1 + w2), 2.0 * damping.ratio / (w1 + w2)};
}

}  // namespace

BuiltModel build(const ModelSpec& user_spec, const std::vector<model::GroundMotion>& motions) {
  if (user_spec.dimension != 1 && !user_spec.rod_pairs.empty())
    throw InputError(user_spec.source,
                     fmt::format("/generators/{}", user_spec.rod_pair_generator_index[0]),
                     "rod_pair needs a 1-D scene (\"dimension\": 1)");
  for (const auto* generators : {&user_spec.building_pairs})
    for (const auto& g : *generators)
      if (user_spec.dimension != 2)
        throw InputError(user_spec.source, fmt::format("/generators/{}", g.generator_index),
                         "adjacent_buildings needs a 2-D scene (\"dimension\": 2)");
  for (const GirderBridgeSpec& g : user_spec.bridges)
    if (user_spec.dimension != 2)
      throw InputError(user_spec.source, fmt::format("/generators/{}", g.generator_index),
                       "girder_bridge needs a 2-D scene (\"dimension\": 2)");
  const ModelSpec spec = expand(user_spec);
  const Resolver resolve(spec);
  BuiltModel built;
  model::Model& model = built.model;
  model.dimension = spec.dimension;

  built.node_index = resolve.index_ids(
      spec.nodes, "node", origin_of(user_spec.nodes.size(), "nodes", spec.generated_from.nodes));
  const auto materials = resolve.index_ids(
      spec.materials, "material",
      origin_of(user_spec.materials.size(), "materials", spec.generated_from.materials));
  resolve.index_ids(spec.elements, "element",
                    origin_of(user_spec.elements.size(), "elements", spec.generated_from.elements));
  const auto link_origin = origin_of(user_spec.links.size(), "links", spec.generated_from.links);
  built.link_index = resolve.index_ids(spec.links, "link", link_origin);

  for (const NodeSpec& node : spec.nodes) model.nodes.push_back({node.id, {node.x, node.y}});

  model.elements = resolve_elements(
      spec, model, materials,
      origin_of(user_spec.elements.size(), "elements", spec.generated_from.elements),
      [&](const std::string& id, const std::string& path) {
        return resolve.node(built.node_index, id, path);
      });

  for (std::size_t k = 0; k < spec.masses.size(); ++k)
    model.masses.push_back(
        {resolve.node(built.node_index, spec.masses[k].node, fmt::format("/masses/{}/node", k)),
         spec.masses[k].mass, spec.masses[k].rotary_inertia,
         spec.masses[k].mass_damping
             ? std::optional(model::RayleighDamping{*spec.masses[k].mass_damping, 0.0})
             : std::nullopt});

  const auto support_origin =
      origin_of(user_spec.supports.size(), "supports", spec.generated_from.supports);
  for (std::size_t k = 0; k < spec.supports.size(); ++k)
    model.supports.push_back(
        {resolve.node(built.node_index, spec.supports[k].node, support_origin(k) + "/node"),
         {spec.supports[k].fix_x, spec.supports[k].fix_y, spec.supports[k].fix_rotation}});

  const auto load_origin = origin_of(user_spec.loads.size(), "loads", spec.generated_from.loads);
  for (std::size_t k = 0; k < spec.loads.size(); ++k)
    model.loads.push_back(
        {resolve.node(built.node_index, spec.loads[k].node, load_origin(k) + "/node"),
         {spec.loads[k].x, spec.loads[k].y}});

  const auto velocity_origin = origin_of(user_spec.initial_velocities.size(), "initial_velocities",
                                         spec.generated_from.initial_velocities);
  if (!spec.initial_velocities.empty())
    model.initial_velocity.assign(model.nodes.size(), {0.0, 0.0});
  for (std::size_t k = 0; k < spec.initial_velocities.size(); ++k) {
    const InitialVelocitySpec& v = spec.initial_velocities[k];
    const Index node = resolve.node(built.node_index, v.node, velocity_origin(k) + "/node");
    model.initial_velocity[static_cast<std::size_t>(node)] = {v.x, v.y};
  }

  for (std::size_t k = 0; k < spec.links.size(); ++k) {
    const LinkSpec& spec_link = spec.links[k];
    const std::string path = link_origin(k);
    model::Link link;
    link.id = spec_link.id;
    link.node_i = resolve.node(built.node_index, spec_link.node_i, path + "/nodes/0");
    link.node_j = resolve.node(built.node_index, spec_link.node_j, path + "/nodes/1");
    if (link.node_i == link.node_j)
      resolve.fail(path + "/nodes", "a link cannot join a node to itself");
    link.gap = spec_link.gap;
    link.rotational = spec_link.rotational;
    link.velocity_j = {spec_link.velocity_j[0], spec_link.velocity_j[1]};
    if (spec_link.segment_end) {
      const Index k_node =
          resolve.node(built.node_index, *spec_link.segment_end, path + "/segment/1");
      if (k_node == link.node_i || k_node == link.node_j)
        resolve.fail(path + "/segment", "a segment needs two nodes other than the link's node i");
      link.segment_end = k_node;
      const auto& p = model.nodes[static_cast<std::size_t>(link.node_i)].position;
      const auto& a = model.nodes[static_cast<std::size_t>(link.node_j)].position;
      const auto& b = model.nodes[static_cast<std::size_t>(k_node)].position;
      const double sx = b[0] - a[0], sy = b[1] - a[1], length2 = sx * sx + sy * sy;
      if (!(length2 > 0.0) || !std::isfinite(length2))
        resolve.fail(path + "/segment", "the segment's two nodes are at the same place");
      link.segment_weight =
          std::clamp(((p[0] - a[0]) * sx + (p[1] - a[1]) * sy) / length2, 0.0, 1.0);
      if (!spec_link.axis) {
        // The segment's normal, pointing from node i towards the segment.
        const double length = std::sqrt(length2);
        model::Coordinates normal{-sy / length, sx / length};
        const double side = (a[0] - p[0]) * normal[0] + (a[1] - p[1]) * normal[1];
        if (std::abs(side) <= 1e-12 * length)
          resolve.fail(path, "node i lies on the segment: give the link an \"axis\"");
        if (side < 0.0) normal = {-normal[0], -normal[1]};
        link.axis = normal;
      }
    }
    if (spec_link.axis) {
      const auto& axis = *spec_link.axis;
      link.axis = {axis[0], axis.size() > 1 ? axis[1] : 0.0};
    } else if (!spec_link.segment_end) {
      const auto& a = model.nodes[static_cast<std::size_t>(link.node_i)].position;
      const auto& b = model.nodes[static_cast<std::size_t>(link.node_j)].position;
      const double dx = b[0] - a[0], dy = spec.dimension == 2 ? b[1] - a[1] : 0.0;
      const double length = std::hypot(dx, dy);
      if (!(length > 0.0))
        resolve.fail(path,
                     fmt::format("nodes '{}' and '{}' are at the same place: give the link an "
                                 "\"axis\"",
                                 spec_link.node_i, spec_link.node_j));
      link.axis = {dx / length, dy / length};
    }
    const links::LawEntry* found_law = links::find_law(spec_link.law.type);
    if (!found_law)
      resolve.fail(path + "/law/type", fmt::format("unknown law '{}'", spec_link.law.type));
    const links::LawEntry& law = *found_law;
    const bool tension_law = law.traits.role == links::LinkRole::tension;
    if (tension_law && spec_link.gap != 0.0)
      resolve.fail(path + "/gap", fmt::format("a {} has 'slack' in its law, not a gap: the link's "
                                              "gap must be 0, got {}",
                                              spec_link.law.type, spec_link.gap));
    link.law = &law;
    link.make_law = links::make_law(spec_link.law, {spec.source, path + "/law"});
    if (spec_link.friction) {
      if (spec.dimension != 2)
        resolve.fail(path + "/friction",
                     "friction needs a tangential direction: a 2-D scene (\"dimension\": 2)");
      if (tension_law)
        resolve.fail(
            path + "/friction",
            fmt::format("a {} carries no normal contact force to rub with", spec_link.law.type));
      const FrictionSpec& f = *spec_link.friction;
      if (!law.traits.stiff_at_first_touch && !f.stick_stiffness)
        resolve.fail(
            path + "/friction",
            fmt::format(
                "give 'stick_stiffness': a {} law has no stiffness at first touch to stick with",
                spec_link.law.type));
      link.friction =
          model::LinkFriction{f.coefficient, f.stick_stiffness, f.stick_damping, f.stick_mass};
    }
    model.links.push_back(std::move(link));
  }

  built.analysis = spec.analysis;
  add_excitations(spec, motions, built.node_index, model, built.excitation_factors);
  if (built.analysis.duration == 0.0)
    for (const model::UniformExcitation& excitation : model.excitations)
      built.analysis.duration = std::max(built.analysis.duration, excitation.motion.duration());
  if (built.analysis.duration == 0.0)
    for (const model::SupportExcitation& excitation : model.support_excitations)
      for (const auto& [node, delay] : excitation.supports)
        built.analysis.duration =
            std::max(built.analysis.duration, excitation.motion.duration() + delay);
  // Adaptive steps no longer than the records' sampling, so no peak of a record is stepped over.
  if (built.analysis.adaptive && built.analysis.adaptive->max_time_step == 0.0) {
    double sampling = INFINITY;
    for (const model::UniformExcitation& excitation : model.excitations)
      sampling = std::min(sampling, excitation.motion.time_step);
    for (const model::SupportExcitation& excitation : model.support_excitations)
      sampling = std::min(sampling, excitation.motion.time_step);
    if (std::isfinite(sampling))
      built.analysis.adaptive->max_time_step = std::max(sampling, built.analysis.time_step);
  }
  if (!built.analysis.time_step_auto) check_step_count(built.analysis, spec.source);
  if (spec.damping) model.damping = rayleigh_damping(*spec.damping, model, spec.source);
  if (!spec.recorders_given && !model.links.empty()) {
    ResolvedRecorder every_link{"link", {}, "links.csv"};
    for (Index i = 0; i < static_cast<Index>(model.links.size()); ++i)
      every_link.items.push_back(i);
    built.recorders.push_back(std::move(every_link));
  }
  for (std::size_t k = 0; k < spec.recorders.size(); ++k) {
    const RecorderSpec& recorder = spec.recorders[k];
    ResolvedRecorder resolved{recorder.type, {}, recorder.file};
    for (std::size_t i = 0; i < recorder.ids.size(); ++i) {
      const std::string path =
          fmt::format("/recorders/{}/{}/{}", k, recorder.type == "link" ? "links" : "nodes", i);
      if (recorder.type == "node") {
        resolved.items.push_back(resolve.node(built.node_index, recorder.ids[i], path));
      } else {
        auto found = built.link_index.find(recorder.ids[i]);
        if (found == built.link_index.end())
          resolve.fail(path, fmt::format("link '{}' does not exist", recorder.ids[i]));
        resolved.items.push_back(found->second);
      }
    }
    if (recorder.type == "link" && recorder.ids.empty())
      for (Index i = 0; i < static_cast<Index>(model.links.size()); ++i)
        resolved.items.push_back(i);
    built.recorders.push_back(std::move(resolved));
  }

  // Monitors, generated or the user's; generated ones come after the user's.
  const std::size_t user_drifts = user_spec.drift_monitors.size(),
                    user_joints = user_spec.joint_monitors.size();
  for (std::size_t k = 0; k < spec.drift_monitors.size(); ++k) {
    const DriftMonitorSpec& m = spec.drift_monitors[k];
    const std::string path =
        k < user_drifts ? fmt::format("/monitors/drifts/{}", k) : "/generators";
    built.drift_monitors.push_back(
        {m.id, m.kind, m.group, resolve.node(built.node_index, m.bottom, path + "/bottom"),
         resolve.node(built.node_index, m.top, path + "/top"), m.height, m.yield_drift});
  }
  for (std::size_t k = 0; k < spec.joint_monitors.size(); ++k) {
    const JointMonitorSpec& m = spec.joint_monitors[k];
    const std::string path =
        k < user_joints ? fmt::format("/monitors/joints/{}", k) : "/generators";
    auto link = built.link_index.find(m.link);
    if (link == built.link_index.end())
      resolve.fail(path + "/link", fmt::format("link '{}' does not exist", m.link));
    built.joint_monitors.push_back(
        {m.id, link->second, resolve.node(built.node_index, m.girder, path + "/girder"),
         resolve.node(built.node_index, m.seat, path + "/seat"), m.seat_width});
  }

  const bool only_rod_pair = user_spec.rod_pairs.size() == 1 && user_spec.nodes.empty() &&
                             user_spec.building_pairs.empty() && user_spec.bridges.empty() &&
                             user_spec.loads.empty() && user_spec.elements.empty() &&
                             user_spec.masses.empty() && user_spec.supports.empty() &&
                             user_spec.initial_velocities.empty() && user_spec.links.empty();
  if (only_rod_pair) built.sole_rod_pair = user_spec.rod_pairs.front();
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
  size.dofs = size.nodes * (spec.dimension == 1 ? 1 : 3);
  return size;
}

}  // namespace pound::builder
