#include "builder/generators.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/errors.hpp"

namespace pound::builder {
namespace {

double element_stiffness(const RodSpec& rod) {
  return rod.youngs_modulus * rod.area / (rod.length / rod.elements);
}

// Left rod: nodes 0..n from the far end (x = -L) to the facing end (x = 0). Right rod: nodes
// 0..n from the facing end (x = 0) to the far end (x = L).
void add_rod(const RodPairSpec& pair, int side, ModelSpec& out) {
  const RodSpec& rod = side == 0 ? pair.left : pair.right;
  const std::string material = fmt::format("{}.{}", pair.id, kPairSides[side]);
  out.materials.push_back({material, rod.youngs_modulus, rod.density});
  const double h = rod.length / rod.elements;
  for (int i = 0; i <= rod.elements; ++i) {
    const double x = side == 0 ? -rod.length + i * h : i * h;
    out.nodes.push_back(
        {rod_node_id(pair, side, i), side == 0 && i == rod.elements ? 0.0 : x, 0.0});
    if (rod.initial_velocity != 0.0)
      out.initial_velocities.push_back({rod_node_id(pair, side, i), rod.initial_velocity, 0.0});
  }
  for (int e = 0; e < rod.elements; ++e)
    out.elements.push_back({fmt::format("{}.{}.e{}", pair.id, kPairSides[side], e),
                            ElementKind::truss, rod_node_id(pair, side, e),
                            rod_node_id(pair, side, e + 1), material, rod.area});
  if (rod.far_end_fixed)
    out.supports.push_back({rod_node_id(pair, side, side == 0 ? 0 : rod.elements), {true}});
}

// The contact link between the facing ends of the rods.
LinkSpec rod_contact_link(const RodPairSpec& pair) {
  LinkSpec link = make_link(rod_link_id(pair), rod_node_id(pair, 0, pair.left.elements),
                            pair.right_wall ? rod_wall_id(pair) : rod_node_id(pair, 1, 0), {1.0},
                            pair.gap, pair.law);
  if (const auto ratio = pair.law.number("stiffness_ratio")) {
    link.law.parameters["stiffness"] = *ratio * rod_pair_adjacent_stiffness(pair);
    link.law.parameters.erase("stiffness_ratio");
  }
  return link;
}

// The spec without its generators, which expand() replaces by what they generate.
ModelSpec without_generators(const ModelSpec& spec) {
  ModelSpec out = spec;
  out.rod_pairs.clear();
  out.rod_pair_generator_index.clear();
  out.building_pairs.clear();
  out.bridges.clear();
  out.blocks.clear();
  out.surfaces.clear();
  out.contacts.clear();
  return out;
}

// Everything appended to `out` since the last call came from the generator at `path`.
void mark_generated(const ModelSpec& spec, const std::string& path, ModelSpec& out) {
  auto fill = [&path](std::vector<std::string>& origins, std::size_t total, std::size_t user) {
    origins.resize(total - user, path);
  };
  auto& from = out.generated_from;
  fill(from.nodes, out.nodes.size(), spec.nodes.size());
  fill(from.materials, out.materials.size(), spec.materials.size());
  fill(from.elements, out.elements.size(), spec.elements.size());
  fill(from.supports, out.supports.size(), spec.supports.size());
  fill(from.initial_velocities, out.initial_velocities.size(), spec.initial_velocities.size());
  fill(from.links, out.links.size(), spec.links.size());
  fill(from.loads, out.loads.size(), spec.loads.size());
}

std::string generator_path(int generator) { return fmt::format("/generators/{}", generator); }

}  // namespace

void require_law_role(const LawSpec& law, links::LinkRole role, const std::string& what,
                      const std::string& source, const std::string& path, const std::string& hint) {
  using links::LinkRole;
  const links::LawEntry* entry = links::find_law(law.type);
  if (!entry || entry->traits.role == role) return;
  std::string fitting;
  for (const links::LawEntry* other : links::law_registry())
    if (other->traits.role == role) fitting += (fitting.empty() ? "" : ", ") + other->name;
  const LinkRole given = entry->traits.role;
  std::string kind = "compression-only contact", why = "pulls, not pushes";
  if (role == LinkRole::spring) {
    kind = "spring (force both ways)";
    why = given == LinkRole::tension ? "only pulls" : "only pushes";
  } else if (role == LinkRole::tension) {
    kind = "tension-only";
    why = given == LinkRole::spring ? "acts both ways: it would push as well as pull"
                                    : "pushes, not pulls";
  } else if (given == LinkRole::spring) {
    why =
        "acts both ways from the link's rest length: across the gap it would pull with k x gap "
        "before anything touches";
  }
  throw InputError(source, path + "/type",
                   fmt::format("{} needs a {} law ({}), got '{}', which {}{}", what, kind, fitting,
                               law.type, why, hint.empty() ? "" : "; " + hint));
}

LinkSpec make_link(const std::string& id, const std::string& node_i, const std::string& node_j,
                   std::vector<double> axis, double gap, const LawSpec& law) {
  LinkSpec link;
  link.id = id;
  link.node_i = node_i;
  link.node_j = node_j;
  link.gap = gap;
  link.axis = std::move(axis);
  link.law = law;
  return link;
}

ElementSpec make_beam(const std::string& id, const std::string& node_i, const std::string& node_j,
                      const std::string& material, double area, double inertia) {
  ElementSpec beam;
  beam.id = id;
  beam.type = ElementKind::beam;
  beam.node_i = node_i;
  beam.node_j = node_j;
  beam.material = material;
  beam.area = area;
  beam.inertia = inertia;
  return beam;
}

std::string rod_node_id(const RodPairSpec& pair, int rod, int index) {
  return fmt::format("{}.{}.{}", pair.id, kPairSides[rod], index);
}

std::string rod_link_id(const RodPairSpec& pair) { return pair.id + ".contact"; }

std::string rod_wall_id(const RodPairSpec& pair) { return pair.id + ".wall"; }

double rod_pair_adjacent_stiffness(const RodPairSpec& pair) {
  if (pair.right_wall) return element_stiffness(pair.left);
  return std::min(element_stiffness(pair.left), element_stiffness(pair.right));
}

ModelSpec expand(const ModelSpec& spec) {
  ModelSpec out = without_generators(spec);
  for (std::size_t g = 0; g < spec.rod_pairs.size(); ++g) {
    const RodPairSpec& pair = spec.rod_pairs[g];
    add_rod(pair, 0, out);
    if (pair.right_wall) {
      out.nodes.push_back({rod_wall_id(pair), 0.0, 0.0});
      out.supports.push_back({rod_wall_id(pair), {true}});
    } else {
      add_rod(pair, 1, out);
    }
    out.links.push_back(rod_contact_link(pair));
    const int generator = spec.rod_pair_generator_index.empty() ? static_cast<int>(g)
                                                                : spec.rod_pair_generator_index[g];
    mark_generated(spec, generator_path(generator), out);
  }
  for (const AdjacentBuildingsSpec& pair : spec.building_pairs) {
    add_adjacent_buildings(pair, out);
    mark_generated(spec, generator_path(pair.generator_index), out);
  }
  for (const GirderBridgeSpec& bridge : spec.bridges) {
    add_girder_bridge(bridge, out);
    mark_generated(spec, generator_path(bridge.generator_index), out);
  }
  for (const BlockSpec& block : spec.blocks) {
    add_block(block, out);
    mark_generated(spec, generator_path(block.generator_index), out);
  }
  for (const SurfaceSpec& surface : spec.surfaces) {
    add_surface(surface, out);
    mark_generated(spec, fmt::format("/surfaces/{}", surface.index), out);
  }
  for (const ContactSpec& contact : spec.contacts) {
    add_contact(contact, out);
    mark_generated(spec, fmt::format("/contacts/{}", contact.index), out);
  }
  return out;
}

}  // namespace pound::builder
