// girder_bridge: a multi-span girder bridge with piers, bearings, expansion joints, abutments,
// restrainers and backfill (builder/spec.hpp, GirderBridgeSpec). In a plane scene x runs along
// the bridge and y up; in a 3-D scene x along, y across and z up, the girders and piers 3-D
// beams on one spine, the deck's ends skewed: its pounding points lie along each end line.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "builder/generators.hpp"
#include "core/errors.hpp"
#include "links/coupled_shear.hpp"

namespace pound::builder {
namespace {

// What every part of one bridge needs while it is generated.
struct Bridge {
  const GirderBridgeSpec& spec;
  std::vector<double> x;  // stations of the abutments and piers: 0, then the end of each span
  double deck;            // height of the girders, on top of the piers
  std::string girder_material, pier_material;
  bool space = false;  // a 3-D scene
};

// The deck centreline's heading at station s from x [rad]: s / R on a curved bridge, else 0.
double heading(const Bridge& bridge, double station) {
  return bridge.spec.plan_radius ? station / *bridge.spec.plan_radius : 0.0;
}

// A node at station s and height h: (s, h) in a plane; in space (s, 0, h) on a straight bridge,
// (R sin(s / R), R (1 - cos(s / R)), h) on a curved one.
NodeSpec node_at(const Bridge& bridge, std::string id, double station, double height) {
  if (!bridge.space) return {std::move(id), station, height};
  if (!bridge.spec.plan_radius) return {std::move(id), station, 0.0, height};
  const double radius = *bridge.spec.plan_radius, angle = heading(bridge, station);
  return {std::move(id), radius * std::sin(angle), radius * (1.0 - std::cos(angle)), height};
}

// The unit vectors along the bridge (its tangent at station s), across it (the tangent turned
// +90 degrees in plan, 3-D) and up, with a sign.
std::vector<double> along(const Bridge& bridge, double sign, double station) {
  if (!bridge.space) return {sign, 0.0};
  const double angle = heading(bridge, station);
  if (angle == 0.0) return {sign, 0.0, 0.0};  // no -0 in what `pound expand` writes
  return {sign * std::cos(angle), sign * std::sin(angle), 0.0};
}
std::vector<double> across(const Bridge& bridge, double sign, double station) {
  const double angle = heading(bridge, station);
  if (angle == 0.0) return {0.0, sign, 0.0};
  return {-sign * std::sin(angle), sign * std::cos(angle), 0.0};
}
std::vector<double> upward(const Bridge& bridge, double sign) {
  return bridge.space ? std::vector<double>{0.0, 0.0, sign} : std::vector<double>{0.0, sign};
}

// Supports: every direction; the translations; every direction but the one along the bridge.
SupportSpec fixed(const Bridge& bridge, const std::string& node) {
  if (bridge.space) return {node, {true, true, true, true, true, true}};
  return {node, {true, true, true}};
}
SupportSpec held(const Bridge& bridge, const std::string& node) {
  if (bridge.space) return {node, {true, true, true}};
  return {node, {true, true}};
}
SupportSpec sliding_along(const Bridge& bridge, const std::string& node) {
  if (bridge.space) return {node, {false, true, true, true, true, true}};
  return {node, {false, true}};
}

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

// In space `inertia` bends in the vertical plane along the bridge and `inertia_lateral` across
// it: a girder (along x) oriented by +z has y' = y, z' = z, so I_y is its vertical bending; a pier
// (along z) oriented by the bridge's tangent t there has z' = t, so I_y bends it along the bridge
// (for t = x: y' = -y, z' = x).
void add_beam(const Bridge& bridge, const std::string& id, const std::string& node_i,
              const std::string& node_j, const std::string& material, const SectionSpec& section,
              std::optional<double> pier_station, ModelSpec& out) {
  ElementSpec beam = make_beam(id, node_i, node_j, material, section.area, section.inertia);
  beam.extra_mass = section.extra_mass;
  if (bridge.space) {
    beam.inertia_y = section.inertia;
    beam.inertia_z = section.inertia_lateral;
    beam.torsion = section.torsion;
    beam.orientation = {0.0, 0.0, 1.0};
    if (pier_station) {
      const std::vector<double> tangent = along(bridge, 1.0, *pier_station);
      beam.orientation = {tangent[0], tangent[1], tangent[2]};
    }
  }
  out.elements.push_back(beam);
}

// The pounding points of a deck end at station s, from its centre (3-D): `contact_points` of them
// along the end line d = (-sin a, cos a, 0), a the skew plus the heading there, from the right
// corner (-y side) to the left one. The deck is deck_width wide square to its axis, as drawings
// give it, so its skewed end is deck_width / cos(skew) long, corner to corner.
std::vector<std::array<double, 3>> end_points(const Bridge& bridge, double station) {
  const GirderBridgeSpec& spec = bridge.spec;
  const double skew_angle = spec.skew * std::numbers::pi / 180.0;
  const double skew = skew_angle + heading(bridge, station);
  const std::array<double, 3> line{-std::sin(skew), std::cos(skew), 0.0};
  const double end_length = spec.deck_width / std::cos(skew_angle);
  std::vector<std::array<double, 3>> points;
  const int n = spec.contact_points;
  for (int k = 0; k < n; ++k) {
    const double s = n == 1 ? 0.0 : end_length * (static_cast<double>(k) / (n - 1) - 0.5);
    points.push_back({s * line[0], s * line[1], 0.0});
  }
  return points;
}

// The deck end's normal in plan at station s, along the bridge turned by the skew (3-D).
std::vector<double> end_normal(const Bridge& bridge, double sign, double station) {
  const double skew = bridge.spec.skew * std::numbers::pi / 180.0 + heading(bridge, station);
  return {sign * std::cos(skew), sign * std::sin(skew), 0.0};
}

// In space, one link per bearing carrying the law in both horizontal directions, coupled (its
// axis up from the girder to the seat, so its tangents are x and y): unless asked not to, where
// the law has the coupled form and no friction acts beside it.
bool coupled_bearings(const Bridge& bridge, const ModelSpec& out) {
  const GirderBridgeSpec& spec = bridge.spec;
  if (!bridge.space || !spec.bearing || spec.bearing_friction) return false;
  if (spec.bearing_coupled) return *spec.bearing_coupled;
  const std::string path = fmt::format("/generators/{}/bearing", spec.generator_index);
  return links::CoupledShear::numbers_of(*spec.bearing, {out.source, path}).has_value();
}

// The deck's mass per length: its girder's section and what it carries.
double deck_mass_per_length(const GirderBridgeSpec& spec) {
  return spec.girder.density * spec.girder.area + spec.girder.extra_mass;
}

// A friction pendulum's stick spring gives back 2 mu N d_y at each reversal, d_y = mu N / k_t
// (laws.md): where the model does not set k_t, it is made stiff enough for the whole deck's
// weight W on one bearing, k_t = max(k_v, 1e4 W / R), which keeps every bearing's error under
// 2 % of mu R under gravity (the run warns of a bearing that carries more). The normal law's k_v
// alone was 2.6 % on a two-span deck.
FrictionSpec bearing_friction(const Bridge& bridge, const ModelSpec& out) {
  const GirderBridgeSpec& spec = bridge.spec;
  FrictionSpec friction = *spec.bearing_friction;
  if (!friction.radius || friction.stick_stiffness) return friction;
  const double deck_weight =
      deck_mass_per_length(spec) * (bridge.x.back() - bridge.x.front()) * out.units.gravity();
  friction.stick_stiffness =
      std::max(spec.bearing_vertical_stiffness, 1e4 * deck_weight / *friction.radius);
  return friction;
}

// A girder node sits on a seat: a horizontal bearing (the user's law) and a vertical one. A
// sliding bearing's vertical link is a contact pointing down from the girder to the seat, so
// that the girder's weight presses it (R_n > 0) and its tangent, n turned by +90 degrees, is +x:
// the slide s is u_girder,x - u_seat,x, as for bearing_x. In space the bearing's law acts along
// x and y (`.bearing_x`, `.bearing_y`), the vertical link is `.bearing_z` (a sliding bearing then
// rubs in the horizontal plane, t1 = x, t2 = y: with a radius a bidirectional friction pendulum),
// and the seat's bearings across the deck hold its twist (`.bearing_rx`: two lines of k_v / 2 at
// +-s / 2, k_v s^2 / 4).
void add_bearing(const Bridge& bridge, const std::string& girder, const std::string& seat,
                 double station, ModelSpec& out) {
  const GirderBridgeSpec& spec = bridge.spec;
  if (bridge.space) {
    const double spacing = spec.bearing_spacing.value_or(0.5 * spec.deck_width);
    LinkSpec twist =
        make_link(girder + ".bearing_rx", girder, seat, along(bridge, 1.0, station), 0.0,
                  elastic(spec.bearing_vertical_stiffness * spacing * spacing / 4.0));
    twist.rotational = true;
    out.links.push_back(std::move(twist));
  }
  if (coupled_bearings(bridge, out)) {
    LinkSpec bearing = make_link(girder + ".bearing", girder, seat, upward(bridge, 1.0), 0.0,
                                 elastic(spec.bearing_vertical_stiffness));
    bearing.shear = spec.bearing;
    bearing.tangent = along(bridge, 1.0, station);  // t_1 along the bridge, t_2 across
    out.links.push_back(std::move(bearing));
    return;
  }
  if (spec.bearing) {
    out.links.push_back(make_link(girder + ".bearing_x", girder, seat, along(bridge, 1.0, station),
                                  0.0, *spec.bearing));
    if (bridge.space)
      out.links.push_back(make_link(girder + ".bearing_y", girder, seat,
                                    across(bridge, 1.0, station), 0.0, *spec.bearing));
  }
  const std::string vertical = girder + (bridge.space ? ".bearing_z" : ".bearing_y");
  if (!spec.bearing_friction) {
    out.links.push_back(make_link(vertical, girder, seat, upward(bridge, 1.0), 0.0,
                                  elastic(spec.bearing_vertical_stiffness)));
    return;
  }
  const LawSpec contact{.type = "gap_spring",
                        .parameters = {{"stiffness", spec.bearing_vertical_stiffness}}};
  LinkSpec sliding = make_link(vertical, girder, seat, upward(bridge, -1.0), 0.0, contact);
  sliding.friction = bearing_friction(bridge, out);
  out.links.push_back(std::move(sliding));
}

// The pounding link of a joint along x (`direction` +1 or -1) and its restrainer, if it has one.
// In space one link per pounding point of the deck end, `<joint>.c<k>` (or `<joint>` alone at
// its centre), along the end's normal, both ends offset to the point; the restrainer along the
// bridge between the end nodes.
void add_joint_links(const Bridge& bridge, const std::string& joint, const std::string& node_i,
                     const std::string& node_j, double direction, double station,
                     const JointSpec& spec, ModelSpec& out) {
  if (!bridge.space) {
    out.links.push_back(make_link(joint, node_i, node_j, {direction, 0.0}, spec.gap, spec.law));
  } else {
    const std::vector<std::array<double, 3>> points = end_points(bridge, station);
    for (std::size_t k = 0; k < points.size(); ++k) {
      const std::string id = points.size() == 1 ? joint : fmt::format("{}.c{}", joint, k);
      LinkSpec link =
          make_link(id, node_i, node_j, end_normal(bridge, direction, station), spec.gap, spec.law);
      if (points.size() > 1) link.offsets = std::array{points[k], points[k]};
      out.links.push_back(std::move(link));
    }
  }
  if (spec.restrainer)
    out.links.push_back(make_link(joint + ".restrainer", node_i, node_j,
                                  along(bridge, direction, station), 0.0, *spec.restrainer));
}

// The pier's section: with hinges its E I is raised to (n + 1) / n E I (builder/spec.hpp), in
// space about both axes.
SectionSpec pier_section(const GirderBridgeSpec& spec) {
  SectionSpec section = spec.pier;
  if (spec.pier_hinge) {
    const double raise =
        (spec.pier_hinge->stiffness_factor + 1.0) / spec.pier_hinge->stiffness_factor;
    section.inertia *= raise;
    section.inertia_lateral *= raise;
  }
  return section;
}

// A base hinge's law: the user's, with k_h = (n + 1) 3 E I / h and M_y; the pier's yield
// displacement (pier_yield_displacement); what its drift monitor needs for the curvature
// ductility. Along the bridge with E I, across it (3-D) with E I_lateral and its own M_y or phi_y.
struct PierHinge {
  LawSpec law;
  double yield_displacement;
  std::string link;  // its id
  std::optional<double> yield_curvature;
};
// The hinge's hardening ratio that gives the pier `pier_ratio`: in series with the stiffened
// elastic pier ((n + 1) / n of 3 E I / h), the hinge's post-yield slope s gives the pier r times
// its yield secant, 1 / (n / ((n + 1) k) + 1 / s) = r k_ym, with k_ym the pier's secant to yield
// (series of the pier and the hinge's F_y / delta_y). For a bilinear hinge, r / (1 + n (1 - r))
// (Ibarra & Krawinkler 2005, appendix B; Zareian & Medina 2010).
double hinge_hardening(double pier_ratio, double n, double hinge_stiffness, const LawSpec& law) {
  const auto deformation = law.parameters.find("yield_deformation");
  // Bilinear: closed form, the same bits about either axis of a 3-D pier (a coupled hinge
  // needs one ratio).
  if (deformation == law.parameters.end()) return pier_ratio / (1.0 + n * (1.0 - pier_ratio));
  const double elastic_part = hinge_stiffness / n;  // (n + 1) / n 3 E I / h
  const double hinge_secant = law.parameters.at("yield_force") / deformation->second;
  const double pier_secant = 1.0 / (1.0 / elastic_part + 1.0 / hinge_secant);
  const double slope = 1.0 / (1.0 / (pier_ratio * pier_secant) - 1.0 / elastic_part);
  return slope / hinge_secant;
}

// Where the pier yields: its hinge at the yield rotation, and the stiffened elastic pier bent by
// V_y = M_y / h, n / (n + 1) of M_y h^2 / (3 E I). On a bilinear skeleton the rotation is
// M_y / k_h and the sum is M_y h^2 / (3 E I); a trilinear one (Takeda's cracking point) gives its
// own, larger yield rotation, past the cracked branch (taking M_y h^2 / (3 E I) there doubled a
// pier's ductility).
double pier_yield_displacement(const LawSpec& law, double yield_moment, double ei, double h,
                               double n) {
  const double elastic = yield_moment * h * h / (3.0 * ei);
  const auto rotation = law.parameters.find("yield_deformation");
  if (rotation == law.parameters.end()) return elastic;
  return rotation->second * h + n / (n + 1.0) * elastic;
}

PierHinge pier_hinge(const GirderBridgeSpec& spec, int pier, bool across) {
  const PierHingeSpec& hinge = *spec.pier_hinge;
  const double ei =
      spec.pier.youngs_modulus * (across ? spec.pier.inertia_lateral : spec.pier.inertia);
  const double h = spec.pier_height;
  const std::optional<double> curvature =
      across && hinge.yield_curvature
          ? hinge.yield_curvature_lateral.value_or(*hinge.yield_curvature)
          : hinge.yield_curvature;
  const std::optional<double> moment =
      across && hinge.yield_moment ? hinge.yield_moment_lateral.value_or(*hinge.yield_moment)
                                   : hinge.yield_moment;
  const double yield_moment = moment.value_or(ei * curvature.value_or(0.0));
  const double n = hinge.stiffness_factor, stiffness = (n + 1.0) * 3.0 * ei / h;
  PierHinge made{hinge.law, pier_yield_displacement(hinge.law, yield_moment, ei, h, n),
                 fmt::format("{}.p{}.hinge{}", spec.id, pier, across ? ".across" : ""), curvature};
  made.law.parameters["stiffness"] = stiffness;
  made.law.parameters["yield_force"] = yield_moment;
  // The law's hardening ratio is the pier's, not the hinge's.
  const auto ratio = made.law.parameters.find("hardening_ratio");
  if (ratio != made.law.parameters.end() && ratio->second > 0.0)
    ratio->second = hinge_hardening(ratio->second, n, stiffness, made.law);
  return made;
}

// In space, one hinge per pier base bending about x and y, coupled on an elliptic surface:
// unless asked not to, where the law has the coupled form.
bool coupled_hinges(const Bridge& bridge, const ModelSpec& out) {
  const GirderBridgeSpec& spec = bridge.spec;
  if (!bridge.space || !spec.pier_hinge) return false;
  if (spec.pier_hinge->coupled) return *spec.pier_hinge->coupled;
  return spec.pier_hinge->law_couples(
      {out.source, fmt::format("/generators/{}/pier_hinge/law", spec.generator_index)});
}

// A pier's coupled base hinge `<pier>.hinge` (axis up; its tangents the bridge's directions at
// its station, x and y on a straight bridge): the bending across the bridge (about the tangent
// along it, t_1) and along it (about t_2, across) on one yield ellipse; its own law the torsion,
// which the held hinge node never turns.
LinkSpec coupled_hinge(const Bridge& bridge, int pier, const std::string& node,
                       const std::string& base, const std::vector<PierHinge>& hinges) {
  LinkSpec link = make_link(hinges.front().link, node, base, upward(bridge, 1.0), 0.0,
                            elastic(hinges.front().law.parameters.at("stiffness")));
  link.tangent = along(bridge, 1.0, bridge.x[pier]);
  link.rotational = true;
  link.shear = hinges[1].law;           // across: about x
  link.shear_2 = hinges[0].law;         // along: about y
  if (bridge.spec.pier_hinge->damping)  // with the model's a1, known to the builder
    link.rayleigh = LinkRayleighSpec{.stiffness = *bridge.spec.pier_hinge->damping};
  return link;
}

// A pier's base hinges: the hinge's free end node (named as the hinge along the bridge) and the
// links. In a plane the hinge turns about z; in space the one along the bridge about the
// horizontal across it (y on a straight bridge), the one across it about the bridge's tangent (x),
// or one coupled hinge about both, and the free end is held in torsion.
std::string add_pier_base(const Bridge& bridge, int pier, const std::vector<PierHinge>& hinges,
                          ModelSpec& out) {
  const GirderBridgeSpec& spec = bridge.spec;
  const std::string base = fmt::format("{}.p{}.base", spec.id, pier);
  out.nodes.push_back(node_at(bridge, base, bridge.x[pier], 0.0));
  out.supports.push_back(fixed(bridge, base));
  if (hinges.empty()) return base;
  const std::string node = hinges.front().link;
  out.nodes.push_back(node_at(bridge, node, bridge.x[pier], 0.0));
  if (bridge.space)
    out.supports.push_back({node, {true, true, true, false, false, true}});
  else
    out.supports.push_back(held(bridge, node));
  if (coupled_hinges(bridge, out)) {
    out.links.push_back(coupled_hinge(bridge, pier, node, base, hinges));
    return node;
  }
  for (std::size_t k = 0; k < hinges.size(); ++k) {
    LinkSpec link = make_link(hinges[k].link, node, base, {1.0, 0.0}, 0.0, hinges[k].law);
    link.rotational = true;  // a hinge acts on theta_i - theta_j
    if (bridge.space)
      link.axis = k == 0 ? across(bridge, 1.0, bridge.x[pier]) : along(bridge, 1.0, bridge.x[pier]);
    else
      link.axis.reset();
    if (spec.pier_hinge->damping)  // with the model's a1, known to the builder
      link.rayleigh = LinkRayleighSpec{.stiffness = *spec.pier_hinge->damping};
    out.links.push_back(link);
  }
  return node;
}

// A pier, fixed at the base (or on its hinge); its top is the seat of the girder nodes above.
void add_pier(const Bridge& bridge, int pier, ModelSpec& out) {
  const GirderBridgeSpec& spec = bridge.spec;
  const std::string base = fmt::format("{}.p{}.base", spec.id, pier), top = pier_top(spec, pier);
  std::vector<PierHinge> hinges;
  if (spec.pier_hinge) {
    hinges.push_back(pier_hinge(spec, pier, false));
    if (bridge.space) hinges.push_back(pier_hinge(spec, pier, true));
  }
  std::string previous = add_pier_base(bridge, pier, hinges, out);
  const SectionSpec section = pier_section(spec);
  for (int e = 1; e <= spec.pier.elements; ++e) {
    const std::string node =
        e == spec.pier.elements ? top : fmt::format("{}.p{}.n{}", spec.id, pier, e);
    out.nodes.push_back(
        node_at(bridge, node, bridge.x[pier], bridge.deck * e / spec.pier.elements));
    add_beam(bridge, fmt::format("{}.p{}.e{}", spec.id, pier, e), previous, node,
             bridge.pier_material, section, bridge.x[pier], out);
    previous = node;
  }
  // Its drift along the bridge and, in space, across it (`.y`), each with its hinge.
  for (int direction = 0; direction < (bridge.space ? 2 : 1); ++direction) {
    const PierHinge* hinge =
        hinges.empty() ? nullptr : &hinges[static_cast<std::size_t>(direction)];
    DriftMonitorSpec monitor{
        fmt::format("{}.p{}{}", spec.id, pier, direction == 0 ? "" : ".y"),
        DriftKind::pier,
        spec.id,
        base,
        top,
        bridge.deck,
        hinge ? std::optional(hinge->yield_displacement) : spec.pier_yield_drift,
        hinge != nullptr};
    monitor.base_element = fmt::format("{}.p{}.e1", spec.id, pier);
    monitor.direction = direction;
    if (bridge.space && heading(bridge, bridge.x[pier]) != 0.0) {  // along and across the curve
      const std::vector<double> axis =
          direction == 0 ? along(bridge, 1.0, bridge.x[pier]) : across(bridge, 1.0, bridge.x[pier]);
      monitor.axis = std::array{axis[0], axis[1], axis[2]};
    }
    if (hinge && spec.pier_hinge->plastic_hinge_length) {
      monitor.hinge = hinge->link;
      monitor.yield_curvature = hinge->yield_curvature;
      monitor.plastic_hinge_length = spec.pier_hinge->plastic_hinge_length;
      if (coupled_hinges(bridge, out)) {  // one hinge: along the bridge about y (t_2)
        monitor.hinge = hinges.front().link;
        monitor.hinge_direction = direction == 0 ? 2 : 1;
      }
    }
    // One hinge yielding on an ellipse: the two drifts yield together.
    if (hinge && coupled_hinges(bridge, out))
      monitor.yields_with = fmt::format("{}.p{}{}", spec.id, pier, direction == 0 ? ".y" : "");
    out.drift_monitors.push_back(monitor);
  }
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

// In space the deck's width gives each girder node a rotary inertia about x (twist) and z (plan
// turn), m W^2 / 12 of the mass m it lumps (half of each beam beside it), the deck's mass spread
// evenly across its width W, square to its axis whatever the skew.
void add_deck_rotary_inertia(const Bridge& bridge, const std::vector<std::string>& nodes,
                             const std::vector<double>& stations, ModelSpec& out) {
  const GirderBridgeSpec& spec = bridge.spec;
  const double per_length = deck_mass_per_length(spec);
  std::vector<double> lumped(nodes.size(), 0.0);
  for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
    const double half = 0.5 * per_length * (stations[k + 1] - stations[k]);
    lumped[k] += half;
    lumped[k + 1] += half;
  }
  const double width_squared = spec.deck_width * spec.deck_width;
  // A curved deck twists about its tangent, which turns along it; masses are diagonal in the
  // global axes, so it takes the same inertia about both horizontal axes (exact for the twist).
  const double across = spec.plan_radius ? 1.0 : 0.0;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const double inertia = lumped[k] * width_squared / 12.0;
    if (inertia > 0.0)
      out.masses.push_back({nodes[k], 0.0, {inertia, across * inertia, inertia}, std::nullopt});
  }
}

// Girder segment `g`, over spans [first_span, end_span) between two cuts.
GirderSegment add_girder_segment(const Bridge& bridge, std::size_t g, int first_span, int end_span,
                                 ModelSpec& out) {
  const GirderBridgeSpec& spec = bridge.spec;
  GirderSegment segment;
  std::string previous;
  int counter = 0;
  std::vector<std::string> nodes;
  std::vector<double> positions;
  for (int span = first_span; span < end_span; ++span)
    for (int e = 0; e <= spec.girder.elements; ++e) {
      if (e == 0 && span > first_span) continue;  // shared with the previous span
      const double at =
          bridge.x[span] + spec.spans[static_cast<std::size_t>(span)] * e / spec.girder.elements;
      const std::string node = fmt::format("{}.g{}.n{}", spec.id, g, counter++);
      out.nodes.push_back(node_at(bridge, node, at, bridge.deck));
      nodes.push_back(node);
      positions.push_back(at);
      if (!previous.empty())
        add_beam(bridge, fmt::format("{}.g{}.e{}", spec.id, g, counter - 1), previous, node,
                 bridge.girder_material, spec.girder, std::nullopt, out);
      else
        segment.first = node;
      previous = node;
      // A node over a pier that is not cut sits on it.
      if (e == spec.girder.elements && span + 1 < end_span)
        add_bearing(bridge, node, pier_top(spec, span + 1), at, out);
    }
  segment.last = previous;
  if (bridge.space) add_deck_rotary_inertia(bridge, nodes, positions, out);
  return segment;
}

// A joint's monitors: its opening and closing, and the girder end's movement on its seat along the
// bridge. In space across the skewed support line and, with several pounding points, one per
// point, `<id>.c<k>`: the opening at that point and the point's movement on its seat (the
// corner's unseating margin; the acute corner's is the one to watch).
void add_joint_monitors(const Bridge& bridge, const std::string& id, const std::string& joint,
                        const std::string& girder, const std::string& seat, double seat_width,
                        double station, ModelSpec& out) {
  const int points = bridge.space ? bridge.spec.contact_points : 1;
  if (!bridge.space) {
    out.joint_monitors.push_back({id, joint, girder, seat, seat_width});
    return;
  }
  const std::vector<std::array<double, 3>> at = end_points(bridge, station);
  const std::vector<double> normal = end_normal(bridge, 1.0, station);
  if (points == 1) {  // the end's centre, across the (skewed) support line
    JointMonitorSpec monitor{id, joint, girder, seat, seat_width};
    monitor.point = at.front();
    monitor.direction = std::array{normal[0], normal[1], normal[2]};
    out.joint_monitors.push_back(monitor);
    return;
  }
  for (int k = 0; k < points; ++k) {
    JointMonitorSpec monitor{fmt::format("{}.c{}", id, k), fmt::format("{}.c{}", joint, k), girder,
                             seat, seat_width};
    monitor.point = at[static_cast<std::size_t>(k)];
    monitor.direction = std::array{normal[0], normal[1], normal[2]};
    out.joint_monitors.push_back(monitor);
  }
}

// An expansion joint over a pier: both girder ends sit on the pier top and may pound.
void add_expansion_joint(const Bridge& bridge, int pier, const std::string& left,
                         const std::string& right, ModelSpec& out) {
  const GirderBridgeSpec& spec = bridge.spec;
  const std::string seat = pier_top(spec, pier);
  const double at = bridge.x[static_cast<std::size_t>(pier)];
  add_bearing(bridge, left, seat, at, out);
  add_bearing(bridge, right, seat, at, out);
  const std::string joint = fmt::format("{}.joint{}", spec.id, pier);
  add_joint_links(bridge, joint, left, right, 1.0, at, spec.joint, out);
  add_joint_monitors(bridge, joint + ".left_end", joint, left, seat, spec.joint.seat_width, at,
                     out);
  add_joint_monitors(bridge, joint + ".right_end", joint, right, seat, spec.joint.seat_width, at,
                     out);
}

// Shear keys on an abutment seat at station s (3-D): `<abutment>.shear_key.left` (across the
// bridge, +y when straight) and `.right`, compression-only stops the deck end strikes after the
// keys' gap.
void add_shear_keys(const Bridge& bridge, const std::string& abutment, const std::string& girder,
                    const std::string& seat, double station, ModelSpec& out) {
  const ShearKeySpec& keys = *bridge.spec.shear_keys;
  for (const auto& [side, sign] : {std::pair{"left", 1.0}, std::pair{"right", -1.0}})
    out.links.push_back(make_link(fmt::format("{}.shear_key.{}", abutment, side), girder, seat,
                                  across(bridge, sign, station), keys.gap, keys.law));
}

// The backfill law with the abutment's stem holding the wall toward the span (links/backfill.hpp),
// as stiffly as the soil's initial stiffness unless the law says: without it the wall's mass hung
// free on the span's side and drifted across the gap under shaking alone.
LawSpec backfill_with_stem(LawSpec law) {
  if (law.type == "backfill" && !law.number("stem_stiffness"))
    law.parameters["stem_stiffness"] = law.parameters.at("initial_stiffness");
  return law;
}

// An abutment (side 0 at the start, 1 at the end): the girder end sits on the seat and may
// pound on the backwall, which the backfill holds (or which is fixed without backfill).
void add_abutment(const Bridge& bridge, int side, const std::string& girder, ModelSpec& out) {
  const GirderBridgeSpec& spec = bridge.spec;
  const std::string name = fmt::format("{}.a{}", spec.id, side);
  const double at = side == 0 ? 0.0 : bridge.x.back(), outward = side == 0 ? -1.0 : 1.0;
  const std::string seat = name + ".seat", wall = name + ".wall";
  out.nodes.push_back(node_at(bridge, seat, at, bridge.deck));
  out.supports.push_back(bridge.space ? fixed(bridge, seat) : held(bridge, seat));
  out.nodes.push_back(node_at(bridge, wall, at, bridge.deck));
  add_bearing(bridge, girder, seat, at, out);
  // In space the backwall moves along the bridge only (its backfill's direction), held across it
  // and in its rotations by the abutment. Where a curved bridge's tangent is not x, supports
  // (along global axes) cannot hold it across: a guide spring as stiff as the bearings
  // vertically does, `<abutment>.wall_guide`.
  if (spec.backfill) {
    const std::string ground = name + ".ground";
    out.nodes.push_back(node_at(bridge, ground, at, bridge.deck));
    out.supports.push_back(held(bridge, ground));
    if (bridge.space && heading(bridge, at) != 0.0) {
      out.supports.push_back({wall, {false, false, true, true, true, true}});
      out.links.push_back(make_link(name + ".wall_guide", wall, ground, across(bridge, 1.0, at),
                                    0.0, elastic(spec.bearing_vertical_stiffness)));
    } else {
      out.supports.push_back(sliding_along(bridge, wall));
    }
    out.masses.push_back({wall, spec.backwall_mass, {}, std::nullopt});
    out.links.push_back(make_link(name + ".backfill", wall, ground, along(bridge, outward, at), 0.0,
                                  backfill_with_stem(*spec.backfill)));
  } else {
    out.supports.push_back(fixed(bridge, wall));
  }
  if (bridge.space && spec.shear_keys) add_shear_keys(bridge, name, girder, seat, at, out);
  const std::string joint = name + ".joint";
  add_joint_links(bridge, joint, girder, wall, outward, at, spec.abutment, out);
  add_joint_monitors(bridge, joint + ".girder_end", joint, girder, seat, spec.abutment.seat_width,
                     at, out);
}

}  // namespace

// Each law in the role of its links, refused at its own path (the links it makes would be
// located at the generator only).
void check_law_roles(const GirderBridgeSpec& spec, const std::string& source) {
  const std::string at = fmt::format("/generators/{}", spec.generator_index);
  using links::LinkRole;
  for (const auto& [joint, name] :
       {std::pair{&spec.joint, "joint"}, std::pair{&spec.abutment, "abutment"}}) {
    require_law_role(joint->law, LinkRole::contact, fmt::format("the {}'s pounding link", name),
                     source, fmt::format("{}/{}/law", at, name));
    if (joint->restrainer)
      require_law_role(*joint->restrainer, LinkRole::tension,
                       fmt::format("the {}'s restrainer", name), source,
                       fmt::format("{}/{}/restrainer", at, name));
  }
  if (spec.backfill)
    require_law_role(*spec.backfill, LinkRole::contact, "the backfill behind a backwall", source,
                     at + "/backfill");
  if (spec.shear_keys)
    require_law_role(spec.shear_keys->law, LinkRole::contact, "a shear key", source,
                     at + "/shear_keys/law",
                     "backfill gives a key that yields at a capacity (its ultimate force)");
  if (spec.bearing)
    require_law_role(*spec.bearing, LinkRole::spring, "a bearing", source, at + "/bearing");
}

// A deck without mass is a static part: its girders would follow their bearings with no inertia
// of their own, and their impacts would move nothing (piers without mass are fine: their tops
// are static DOFs the bearings and hinges hold).
void require_deck_mass(const GirderBridgeSpec& spec, const std::string& source) {
  if (deck_mass_per_length(spec) > 0.0) return;
  throw InputError(source, fmt::format("/generators/{}/girder", spec.generator_index),
                   "the girders have no mass (density and extra_mass both 0): a deck without "
                   "inertia follows its bearings and its impacts move nothing; give extra_mass, "
                   "the deck's mass per length, or the girders' density");
}

void add_girder_bridge(const GirderBridgeSpec& spec, ModelSpec& out) {
  check_law_roles(spec, out.source);
  require_deck_mass(spec, out.source);
  const Bridge bridge{spec,
                      stations(spec),
                      spec.pier_height,
                      spec.id + ".girder",
                      spec.id + ".pier",
                      out.dimension == 3};
  for (const auto& [material, section] : {std::pair{bridge.girder_material, &spec.girder},
                                          std::pair{bridge.pier_material, &spec.pier}}) {
    MaterialSpec made{material, section->youngs_modulus, section->density};
    if (bridge.space) made.poisson_ratio = section->poisson_ratio;
    out.materials.push_back(made);
  }
  const int spans = static_cast<int>(spec.spans.size());
  for (int pier = 1; pier < spans; ++pier) add_pier(bridge, pier, out);
  const std::vector<int> cuts = girder_cuts(spec);
  std::vector<GirderSegment> segments;
  for (std::size_t g = 0; g + 1 < cuts.size(); ++g)
    segments.push_back(add_girder_segment(bridge, g, cuts[g], cuts[g + 1], out));
  for (std::size_t g = 1; g + 1 < cuts.size(); ++g)
    add_expansion_joint(bridge, cuts[g], segments[g - 1].last, segments[g].first, out);
  add_abutment(bridge, 0, segments.front().first, out);
  add_abutment(bridge, 1, segments.back().last, out);
}

}  // namespace pound::builder
