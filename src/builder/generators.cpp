#include "builder/generators.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace pound::builder {
namespace {
constexpr const char* kSide[] = {"left", "right"};

double element_stiffness(const RodSpec& rod) {
  return rod.youngs_modulus * rod.area / (rod.length / rod.elements);
}

// Left rod: nodes 0..n from the far end (x = -L) to the facing end (x = 0). Right rod: nodes
// 0..n from the facing end (x = 0) to the far end (x = L).
void add_rod(const RodPairSpec& pair, int side, ModelSpec& out) {
  const RodSpec& rod = side == 0 ? pair.left : pair.right;
  const std::string material = fmt::format("{}.{}", pair.id, kSide[side]);
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
    out.elements.push_back({fmt::format("{}.{}.e{}", pair.id, kSide[side], e), "truss",
                            rod_node_id(pair, side, e), rod_node_id(pair, side, e + 1), material,
                            rod.area});
  if (rod.far_end_fixed)
    out.supports.push_back({rod_node_id(pair, side, side == 0 ? 0 : rod.elements), true, false});
}
}  // namespace

std::string rod_node_id(const RodPairSpec& pair, int rod, int index) {
  return fmt::format("{}.{}.{}", pair.id, kSide[rod], index);
}

std::string rod_link_id(const RodPairSpec& pair) { return pair.id + ".contact"; }

double rod_pair_adjacent_stiffness(const RodPairSpec& pair) {
  return std::min(element_stiffness(pair.left), element_stiffness(pair.right));
}

ModelSpec expand(const ModelSpec& spec) {
  ModelSpec out = spec;
  out.rod_pairs.clear();
  out.rod_pair_generator_index.clear();
  auto& from = out.generated_from;
  // Everything appended since the last call came from `generator`.
  auto mark_path = [&out, &from, &spec](const std::string& path) {
    auto fill = [&path](std::vector<std::string>& origins, std::size_t total, std::size_t user) {
      origins.resize(total - user, path);
    };
    fill(from.nodes, out.nodes.size(), spec.nodes.size());
    fill(from.materials, out.materials.size(), spec.materials.size());
    fill(from.elements, out.elements.size(), spec.elements.size());
    fill(from.supports, out.supports.size(), spec.supports.size());
    fill(from.initial_velocities, out.initial_velocities.size(), spec.initial_velocities.size());
    fill(from.links, out.links.size(), spec.links.size());
    fill(from.loads, out.loads.size(), spec.loads.size());
  };
  auto mark = [&mark_path](int generator) { mark_path(fmt::format("/generators/{}", generator)); };
  for (std::size_t g = 0; g < spec.rod_pairs.size(); ++g) {
    const RodPairSpec& pair = spec.rod_pairs[g];
    add_rod(pair, 0, out);
    add_rod(pair, 1, out);
    LinkSpec link;
    link.id = rod_link_id(pair);
    link.node_i = rod_node_id(pair, 0, pair.left.elements);
    link.node_j = rod_node_id(pair, 1, 0);
    link.gap = pair.gap;
    link.axis = std::vector<double>{1.0};
    link.law = pair.law;
    if (const auto ratio = pair.law.number("stiffness_ratio")) {
      link.law.parameters["stiffness"] = *ratio * rod_pair_adjacent_stiffness(pair);
      link.law.parameters.erase("stiffness_ratio");
    }
    out.links.push_back(std::move(link));
    mark(spec.rod_pair_generator_index.empty() ? static_cast<int>(g)
                                               : spec.rod_pair_generator_index[g]);
  }
  out.building_pairs.clear();
  out.bridges.clear();
  for (const AdjacentBuildingsSpec& pair : spec.building_pairs) {
    add_adjacent_buildings(pair, out);
    mark(pair.generator_index);
  }
  for (const GirderBridgeSpec& bridge : spec.bridges) {
    add_girder_bridge(bridge, out);
    mark(bridge.generator_index);
  }
  out.blocks.clear();
  out.surfaces.clear();
  out.contacts.clear();
  for (const BlockSpec& block : spec.blocks) {
    add_block(block, out);
    mark(block.generator_index);
  }
  for (const SurfaceSpec& surface : spec.surfaces) {
    add_surface(surface, out);
    mark_path(fmt::format("/surfaces/{}", surface.index));
  }
  for (const ContactSpec& contact : spec.contacts) {
    add_contact(contact, out);
    mark_path(fmt::format("/contacts/{}", contact.index));
  }
  return out;
}

}  // namespace pound::builder
