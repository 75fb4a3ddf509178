// girder_bridge: a multi-span girder bridge with piers, bearings, expansion joints, abutments,
// restrainers and backfill (builder/spec.hpp, GirderBridgeSpec).
#include <fmt/format.h>

#include <algorithm>

#include "builder/generators.hpp"

namespace pound::builder {
namespace {

LawSpec elastic(double stiffness) {
  return {.type = "elastic_spring", .parameters = {{"stiffness", stiffness}}};
}

}  // namespace

void add_girder_bridge(const GirderBridgeSpec& b, ModelSpec& out) {
  const std::string& id = b.id;
  const int spans = static_cast<int>(b.spans.size());
  std::vector<double> x{0.0};
  for (double span : b.spans) x.push_back(x.back() + span);
  const double deck = b.pier_height;
  const std::string girder_material = id + ".girder", pier_material = id + ".pier";
  out.materials.push_back({girder_material, b.girder.youngs_modulus, b.girder.density});
  out.materials.push_back({pier_material, b.pier.youngs_modulus, b.pier.density});

  auto add_link = [&out](const std::string& link_id, const std::string& i, const std::string& j,
                         std::vector<double> axis, double gap, const LawSpec& law) {
    LinkSpec link;
    link.id = link_id;
    link.node_i = i;
    link.node_j = j;
    link.axis = std::move(axis);
    link.gap = gap;
    link.law = law;
    out.links.push_back(link);
  };
  auto add_beam = [&out](const std::string& element_id, const std::string& i, const std::string& j,
                         const std::string& material, const SectionSpec& section) {
    ElementSpec beam;
    beam.id = element_id;
    beam.type = "beam";
    beam.node_i = i;
    beam.node_j = j;
    beam.material = material;
    beam.area = section.area;
    beam.inertia = section.inertia;
    beam.extra_mass = section.extra_mass;
    out.elements.push_back(beam);
  };
  // A girder node sits on a seat: a horizontal bearing (the user's law) and a vertical one.
  auto add_bearing = [&](const std::string& girder, const std::string& seat) {
    add_link(girder + ".bearing_x", girder, seat, {1.0, 0.0}, 0.0, b.bearing);
    add_link(girder + ".bearing_y", girder, seat, {0.0, 1.0}, 0.0,
             elastic(b.bearing_vertical_stiffness));
  };

  // Piers: fixed at the base, their top is the seat of the girder nodes above.
  for (int p = 1; p < spans; ++p) {
    const std::string base = fmt::format("{}.p{}.base", id, p),
                      top = fmt::format("{}.p{}.top", id, p);
    out.nodes.push_back({base, x[p], 0.0});
    out.supports.push_back({base, true, true, true});
    std::string previous = base;
    for (int e = 1; e <= b.pier.elements; ++e) {
      const std::string node = e == b.pier.elements ? top : fmt::format("{}.p{}.n{}", id, p, e);
      out.nodes.push_back({node, x[p], deck * e / b.pier.elements});
      add_beam(fmt::format("{}.p{}.e{}", id, p, e), previous, node, pier_material, b.pier);
      previous = node;
    }
    out.drift_monitors.push_back(
        {fmt::format("{}.p{}", id, p), "pier", id, base, top, deck, b.pier_yield_drift});
  }

  // Girder segments between cuts (the abutments and the expansion joints).
  std::vector<int> cuts{0};
  for (int joint : b.expansion_joints) cuts.push_back(joint);
  cuts.push_back(spans);
  std::sort(cuts.begin(), cuts.end());
  std::vector<std::string> starts, ends;  // first and last girder node of each segment
  for (std::size_t g = 0; g + 1 < cuts.size(); ++g) {
    std::string previous;
    int counter = 0;
    for (int span = cuts[g]; span < cuts[g + 1]; ++span)
      for (int e = 0; e <= b.girder.elements; ++e) {
        if (e == 0 && span > cuts[g]) continue;  // shared with the previous span
        const double at = x[span] + b.spans[static_cast<std::size_t>(span)] * e / b.girder.elements;
        const std::string node = fmt::format("{}.g{}.n{}", id, g, counter++);
        out.nodes.push_back({node, at, deck});
        if (!previous.empty())
          add_beam(fmt::format("{}.g{}.e{}", id, g, counter - 1), previous, node, girder_material,
                   b.girder);
        else
          starts.push_back(node);
        previous = node;
        // A node over a pier that is not cut sits on it.
        if (e == b.girder.elements && span + 1 < cuts[g + 1])
          add_bearing(node, fmt::format("{}.p{}.top", id, span + 1));
      }
    ends.push_back(previous);
  }

  // Expansion joints over piers: both girder ends sit on the pier top and may pound.
  for (std::size_t g = 1; g + 1 < cuts.size(); ++g) {
    const std::string seat = fmt::format("{}.p{}.top", id, cuts[g]);
    const std::string left = ends[g - 1], right = starts[g];
    add_bearing(left, seat);
    add_bearing(right, seat);
    const std::string joint = fmt::format("{}.joint{}", id, cuts[g]);
    add_link(joint, left, right, {1.0, 0.0}, b.joint.gap, b.joint.law);
    if (b.joint.restrainer)
      add_link(joint + ".restrainer", left, right, {1.0, 0.0}, 0.0, *b.joint.restrainer);
    out.joint_monitors.push_back({joint + ".left_end", joint, left, seat, b.joint.seat_width});
    out.joint_monitors.push_back({joint + ".right_end", joint, right, seat, b.joint.seat_width});
  }

  // Abutments: the girder end sits on the seat and may pound on the backwall, which the
  // backfill holds (or which is fixed without backfill).
  for (int side = 0; side < 2; ++side) {
    const std::string name = fmt::format("{}.a{}", id, side);
    const double at = side == 0 ? 0.0 : x.back(), outward = side == 0 ? -1.0 : 1.0;
    const std::string seat = name + ".seat", wall = name + ".wall";
    out.nodes.push_back({seat, at, deck});
    out.supports.push_back({seat, true, true, false});
    out.nodes.push_back({wall, at, deck});
    const std::string girder = side == 0 ? starts.front() : ends.back();
    add_bearing(girder, seat);
    if (b.backfill) {
      const std::string ground = name + ".ground";
      out.nodes.push_back({ground, at, deck});
      out.supports.push_back({ground, true, true, false});
      out.supports.push_back({wall, false, true, false});
      out.masses.push_back({wall, b.backwall_mass, 0.0, std::nullopt});
      add_link(name + ".backfill", wall, ground, {outward, 0.0}, 0.0, *b.backfill);
    } else {
      out.supports.push_back({wall, true, true, false});
    }
    const std::string joint = name + ".joint";
    add_link(joint, girder, wall, {outward, 0.0}, b.abutment.gap, b.abutment.law);
    if (b.abutment.restrainer)
      add_link(joint + ".restrainer", girder, wall, {outward, 0.0}, 0.0, *b.abutment.restrainer);
    out.joint_monitors.push_back(
        {joint + ".girder_end", joint, girder, seat, b.abutment.seat_width});
  }
}

}  // namespace pound::builder
