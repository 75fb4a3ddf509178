// girder_bridge: a multi-span girder bridge with piers, bearings, expansion joints, abutments,
// restrainers and backfill (builder/spec.hpp, GirderBridgeSpec).
#include <fmt/format.h>

#include <algorithm>

#include "builder/generators.hpp"

namespace pound::builder {
namespace {

// What every part of one bridge needs while it is generated.
struct Bridge {
  const GirderBridgeSpec& spec;
  std::vector<double> x;  // stations of the abutments and piers: 0, then the end of each span
  double deck;            // height of the girders, on top of the piers
  std::string girder_material, pier_material;
};

// The first and last node of a continuous stretch of girder.
struct GirderSegment {
  std::string first, last;
};

LawSpec elastic(double stiffness) {
  return {.type = "elastic_spring", .parameters = {{"stiffness", stiffness}}};
}

std::vector<double> stations(const GirderBridgeSpec& spec) {
  std::vector<double> x{0.0};
  for (double span : spec.spans) x.push_back(x.back() + span);
  return x;
}

std::string pier_top(const GirderBridgeSpec& spec, int pier) {
  return fmt::format("{}.p{}.top", spec.id, pier);
}

void add_beam(const std::string& id, const std::string& node_i, const std::string& node_j,
              const std::string& material, const SectionSpec& section, ModelSpec& out) {
  ElementSpec beam = make_beam(id, node_i, node_j, material, section.area, section.inertia);
  beam.extra_mass = section.extra_mass;
  out.elements.push_back(beam);
}

// A girder node sits on a seat: a horizontal bearing (the user's law) and a vertical one. A
// sliding bearing's vertical link is a contact pointing down from the girder to the seat, so
// that the girder's weight presses it (R_n > 0) and its tangent, n turned by +90 degrees, is +x:
// the slide s is u_girder,x - u_seat,x, as for bearing_x.
void add_bearing(const GirderBridgeSpec& spec, const std::string& girder, const std::string& seat,
                 ModelSpec& out) {
  if (spec.bearing)
    out.links.push_back(
        make_link(girder + ".bearing_x", girder, seat, {1.0, 0.0}, 0.0, *spec.bearing));
  if (!spec.bearing_friction) {
    out.links.push_back(make_link(girder + ".bearing_y", girder, seat, {0.0, 1.0}, 0.0,
                                  elastic(spec.bearing_vertical_stiffness)));
    return;
  }
  const LawSpec contact{.type = "gap_spring",
                        .parameters = {{"stiffness", spec.bearing_vertical_stiffness}}};
  LinkSpec sliding = make_link(girder + ".bearing_y", girder, seat, {0.0, -1.0}, 0.0, contact);
  sliding.friction = spec.bearing_friction;
  out.links.push_back(std::move(sliding));
}

// The pounding link of a joint along x (`direction` +1 or -1) and its restrainer, if it has one.
void add_joint_links(const std::string& joint, const std::string& node_i, const std::string& node_j,
                     double direction, const JointSpec& spec, ModelSpec& out) {
  out.links.push_back(make_link(joint, node_i, node_j, {direction, 0.0}, spec.gap, spec.law));
  if (spec.restrainer)
    out.links.push_back(
        make_link(joint + ".restrainer", node_i, node_j, {direction, 0.0}, 0.0, *spec.restrainer));
}

// The pier's section: with hinges its E I is raised to (n + 1) / n E I (builder/spec.hpp).
SectionSpec pier_section(const GirderBridgeSpec& spec) {
  SectionSpec section = spec.pier;
  if (spec.pier_hinge)
    section.inertia *=
        (spec.pier_hinge->stiffness_factor + 1.0) / spec.pier_hinge->stiffness_factor;
  return section;
}

// The base hinge's law: the user's, with k_h = (n + 1) 3 E I / h and M_y; and the pier's yield
// displacement M_y h^2 / (3 E I).
struct PierHinge {
  LawSpec law;
  double yield_displacement;
};
PierHinge pier_hinge(const GirderBridgeSpec& spec) {
  const PierHingeSpec& hinge = *spec.pier_hinge;
  const double ei = spec.pier.youngs_modulus * spec.pier.inertia, h = spec.pier_height;
  const double yield_moment = hinge.yield_moment.value_or(ei * hinge.yield_curvature.value_or(0.0));
  PierHinge made{hinge.law, yield_moment * h * h / (3.0 * ei)};
  made.law.parameters["stiffness"] = (hinge.stiffness_factor + 1.0) * 3.0 * ei / h;
  made.law.parameters["yield_force"] = yield_moment;
  return made;
}

// A pier's base hinge: the hinge's free end node and the link, of one name.
std::string hinge_id(const GirderBridgeSpec& spec, int pier) {
  return fmt::format("{}.p{}.hinge", spec.id, pier);
}

// The pier's lowest node: the base support, or above it the hinge's free end.
std::string add_pier_base(const Bridge& bridge, int pier, const std::optional<PierHinge>& hinge,
                          ModelSpec& out) {
  const GirderBridgeSpec& spec = bridge.spec;
  const std::string base = fmt::format("{}.p{}.base", spec.id, pier);
  out.nodes.push_back({base, bridge.x[pier], 0.0});
  out.supports.push_back({base, {true, true, true}});
  if (!hinge) return base;
  const std::string node = hinge_id(spec, pier);
  out.nodes.push_back({node, bridge.x[pier], 0.0});
  out.supports.push_back({node, {true, true}});
  LinkSpec link = make_link(node, node, base, {1.0, 0.0}, 0.0, hinge->law);
  link.rotational = true;
  link.axis.reset();             // a hinge acts on theta_i - theta_j
  if (spec.pier_hinge->damping)  // with the model's a1, known to the builder
    link.rayleigh = LinkRayleighSpec{.stiffness = *spec.pier_hinge->damping};
  out.links.push_back(link);
  return node;
}

// A pier, fixed at the base (or on its hinge); its top is the seat of the girder nodes above.
void add_pier(const Bridge& bridge, int pier, ModelSpec& out) {
  const GirderBridgeSpec& spec = bridge.spec;
  const std::string base = fmt::format("{}.p{}.base", spec.id, pier), top = pier_top(spec, pier);
  const std::optional<PierHinge> hinge =
      spec.pier_hinge ? std::optional(pier_hinge(spec)) : std::nullopt;
  std::string previous = add_pier_base(bridge, pier, hinge, out);
  const SectionSpec section = pier_section(spec);
  for (int e = 1; e <= spec.pier.elements; ++e) {
    const std::string node =
        e == spec.pier.elements ? top : fmt::format("{}.p{}.n{}", spec.id, pier, e);
    out.nodes.push_back({node, bridge.x[pier], bridge.deck * e / spec.pier.elements});
    add_beam(fmt::format("{}.p{}.e{}", spec.id, pier, e), previous, node, bridge.pier_material,
             section, out);
    previous = node;
  }
  const std::optional<double> yield_drift =
      hinge ? std::optional(hinge->yield_displacement) : spec.pier_yield_drift;
  DriftMonitorSpec monitor{fmt::format("{}.p{}", spec.id, pier),
                           DriftKind::pier,
                           spec.id,
                           base,
                           top,
                           bridge.deck,
                           yield_drift,
                           hinge.has_value()};
  monitor.base_element = fmt::format("{}.p{}.e1", spec.id, pier);
  if (hinge && spec.pier_hinge->plastic_hinge_length) {
    monitor.hinge = hinge_id(spec, pier);
    monitor.yield_curvature = spec.pier_hinge->yield_curvature;
    monitor.plastic_hinge_length = spec.pier_hinge->plastic_hinge_length;
  }
  out.drift_monitors.push_back(monitor);
}

// Where the girder is cut, as span numbers: 0 and the last at the abutments, and the expansion
// joints (pier p stands between spans p - 1 and p), in order.
std::vector<int> girder_cuts(const GirderBridgeSpec& spec) {
  std::vector<int> cuts{0};
  for (int joint : spec.expansion_joints) cuts.push_back(joint);
  cuts.push_back(static_cast<int>(spec.spans.size()));
  std::sort(cuts.begin(), cuts.end());
  return cuts;
}

// Girder segment `g`, over spans [first_span, end_span) between two cuts.
GirderSegment add_girder_segment(const Bridge& bridge, std::size_t g, int first_span, int end_span,
                                 ModelSpec& out) {
  const GirderBridgeSpec& spec = bridge.spec;
  GirderSegment segment;
  std::string previous;
  int counter = 0;
  for (int span = first_span; span < end_span; ++span)
    for (int e = 0; e <= spec.girder.elements; ++e) {
      if (e == 0 && span > first_span) continue;  // shared with the previous span
      const double at =
          bridge.x[span] + spec.spans[static_cast<std::size_t>(span)] * e / spec.girder.elements;
      const std::string node = fmt::format("{}.g{}.n{}", spec.id, g, counter++);
      out.nodes.push_back({node, at, bridge.deck});
      if (!previous.empty())
        add_beam(fmt::format("{}.g{}.e{}", spec.id, g, counter - 1), previous, node,
                 bridge.girder_material, spec.girder, out);
      else
        segment.first = node;
      previous = node;
      // A node over a pier that is not cut sits on it.
      if (e == spec.girder.elements && span + 1 < end_span)
        add_bearing(spec, node, pier_top(spec, span + 1), out);
    }
  segment.last = previous;
  return segment;
}

// An expansion joint over a pier: both girder ends sit on the pier top and may pound.
void add_expansion_joint(const GirderBridgeSpec& spec, int pier, const std::string& left,
                         const std::string& right, ModelSpec& out) {
  const std::string seat = pier_top(spec, pier);
  add_bearing(spec, left, seat, out);
  add_bearing(spec, right, seat, out);
  const std::string joint = fmt::format("{}.joint{}", spec.id, pier);
  add_joint_links(joint, left, right, 1.0, spec.joint, out);
  out.joint_monitors.push_back({joint + ".left_end", joint, left, seat, spec.joint.seat_width});
  out.joint_monitors.push_back({joint + ".right_end", joint, right, seat, spec.joint.seat_width});
}

// An abutment (side 0 at the start, 1 at the end): the girder end sits on the seat and may
// pound on the backwall, which the backfill holds (or which is fixed without backfill).
void add_abutment(const Bridge& bridge, int side, const std::string& girder, ModelSpec& out) {
  const GirderBridgeSpec& spec = bridge.spec;
  const std::string name = fmt::format("{}.a{}", spec.id, side);
  const double at = side == 0 ? 0.0 : bridge.x.back(), outward = side == 0 ? -1.0 : 1.0;
  const std::string seat = name + ".seat", wall = name + ".wall";
  out.nodes.push_back({seat, at, bridge.deck});
  out.supports.push_back({seat, {true, true}});
  out.nodes.push_back({wall, at, bridge.deck});
  add_bearing(spec, girder, seat, out);
  if (spec.backfill) {
    const std::string ground = name + ".ground";
    out.nodes.push_back({ground, at, bridge.deck});
    out.supports.push_back({ground, {true, true}});
    out.supports.push_back({wall, {false, true}});
    out.masses.push_back({wall, spec.backwall_mass, {}, std::nullopt});
    out.links.push_back(
        make_link(name + ".backfill", wall, ground, {outward, 0.0}, 0.0, *spec.backfill));
  } else {
    out.supports.push_back({wall, {true, true}});
  }
  const std::string joint = name + ".joint";
  add_joint_links(joint, girder, wall, outward, spec.abutment, out);
  out.joint_monitors.push_back(
      {joint + ".girder_end", joint, girder, seat, spec.abutment.seat_width});
}

}  // namespace

void add_girder_bridge(const GirderBridgeSpec& spec, ModelSpec& out) {
  const Bridge bridge{spec, stations(spec), spec.pier_height, spec.id + ".girder",
                      spec.id + ".pier"};
  out.materials.push_back(
      {bridge.girder_material, spec.girder.youngs_modulus, spec.girder.density});
  out.materials.push_back({bridge.pier_material, spec.pier.youngs_modulus, spec.pier.density});
  const int spans = static_cast<int>(spec.spans.size());
  for (int pier = 1; pier < spans; ++pier) add_pier(bridge, pier, out);
  const std::vector<int> cuts = girder_cuts(spec);
  std::vector<GirderSegment> segments;
  for (std::size_t g = 0; g + 1 < cuts.size(); ++g)
    segments.push_back(add_girder_segment(bridge, g, cuts[g], cuts[g + 1], out));
  for (std::size_t g = 1; g + 1 < cuts.size(); ++g)
    add_expansion_joint(spec, cuts[g], segments[g - 1].last, segments[g].first, out);
  add_abutment(bridge, 0, segments.front().first, out);
  add_abutment(bridge, 1, segments.back().last, out);
}

}  // namespace pound::builder
