// The plane-continuum parts of expand(): rectangular blocks of quads, rigid (moving) surfaces
// and node-to-segment contacts between boundaries.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "builder/generators.hpp"
#include "core/errors.hpp"

namespace pound::builder {
namespace {

constexpr const char* kEdges[] = {"bottom", "right", "top", "left"};

std::array<double, 2> position(const ModelSpec& out, const std::map<std::string, std::size_t>& at,
                               const std::string& id, const std::string& path) {
  auto found = at.find(id);
  if (found == at.end())
    throw InputError(out.source, path, fmt::format("node or node set '{}' does not exist", id));
  const NodeSpec& node = out.nodes[found->second];
  return {node.x, node.y};
}

std::map<std::string, std::size_t> node_positions(const ModelSpec& out) {
  std::map<std::string, std::size_t> at;
  for (std::size_t k = 0; k < out.nodes.size(); ++k) at.emplace(out.nodes[k].id, k);
  return at;
}

// Node ids of a list of ids and node-set names, in order.
std::vector<std::string> resolve_nodes(const ModelSpec& out,
                                       const std::map<std::string, std::size_t>& at,
                                       const std::vector<std::string>& names,
                                       const std::string& path) {
  std::vector<std::string> ids;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string& name = names[k];
    auto set = out.node_sets.find(name);
    if (set != out.node_sets.end()) {
      ids.insert(ids.end(), set->second.begin(), set->second.end());
    } else if (at.count(name)) {
      ids.push_back(name);
    } else {
      std::string known;
      for (const auto& [set_name, nodes] : out.node_sets)
        known += (known.empty() ? "" : ", ") + set_name;
      throw InputError(out.source, fmt::format("{}/{}", path, k),
                       fmt::format("node or node set '{}' does not exist{}", name,
                                   known.empty() ? "" : " (node sets: " + known + ")"));
    }
  }
  return ids;
}

// Numbered across the shorter side first: the narrowest band of K.
void add_block_nodes(const BlockSpec& block, ModelSpec& out) {
  const int n = block.columns, m = block.rows;
  const double dx = block.width / n, dy = block.height / m;
  auto add_node = [&](int i, int j) {
    const std::string id = block_node_id(block, i, j);
    out.nodes.push_back({id, block.origin[0] + (i == n ? block.width : i * dx),
                         block.origin[1] + (j == m ? block.height : j * dy)});
    if (block.initial_velocity[0] != 0.0 || block.initial_velocity[1] != 0.0)
      out.initial_velocities.push_back({id, block.initial_velocity[0], block.initial_velocity[1]});
  };
  if (n <= m) {
    for (int j = 0; j <= m; ++j)
      for (int i = 0; i <= n; ++i) add_node(i, j);
  } else {
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= m; ++j) add_node(i, j);
  }
}

void add_block_quads(const BlockSpec& block, ModelSpec& out) {
  for (int j = 0; j < block.rows; ++j)
    for (int i = 0; i < block.columns; ++i) {
      ElementSpec quad;
      quad.id = fmt::format("{}.e{}.{}", block.id, i, j);
      quad.type = ElementKind::quad;
      quad.node_i = block_node_id(block, i, j);
      quad.node_j = block_node_id(block, i + 1, j);
      quad.more_nodes = {block_node_id(block, i + 1, j + 1), block_node_id(block, i, j + 1)};
      quad.material = block.material;
      quad.thickness = block.thickness;
      quad.plane_strain = block.plane_strain;
      quad.consistent_mass = block.consistent_mass;
      out.elements.push_back(std::move(quad));
    }
}

// Edges counter-clockwise round the block (the body on the left of each chain), as kEdges.
std::array<std::vector<std::string>, 4> block_edges(const BlockSpec& block) {
  const int n = block.columns, m = block.rows;
  std::array<std::vector<std::string>, 4> edges;
  for (int i = 0; i <= n; ++i) edges[0].push_back(block_node_id(block, i, 0));
  for (int j = 0; j <= m; ++j) edges[1].push_back(block_node_id(block, n, j));
  for (int i = n; i >= 0; --i) edges[2].push_back(block_node_id(block, i, m));
  for (int j = m; j >= 0; --j) edges[3].push_back(block_node_id(block, 0, j));
  return edges;
}

// A pressure p on an edge: p t h / 2 on each end of each element side, pushing inwards
// (the exact consistent loads of a uniform traction on a linear side).
void add_edge_pressure(const BlockSpec& block, const std::vector<std::string>& chain, double p,
                       const std::map<std::string, std::size_t>& at, ModelSpec& out) {
  std::map<std::string, std::array<double, 2>> loads;
  for (std::size_t s = 0; s + 1 < chain.size(); ++s) {
    const auto a = position(out, at, chain[s], "/generators");
    const auto b = position(out, at, chain[s + 1], "/generators");
    // Inward normal times the side's length: the chain direction rotated +90 degrees.
    const double fx = -(b[1] - a[1]) * p * block.thickness / 2;
    const double fy = (b[0] - a[0]) * p * block.thickness / 2;
    for (const std::string& id : {chain[s], chain[s + 1]}) {
      loads[id][0] += fx;
      loads[id][1] += fy;
    }
  }
  for (const std::string& id : chain) out.loads.push_back({id, loads[id][0], loads[id][1]});
}

// The link from node `id` to the nearest segment of `chain` (the chain's nodes in order); its
// normal points out of the body on the chain's left.
LinkSpec link_to_nearest_segment(const ContactSpec& contact, const std::string& id,
                                 const std::vector<std::string>& chain, const ModelSpec& out,
                                 const std::map<std::string, std::size_t>& at,
                                 const std::string& path) {
  const auto p = position(out, at, id, path + "/nodes");
  double best = std::numeric_limits<double>::infinity();
  LinkSpec link;
  for (std::size_t s = 0; s + 1 < chain.size(); ++s) {
    const auto a = position(out, at, chain[s], path + "/segments");
    const auto b = position(out, at, chain[s + 1], path + "/segments");
    const double sx = b[0] - a[0], sy = b[1] - a[1], length = std::hypot(sx, sy);
    if (!(length > 0.0))
      throw InputError(
          out.source, path + "/segments",
          fmt::format("nodes '{}' and '{}' are at the same place", chain[s], chain[s + 1]));
    const double w =
        std::clamp(((p[0] - a[0]) * sx + (p[1] - a[1]) * sy) / (length * length), 0.0, 1.0);
    const double cx = a[0] + w * sx - p[0], cy = a[1] + w * sy - p[1];
    const double distance = std::hypot(cx, cy);
    if (distance >= best) continue;
    best = distance;
    // From the node towards the segment: minus the outward normal (sy, -sx) / length.
    const std::array<double, 2> axis{-sy / length, sx / length};
    const double gap = cx * axis[0] + cy * axis[1];
    if (gap < -1e-9 * length)
      throw InputError(out.source, path + "/nodes",
                       fmt::format("node '{}' starts {:g} inside the body behind segment "
                                   "'{}'-'{}' (segments must run counter-clockwise round "
                                   "their body)",
                                   id, -gap, chain[s], chain[s + 1]));
    link = LinkSpec{};
    link.id = fmt::format("{}.{}", contact.id, id);
    link.node_i = id;
    link.axis = std::vector<double>{axis[0], axis[1]};
    link.gap = std::max(gap, 0.0);
    constexpr double kAtEnd = 1e-9;
    if (w <= kAtEnd) {
      link.node_j = chain[s];
    } else if (w >= 1.0 - kAtEnd) {
      link.node_j = chain[s + 1];
    } else {
      link.node_j = chain[s];
      link.segment_end = chain[s + 1];
    }
  }
  return link;
}

}  // namespace

std::string block_node_id(const BlockSpec& block, int column, int row) {
  return fmt::format("{}.{}.{}", block.id, column, row);
}

void add_block(const BlockSpec& block, ModelSpec& out) {
  add_block_nodes(block, out);
  add_block_quads(block, out);
  const std::array<std::vector<std::string>, 4> edges = block_edges(block);
  const std::map<std::string, std::size_t> at = node_positions(out);
  for (int e = 0; e < 4; ++e) {
    const auto& chain = edges[static_cast<std::size_t>(e)];
    out.node_sets[fmt::format("{}.{}", block.id, kEdges[e])] = chain;
    const double p = block.pressure[static_cast<std::size_t>(e)];
    if (p != 0.0) add_edge_pressure(block, chain, p, at, out);
    if (std::find(block.fixed_edges.begin(), block.fixed_edges.end(), kEdges[e]) !=
        block.fixed_edges.end())
      for (const std::string& id : chain) out.supports.push_back({id, {true, true}});
  }
}

void add_surface(const SurfaceSpec& surface, ModelSpec& out) {
  const std::string path = fmt::format("/surfaces/{}", surface.index);
  out.nodes.push_back({surface.id, surface.point[0], surface.point[1]});
  out.supports.push_back({surface.id, {true, true}});
  const std::map<std::string, std::size_t> at = node_positions(out);
  const std::vector<std::string> ids = resolve_nodes(out, at, surface.nodes, path + "/nodes");
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const auto p = position(out, at, ids[k], fmt::format("{}/nodes", path));
    const double height = (p[0] - surface.point[0]) * surface.normal[0] +
                          (p[1] - surface.point[1]) * surface.normal[1];
    const double scale = std::max(
        {std::abs(p[0]), std::abs(p[1]), std::abs(surface.point[0]), std::abs(surface.point[1])});
    if (height < -1e-12 * scale)
      throw InputError(out.source, fmt::format("{}/nodes", path),
                       fmt::format("node '{}' is {:g} below the surface (behind its normal): "
                                   "bodies must start clear of or touching a surface",
                                   ids[k], -height));
    LinkSpec link =
        make_link(fmt::format("{}.{}", surface.id, ids[k]), ids[k], surface.id,
                  {-surface.normal[0], -surface.normal[1]}, std::max(height, 0.0), surface.law);
    link.friction = surface.friction;
    link.velocity_j = surface.velocity;
    out.links.push_back(std::move(link));
  }
}

void add_contact(const ContactSpec& contact, ModelSpec& out) {
  const std::string path = fmt::format("/contacts/{}", contact.index);
  const std::map<std::string, std::size_t> at = node_positions(out);
  const std::vector<std::string> nodes = resolve_nodes(out, at, contact.nodes, path + "/nodes");
  const std::vector<std::string> chain =
      resolve_nodes(out, at, contact.segments, path + "/segments");
  if (chain.size() < 2)
    throw InputError(out.source, path + "/segments",
                     "needs a chain of at least two nodes (one segment)");
  for (const std::string& id : nodes) {
    LinkSpec link = link_to_nearest_segment(contact, id, chain, out, at, path);
    if (link.node_j == id)
      throw InputError(out.source, path + "/nodes",
                       fmt::format("node '{}' is also on the facing boundary", id));
    link.law = contact.law;
    link.friction = contact.friction;
    out.links.push_back(std::move(link));
  }
}

}  // namespace pound::builder
