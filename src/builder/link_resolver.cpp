#include "builder/link_resolver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "links/coupled_shear.hpp"
#include "links/law_registry.hpp"
#include "links/stiffness_damping.hpp"

namespace pound::builder {
namespace {

// What resolving one link needs besides its spec.
struct LinkPlace {
  const Resolver& resolver;
  const model::Model& model;
  const LinkSpec& spec;
  std::string path;

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    resolver.fail(path + where, what);
  }
  const model::Coordinates& position(Index node) const {
    return model.nodes[static_cast<std::size_t>(node)].position;
  }
};

void resolve_nodes(const LinkPlace& place, model::Link& link) {
  link.node_i = place.resolver.node(place.spec.node_i, place.path + "/nodes/0");
  link.node_j = place.resolver.node(place.spec.node_j, place.path + "/nodes/1");
  if (link.node_i == link.node_j) place.fail("/nodes", "a link cannot join a node to itself");
}

// Node-to-segment: where node i projects onto the segment j-k (clamped to it), and the
// segment's normal towards it as the axis unless one is given.
void resolve_segment(const LinkPlace& place, model::Link& link) {
  const Index k_node = place.resolver.node(*place.spec.segment_end, place.path + "/segment/1");
  if (k_node == link.node_i || k_node == link.node_j)
    place.fail("/segment", "a segment needs two nodes other than the link's node i");
  link.segment_end = k_node;
  const auto& p = place.position(link.node_i);
  const auto& a = place.position(link.node_j);
  const auto& b = place.position(k_node);
  const double sx = b[0] - a[0], sy = b[1] - a[1], length2 = sx * sx + sy * sy;
  if (!(length2 > 0.0) || !std::isfinite(length2))
    place.fail("/segment", "the segment's two nodes are at the same place");
  link.segment_weight = std::clamp(((p[0] - a[0]) * sx + (p[1] - a[1]) * sy) / length2, 0.0, 1.0);
  if (place.spec.axis) return;
  // The segment's normal, pointing from node i towards the segment.
  const double length = std::sqrt(length2);
  model::Coordinates normal{-sy / length, sx / length};
  const double side = (a[0] - p[0]) * normal[0] + (a[1] - p[1]) * normal[1];
  if (std::abs(side) <= 1e-12 * length)
    place.fail("", "node i lies on the segment: give the link an \"axis\"");
  if (side < 0.0) normal = {-normal[0], -normal[1]};
  link.axis = normal;
}

// The given axis, or the unit vector from node i to node j.
void resolve_axis(const LinkPlace& place, model::Link& link) {
  if (place.spec.axis) {
    link.axis = model::to_coordinates(*place.spec.axis);
    return;
  }
  if (place.spec.segment_end) return;
  // A hinge acts on theta_i - theta_j, about z in a plane (no axis; its nodes may meet).
  if (place.spec.rotational) return;
  // From the point that touches at i to the one at j (the nodes unless offset).
  model::Coordinates a = place.position(link.node_i);
  model::Coordinates b = place.position(link.node_j);
  for (std::size_t k = 0; k < 3; ++k) {
    a[k] += link.offsets[0][k];
    b[k] += link.offsets[1][k];
  }
  const double length = model::distance(a, b, place.model.dimension);
  if (!(length > 0.0))
    place.fail(
        "", fmt::format("{} are at the same place: give the link an \"axis\"",
                        link.has_offsets() ? "the points the link's offsets reach"
                                           : fmt::format("nodes '{}' and '{}'", place.spec.node_i,
                                                         place.spec.node_j)));
  link.axis = {};
  for (std::size_t k = 0; k < static_cast<std::size_t>(place.model.dimension); ++k)
    link.axis[k] = (b[k] - a[k]) / length;
}

// Offsets turn the link's ends: a hinge or a point on a segment has no point of its own to offset.
void resolve_offsets(const LinkPlace& place, model::Link& link) {
  if (!place.spec.offsets) return;
  if (place.spec.rotational)
    place.fail("/rigid_offsets", "a rotational link acts on the nodes' rotations: no offsets");
  if (place.spec.segment_end)
    place.fail("/rigid_offsets", "a node-to-segment link takes no offsets");
  link.offsets = *place.spec.offsets;
  for (const auto& end : link.offsets)
    for (const double component : end)
      if (!std::isfinite(component) || std::abs(component) > 1e12)
        place.fail("/rigid_offsets", "offsets must be finite, each component within 1e12");
}

void resolve_law(const LinkPlace& place, model::Link& link) {
  const std::string& type = place.spec.law.type;
  link.law = links::find_law(type);
  if (!link.law) place.fail("/law/type", fmt::format("unknown law '{}'", type));
  if (link.role() == links::LinkRole::tension && place.spec.gap != 0.0)
    place.fail("/gap", fmt::format("a {} has 'slack' in its law, not a gap: the link's gap must "
                                   "be 0, got {}",
                                   type, place.spec.gap));
  if (link.role() == links::LinkRole::spring && place.spec.gap != 0.0)
    place.fail("/gap",
               fmt::format("the law {} acts both ways from the link's rest length, so a gap of {} "
                           "would start it stretched by the gap before anything touches (a "
                           "spring pulling with k x gap): a stop that engages after a gap takes a "
                           "contact law (gap_spring; backfill for one that yields at a capacity), "
                           "a restrainer's slack is in its law",
                           type, place.spec.gap));
  link.make_law =
      links::make_law(place.spec.law, {place.resolver.spec().source, place.path + "/law"});
  link.law_spec = place.spec.law;
}

// A constraint (hard_contact) sticks exactly: no stick penalty to give, and no pendulum (its
// restoring force needs the slide a penalty law leaves).
void refuse_stick_penalty(const LinkPlace& place, const FrictionSpec& friction,
                          const std::string& type) {
  const auto refuse = [&](const std::optional<double>& value, const std::string& name) {
    if (value)
      place.fail(
          "/friction/" + name,
          fmt::format("a {} sticks exactly, with no stick penalty: leave out '{}'", type, name));
  };
  refuse(friction.stick_stiffness, "stick_stiffness");
  refuse(friction.stick_damping, "stick_damping");
  refuse(friction.stick_mass, "stick_mass");
  if (friction.radius)
    place.fail("/friction/radius",
               fmt::format("a friction pendulum needs a penalty normal law, not a {}", type));
}

// Coulomb friction needs a tangent (2-D, or a contact plane in 3-D), a normal force to rub with,
// and a stick stiffness (the normal law's at first touch unless given).
void resolve_friction(const LinkPlace& place, model::Link& link) {
  const FrictionSpec& friction = *place.spec.friction;
  const std::string& type = place.spec.law.type;
  if (place.model.dimension == 1)
    place.fail("/friction",
               "friction needs a tangential direction: a 2-D or 3-D scene (\"dimension\": 2 or 3)");
  if (place.model.dimension == 3 && link.rotational)
    place.fail("/friction", "a rotational link of a 3-D scene has no contact plane to slide in");
  if (link.role() == links::LinkRole::tension)
    place.fail("/friction", fmt::format("a {} carries no normal contact force to rub with", type));
  if (link.law->traits.constraint)
    refuse_stick_penalty(place, friction, type);
  else if (!link.law->traits.stiff_at_first_touch && !friction.stick_stiffness)
    place.fail("/friction",
               fmt::format("give 'stick_stiffness': a {} law has no stiffness at first touch to "
                           "stick with",
                           type));
  if (friction.radius && link.rotational)
    place.fail("/friction/radius", "a friction pendulum slides: a rotational link has no slide");
  link.friction = model::LinkFriction{friction.coefficient, friction.stick_stiffness,
                                      friction.stick_damping, friction.stick_mass, friction.radius};
}

// A bearing's coupled shear, from its uniaxial laws' numbers (the schema checked they have them).
void resolve_shear(const LinkPlace& place, model::Link& link) {
  const auto numbers_at = [&](const LawSpec& shear, const std::string& key) {
    const std::optional<links::ShearNumbers> numbers = links::CoupledShear::numbers_of(
        shear, {place.resolver.spec().source, place.path + "/" + key});
    if (!numbers)
      place.fail("/" + key + "/type", fmt::format("a {} has no coupled form", shear.type));
    return *numbers;
  };
  const links::ShearNumbers first = numbers_at(*place.spec.shear, "shear");
  const links::ShearNumbers second =
      place.spec.shear_2 ? numbers_at(*place.spec.shear_2, "shear_2") : first;
  if (const std::optional<std::string> why = links::CoupledShear::mismatch(first, second))
    place.fail("/shear_2", *why);
  link.shear = model::LinkShear{place.spec.shear->type, {first, second}};
}

// t_1 given: its part across the (unit) axis, which must not vanish.
void resolve_tangent(const LinkPlace& place, model::Link& link) {
  const std::vector<double>& given = *place.spec.tangent;
  model::Coordinates n = link.axis;
  const double length = std::hypot(n[0], n[1], n[2]);
  for (double& component : n) component /= length;
  const double along = given[0] * n[0] + given[1] * n[1] + given[2] * n[2];
  model::Coordinates across{given[0] - along * n[0], given[1] - along * n[1],
                            given[2] - along * n[2]};
  const double size = std::hypot(across[0], across[1], across[2]);
  if (!(size > 1e-6))
    place.fail("/tangent", "lies along the link's axis: t_1 must point across it");
  for (double& component : across) component /= size;
  link.tangent = across;
}

// Link k's JSON path: its entry in "links", or its generator's.
Origin link_origin(const Resolver& resolver) {
  return origin_of(resolver.user_spec().links.size(), "links",
                   resolver.spec().generated_from.links);
}

model::Link resolve_link(const LinkPlace& place) {
  const LinkSpec& spec = place.spec;
  model::Link link;
  link.id = spec.id;
  resolve_nodes(place, link);
  link.gap = spec.gap;
  link.rotational = spec.rotational;
  link.velocity_j = {spec.velocity_j[0], spec.velocity_j[1]};
  if (spec.segment_end) resolve_segment(place, link);
  resolve_offsets(place, link);
  resolve_axis(place, link);
  resolve_law(place, link);
  if (spec.friction) resolve_friction(place, link);
  if (spec.shear) resolve_shear(place, link);
  if (spec.tangent) resolve_tangent(place, link);
  return link;
}

}  // namespace

std::vector<model::Link> resolve_links(const Resolver& resolver, const model::Model& model) {
  const ModelSpec& spec = resolver.spec();
  const Origin origin = link_origin(resolver);
  std::vector<model::Link> links;
  for (std::size_t k = 0; k < spec.links.size(); ++k)
    links.push_back(resolve_link({resolver, model, spec.links[k], origin(k)}));
  return links;
}

void add_link_damping(const Resolver& resolver,
                      const std::optional<model::RayleighDamping>& damping,
                      std::vector<model::Link>& links) {
  const ModelSpec& spec = resolver.spec();
  const Origin origin = link_origin(resolver);
  for (std::size_t k = 0; k < spec.links.size(); ++k) {
    const std::optional<LinkRayleighSpec>& rayleigh = spec.links[k].rayleigh;
    if (!rayleigh) continue;
    const std::optional<double> coefficient =
        rayleigh->stiffness_coefficient
            ? rayleigh->stiffness_coefficient
            : (damping ? std::optional(damping->stiffness_coefficient) : std::nullopt);
    if (!coefficient)
      resolver.fail(origin(k) + "/rayleigh/stiffness_coefficient",
                    "the model has no \"damping\" to take a1 from: give the link its own");
    if (links[k].shear)
      links[k].shear->damping = links::ShearDamping{*coefficient, rayleigh->stiffness};
    links[k].law_spec.reset();  // the law is no longer the spec's alone
    links[k].make_law = [inner = links[k].make_law, a1 = *coefficient,
                         stiffness = rayleigh->stiffness](const links::LinkContext& context) {
      return std::make_unique<links::StiffnessDamping>(inner(context), a1, stiffness);
    };
  }
}

}  // namespace pound::builder
