// adjacent_buildings: two storey-stick buildings side by side with pounding links wherever a
// floor of one meets the other (builder/spec.hpp, AdjacentBuildingsSpec). In a 3-D scene x runs
// from the left building to the right one, y along the facades and z up: each floor is a rigid
// plan (u_x, u_y, theta_z at its mass centre), each storey a column stick at its stiffness centre
// reaching the floors through rigid offsets, and the floors pound at points along the facades.
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "builder/generators.hpp"
#include "core/errors.hpp"
#include "links/law_registry.hpp"

namespace pound::builder {
namespace {

// One building of the pair while it is generated.
struct Building {
  const AdjacentBuildingsSpec& pair;
  int side;  // 0 left, 1 right
  const BuildingSpec& spec;
  std::string name;                               // "<pair>.<side>"
  std::string material;                           // of its columns
  std::vector<double> heights;                    // of its floors, from the ground (0) up
  std::array<double, 2> centre;                   // of its plan (2-D: x, 0)
  std::optional<std::array<double, 2>> rayleigh;  // its own damping, if it has any
  bool space = false;                             // a 3-D scene

  // Plan positions of its floor nodes (the mass centre) and of its column (the stiffness
  // centre, where the base and the cuts are); in a plane both are `centre`.
  std::array<double, 2> floor_at() const { return from_centre(spec.mass_centre); }
  std::array<double, 2> column_at() const { return from_centre(spec.stiffness_centre); }
  std::array<double, 2> from_centre(const std::array<double, 2>& point) const {
    if (!space) return centre;
    return {centre[0] + point[0], centre[1] + point[1]};
  }
  // The rigid offset from a floor node to the column (3-D).
  std::array<double, 3> column_arm() const {
    const std::array<double, 2> floor = floor_at(), column = column_at();
    return {column[0] - floor[0], column[1] - floor[1], 0.0};
  }
};

// A node at plan position `at` and height h: (x, h) in a plane, (x, y, h) in space.
NodeSpec node_at(const Building& building, std::string id, std::array<double, 2> at, double h) {
  if (building.space) return {std::move(id), at[0], at[1], h};
  return {std::move(id), at[0], h};
}

// The rigid offset from a node at `from` to the point `to` (3-D; plan positions).
std::array<double, 3> offset(std::array<double, 2> from, std::array<double, 2> to) {
  return {to[0] - from[0], to[1] - from[1], 0.0};
}

std::vector<double> floor_heights(const BuildingSpec& building) {
  std::vector<double> heights{0.0};
  for (const StoreySpec& storey : building.storeys)
    heights.push_back(heights.back() + storey.height);
  return heights;
}

// A storey's torsional stiffness about its stiffness centre (3-D): given, or its lateral
// stiffness spread evenly over the plan a x b, sum k_i r_i^2 = (k_x b^2 + k_y a^2) / 12.
double torsional_stiffness(const BuildingSpec& building, std::size_t s) {
  const StoreySpec& storey = building.storeys[s];
  if (storey.torsional_stiffness) return *storey.torsional_stiffness;
  const double a = building.plan[0], b = building.plan[1];
  return (storey.stiffness * b * b + storey.stiffness_y.value_or(storey.stiffness) * a * a) / 12.0;
}

// A floor's polar moment of inertia about its mass centre (3-D): given, or a uniform slab's.
double floor_rotary_inertia(const BuildingSpec& building, std::size_t s) {
  const StoreySpec& storey = building.storeys[s];
  const double a = building.plan[0], b = building.plan[1];
  return storey.rotary_inertia.value_or(storey.mass * (a * a + b * b) / 12.0);
}

// Rayleigh coefficients giving `ratio` at the building's own first two modes (shear building).
std::array<double, 2> building_rayleigh(const BuildingSpec& building) {
  const auto n = static_cast<Eigen::Index>(building.storeys.size());
  Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(n, n), mass = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index s = 0; s < n; ++s) {
    const double k = building.storeys[static_cast<std::size_t>(s)].stiffness;
    stiffness(s, s) += k;
    if (s > 0) {
      stiffness(s - 1, s - 1) += k;
      stiffness(s - 1, s) -= k;
      stiffness(s, s - 1) -= k;
    }
    mass(s, s) = building.storeys[static_cast<std::size_t>(s)].mass;
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(stiffness, mass);
  const double w1 = std::sqrt(modes.eigenvalues()[0]);
  const double w2 = n > 1 ? std::sqrt(modes.eigenvalues()[1]) : 3.0 * w1;
  const double xi = building.damping_ratio;
  return {2.0 * xi * w1 * w2 / (w1 + w2), 2.0 * xi / (w1 + w2)};
}

// In a plane the buildings stand at x = 0 and x = separation (their facing facades); in space
// the left one's facade toward the right one is at x = 0, the right one's at x = separation.
std::array<double, 2> plan_centre(const AdjacentBuildingsSpec& pair, int side, bool space) {
  if (!space) return {side == 0 ? 0.0 : pair.separation, 0.0};
  if (side == 0) return {-0.5 * pair.left.plan[0], 0.0};
  return {pair.separation + 0.5 * pair.right.plan[0], pair.offset};
}

// A floor lighter than a millionth of the building's heaviest is no floor (a typo, or a mass in the
// wrong unit): its storeys would hold a point that has no inertia, whose acceleration (floor
// spectra, the report's floor acceleration) means nothing, and which gravity's P-Delta can buckle
// between two yielding storeys.
constexpr double kLeastFloorMass = 1e-6;

void require_floor_masses(const AdjacentBuildingsSpec& pair, int side, const std::string& source) {
  const BuildingSpec& spec = side == 0 ? pair.left : pair.right;
  double heaviest = 0.0;
  for (const StoreySpec& storey : spec.storeys) heaviest = std::max(heaviest, storey.mass);
  for (std::size_t s = 0; s < spec.storeys.size(); ++s)
    if (spec.storeys[s].mass < kLeastFloorMass * heaviest)
      throw InputError(
          source,
          fmt::format("/generators/{}/{}/storeys/{}/mass", pair.generator_index, kPairSides[side],
                      s),
          fmt::format("{:g} is {:.3g} of the building's heaviest floor ({:g}): a "
                      "floor without mass (its storeys would hold a point with no "
                      "inertia); give the floor its mass",
                      spec.storeys[s].mass, spec.storeys[s].mass / heaviest, heaviest));
}

Building make_building(const AdjacentBuildingsSpec& pair, int side, bool space,
                       const std::string& source) {
  require_floor_masses(pair, side, source);
  const BuildingSpec& spec = side == 0 ? pair.left : pair.right;
  const std::string name = fmt::format("{}.{}", pair.id, kPairSides[side]);
  Building building{.pair = pair,
                    .side = side,
                    .spec = spec,
                    .name = name,
                    .material = name + ".storeys",
                    .heights = floor_heights(spec),
                    .centre = plan_centre(pair, side, space),
                    .space = space};
  if (spec.damping_ratio > 0.0) {
    building.rayleigh = building_rayleigh(spec);
    // Floor masses and storey stiffnesses further apart than double precision holds (a floor of
    // 1e-300 kg) overflow the modes' frequencies; the damping would make every storey's force NaN.
    if (!std::isfinite((*building.rayleigh)[0]) || !std::isfinite((*building.rayleigh)[1]))
      throw InputError(
          source,
          fmt::format("/generators/{}/{}/damping_ratio", pair.generator_index, kPairSides[side]),
          "the building's first two modes, which set its Rayleigh damping, are not "
          "finite numbers: its floor masses and storey stiffnesses are further apart "
          "than double precision holds (a floor mass near zero? give each floor its "
          "real mass)");
  }
  return building;
}

// Storey s (from 0): "<pair>.<side>.s<s + 1>", which its columns and cuts extend.
std::string storey_id(const Building& building, std::size_t s) {
  return fmt::format("{}.s{}", building.name, s + 1);
}

// Where a floor of the other building at height h cuts storey s's column.
std::string cut_node_id(const Building& building, std::size_t s, double h) {
  return fmt::format("{}.at{:g}", storey_id(building, s), h);
}

std::string floor_node_id(const Building& building, std::size_t floor) {
  return building_node_id(building.pair, building.side, static_cast<int>(floor));
}

// Every height where a floor of either building meets the other one: floors level within
// level_tolerance are one height, the lower one's.
std::vector<double> contact_heights(const std::array<Building, 2>& buildings) {
  const double tolerance = level_tolerance(buildings[0].pair);
  std::vector<double> floors;
  const double top = std::min(buildings[0].heights.back(), buildings[1].heights.back());
  for (const Building& building : buildings)
    for (std::size_t f = 1; f < building.heights.size(); ++f)
      if (building.heights[f] <= top + tolerance) floors.push_back(building.heights[f]);
  std::sort(floors.begin(), floors.end());
  std::vector<double> contacts;
  for (const double h : floors)
    if (contacts.empty() || h - contacts.back() > tolerance) contacts.push_back(h);
  return contacts;
}

// The nodes of storey s's column, bottom up: the floor below, the cuts where the other
// building's floors meet it (free rotation there, which keeps the storey's cubic deflection, so
// its stiffness is unchanged) and its floor. Adds the cuts.
std::vector<std::string> add_column_cuts(const Building& building, std::size_t s,
                                         const std::vector<double>& contacts, ModelSpec& out) {
  const double bottom = building.heights[s], upper = building.heights[s + 1];
  const double tolerance = level_tolerance(building.pair);
  std::vector<std::string> chain{floor_node_id(building, s)};
  for (double h : contacts)
    if (h > bottom + tolerance && h < upper - tolerance) {
      const std::string cut = cut_node_id(building, s, h);
      out.nodes.push_back(node_at(building, cut, building.column_at(), h));
      // Held vertically, free to bend and twist (the column's shape through the cut is kept).
      if (building.space)
        out.supports.push_back({cut, {false, false, true, false, false, false}});
      else
        out.supports.push_back({cut, {false, true}});
      chain.push_back(cut);
    }
  chain.push_back(floor_node_id(building, s + 1));
  return chain;
}

// In space, whether storey s is one link whose x and y shears are coupled: as asked, or where
// its law has the coupled form.
bool coupled_storeys(const Building& building, std::size_t s, const ModelSpec& out) {
  const StoreySpec& storey = building.spec.storeys[s];
  if (!building.space || !storey.law) return false;
  if (building.spec.storeys_coupled) return *building.spec.storeys_coupled;
  return storey.law_couples(
      {out.source, fmt::format("/generators/{}/{}/storeys/{}/law", building.pair.generator_index,
                               kPairSides[building.side], s)});
}

// A yielding storey's shear link between its floors: the user's law with the storey's
// stiffness, drift positive when the upper floor moves along +x, and in it the storey's share of
// the building's stiffness-proportional damping: a1 k0, the dashpot its column would have given
// ("initial"), or a1 times its tangent ("committed"; links/stiffness_damping.hpp). In the link,
// not beside it, so that the damping adds no link row to iterate. In space the link acts at the
// stiffness centre, with the same law along y (the storey's stiffness_y): coupled, one link whose
// vertical axis (the floors hold it) carries the two as its shear (coupled_storeys), or a link
// `<storey>.y` of its own; and an elastic twist spring (`<storey>.rz`). Returns its yield drift
// along x and y (the law's F_y over the stiffness along each).
std::array<std::optional<double>, 2> add_storey_link(const Building& building, std::size_t s,
                                                     ModelSpec& out) {
  const StoreySpec& storey = building.spec.storeys[s];
  const std::string id = storey_id(building, s);
  const std::string top = floor_node_id(building, s + 1), bottom = floor_node_id(building, s);
  const auto storey_link = [&](const std::string& link_id, std::vector<double> axis,
                               const LawSpec& law, bool rotational = false) -> LinkSpec& {
    LinkSpec link = make_link(link_id, top, bottom, std::move(axis), 0.0, law);
    link.rotational = rotational;
    if (building.rayleigh && building.spec.storey_damping != StoreyDamping::none)
      link.rayleigh =
          LinkRayleighSpec{.stiffness = building.spec.storey_damping == StoreyDamping::initial
                                            ? links::DampingStiffness::initial
                                            : links::DampingStiffness::committed,
                           .stiffness_coefficient = (*building.rayleigh)[1]};
    if (building.space && !rotational)  // the base stands on the column: no offset there
      link.offsets = std::array{building.column_arm(),
                                s > 0 ? building.column_arm() : std::array<double, 3>{}};
    out.links.push_back(link);
    return out.links.back();
  };
  LawSpec law = *storey.law;
  law.parameters["stiffness"] = storey.stiffness;
  LawSpec across = law;
  across.parameters["stiffness"] = storey.stiffness_y.value_or(storey.stiffness);
  if (!building.space) {
    storey_link(id, {1.0, 0.0}, law);
  } else if (coupled_storeys(building, s, out)) {
    LinkSpec& link =
        storey_link(id, {0.0, 0.0, 1.0},
                    {.type = "elastic_spring", .parameters = {{"stiffness", storey.stiffness}}});
    link.shear = law;  // along x (t_1)
    link.shear_2 = across;
    storey_link(id + ".rz", {0.0, 0.0, 1.0},
                {.type = "elastic_spring",
                 .parameters = {{"stiffness", torsional_stiffness(building.spec, s)}}},
                true);
  } else {
    storey_link(id, {1.0, 0.0, 0.0}, law);
    storey_link(id + ".y", {0.0, 1.0, 0.0}, across);
    storey_link(id + ".rz", {0.0, 0.0, 1.0},
                {.type = "elastic_spring",
                 .parameters = {{"stiffness", torsional_stiffness(building.spec, s)}}},
                true);
  }
  const std::string path = fmt::format("/generators/{}/{}/storeys/{}/law",
                                       building.pair.generator_index, kPairSides[building.side], s);
  const auto yield_drift = [&](const LawSpec& along) {
    return links::make_law(along, {out.source, path})(links::LinkContext{})->yield_deformation();
  };
  return {yield_drift(law), yield_drift(across)};
}

// The weight above storey s on a pin-ended leaning column between its floors, whose geometric
// stiffness -P/h on the storey drift is the storey's P-Delta: the storey columns cannot carry it
// (the floors are held vertically, so the gravity analysis gives them no axial force).
void add_leaning_column(const Building& building, std::size_t s, ModelSpec& out) {
  if (!out.gravity || out.gravity->p_delta == PDeltaKind::none) return;
  const double downward = -out.gravity->direction[building.space ? 2 : 1] *
                          out.gravity->acceleration.value_or(out.units.gravity());
  double weight = 0.0;
  for (std::size_t above = s; above < building.spec.storeys.size(); ++above)
    weight += building.spec.storeys[above].mass * downward;
  if (!(weight > 0.0)) return;
  ElementSpec column{.id = storey_id(building, s) + ".leaning",
                     .type = ElementKind::truss,
                     .node_i = floor_node_id(building, s),
                     .node_j = floor_node_id(building, s + 1),
                     .material = building.material,
                     .area = 1.0,
                     .axial_force = -weight};
  out.elements.push_back(column);
}

// The storey's column between the nodes of `chain` (floor, cuts, floor): E I = k h^3 / 12 with
// E = 1, so that between floors held against rotation its lateral stiffness is k; in space at
// the stiffness centre (rigid offsets from the floor nodes), I_y from k_x, I_z from k_y and,
// with G = 1, J = k_theta h.
void add_column(const Building& building, std::size_t s, const std::vector<std::string>& chain,
                ModelSpec& out) {
  const StoreySpec& storey = building.spec.storeys[s];
  const auto inertia = [&](double k) { return k * std::pow(storey.height, 3) / 12.0; };
  for (std::size_t c = 0; c + 1 < chain.size(); ++c) {
    ElementSpec column = make_beam(fmt::format("{}.c{}", storey_id(building, s), c), chain[c],
                                   chain[c + 1], building.material, 1.0, inertia(storey.stiffness));
    column.rayleigh = building.rayleigh;
    if (building.space) {
      column.inertia_y = inertia(storey.stiffness);
      column.inertia_z = inertia(storey.stiffness_y.value_or(storey.stiffness));
      column.torsion = torsional_stiffness(building.spec, s) * storey.height;
      column.orientation = {1.0, 0.0, 0.0};  // y' = -y, z' = x: I_y bends it along x
      // The floors' nodes are at the mass centre, the base and the cuts on the column.
      if (c == 0 && s > 0) column.offsets[0] = building.column_arm();
      if (c + 2 == chain.size()) column.offsets[1] = building.column_arm();
    }
    out.elements.push_back(column);
  }
}

// A storey's drift monitors: along x and, in space, along y, each also watching the floor's
// plan corners (c0 at -x -y, then counter-clockwise) and the storey's twist.
void add_drift_monitors(const Building& building, std::size_t s,
                        const std::vector<std::string>& chain,
                        const std::array<std::optional<double>, 2>& yield_drift, ModelSpec& out) {
  const std::string& bottom = chain.front();
  const StoreySpec& storey = building.spec.storeys[s];
  const std::string floor = floor_node_id(building, s + 1);
  for (int direction = 0; direction < (building.space ? 2 : 1); ++direction) {
    const std::string suffix = direction == 0 ? "" : ".y";
    DriftMonitorSpec monitor{storey_id(building, s) + suffix,
                             DriftKind::storey,
                             building.name,
                             bottom,
                             floor,
                             storey.height,
                             yield_drift[static_cast<std::size_t>(direction)]};
    if (coupled_storeys(building, s, out)) {  // one link: its shear along x (t_1) or y (t_2)
      monitor.shear_link = storey_id(building, s);
      monitor.shear_link_direction = direction + 1;
      // Yielding together on the ellipse: the resultant of the two drifts at the mass centre,
      // where each direction's ductility is measured (the link, at the stiffness centre, moves
      // otherwise on an eccentric storey: its resultant read below one direction's ductility).
      monitor.yields_with = storey_id(building, s) + (direction == 0 ? ".y" : "");
    } else if (storey.law) {
      monitor.shear_link = storey_id(building, s) + suffix;
    } else {
      monitor.base_element = fmt::format("{}.c0", storey_id(building, s));
      for (std::size_t c = 1; c + 1 < chain.size(); ++c)  // the segments above a strike
        monitor.upper_elements.push_back(fmt::format("{}.c{}", storey_id(building, s), c));
    }
    monitor.direction = direction;
    if (building.space) {
      const double a = building.spec.plan[0], b = building.spec.plan[1];
      for (const auto& [x, y] : {std::pair{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}})
        monitor.corners.push_back(
            offset(building.floor_at(), building.from_centre({x * a, y * b})));
    }
    out.drift_monitors.push_back(monitor);
  }
}

// Storey s (from 0): its floor with the floor's mass, its column (or its shear link) and its
// drift monitors.
void add_storey(const Building& building, std::size_t s, const std::vector<double>& contacts,
                ModelSpec& out) {
  const StoreySpec& storey = building.spec.storeys[s];
  const std::string floor = floor_node_id(building, s + 1);
  out.nodes.push_back(node_at(building, floor, building.floor_at(), building.heights[s + 1]));
  // A rigid floor: it sways, it neither rises nor tilts (in a plane nor turns).
  if (building.space)
    out.supports.push_back({floor, {false, false, true, true, true, false}});
  else
    out.supports.push_back({floor, {false, true, true}});
  const std::optional<double> mass_damping =
      building.rayleigh ? std::optional<double>((*building.rayleigh)[0]) : std::nullopt;
  std::array<double, 3> rotary{};
  if (building.space) rotary[2] = floor_rotary_inertia(building.spec, s);
  out.masses.push_back({floor, storey.mass, rotary, mass_damping});
  const std::vector<std::string> chain = add_column_cuts(building, s, contacts, out);
  std::array<std::optional<double>, 2> yield_drift;
  if (storey.law)
    yield_drift = add_storey_link(building, s, out);  // the reader left it no cuts
  else
    add_column(building, s, chain, out);
  add_leaning_column(building, s, out);
  add_drift_monitors(building, s, chain, yield_drift, out);
}

void add_building(const Building& building, const std::vector<double>& contacts, ModelSpec& out) {
  // Columns carry only the storey stiffness; floors and their masses are at the nodes.
  out.materials.push_back({building.material, 1.0, 0.0, std::nullopt,
                           building.space ? std::optional(1.0) : std::nullopt});
  const std::string base = floor_node_id(building, 0);
  out.nodes.push_back(node_at(building, base, building.column_at(), 0.0));
  if (building.space)
    out.supports.push_back({base, {true, true, true, true, true, true}});
  else
    out.supports.push_back({base, {true, true, true}});
  for (std::size_t s = 0; s < building.spec.storeys.size(); ++s)
    add_storey(building, s, contacts, out);
}

// The node of a building at a contact height, and where it stands in plan: its floor there, or
// the cut in its column.
struct ContactNode {
  std::string id;
  std::array<double, 2> at;
};
// The id of the building's floor level with height h, or "" where none is.
std::string floor_node_id_at(const Building& building, double h) {
  const double tolerance = level_tolerance(building.pair);
  for (std::size_t f = 1; f < building.heights.size(); ++f)
    if (std::abs(building.heights[f] - h) <= tolerance) return floor_node_id(building, f);
  return {};
}

ContactNode contact_node(const Building& building, double h) {
  if (std::string floor = floor_node_id_at(building, h); !floor.empty())
    return {std::move(floor), building.floor_at()};
  for (std::size_t s = 0; s < building.spec.storeys.size(); ++s)
    if (h > building.heights[s] && h < building.heights[s + 1])
      return {cut_node_id(building, s, h), building.column_at()};
  return {};
}

// The mass of the building's floor nearest a contact height (the upper one midway; the ground,
// which has none, is not a floor here).
double floor_mass_near(const Building& building, double h) {
  std::size_t nearest = 0;
  for (std::size_t s = 1; s < building.spec.storeys.size(); ++s)
    if (std::abs(building.heights[s + 1] - h) <= std::abs(building.heights[nearest + 1] - h))
      nearest = s;
  return building.spec.storeys[nearest].mass;
}

// Where the facades meet along y (3-D): `contact_points` positions spread over the stretch
// where they face each other, its ends first and last (1: its middle).
std::vector<double> contact_positions(const AdjacentBuildingsSpec& pair) {
  const auto [low, high] = facing_stretch(pair);
  const int n = pair.contact_points;
  std::vector<double> positions;
  for (int k = 0; k < n; ++k)
    positions.push_back(n == 1 ? 0.5 * (low + high)
                               : low + (high - low) * static_cast<double>(k) / (n - 1));
  return positions;
}

// The links at contact height h: one along x in a plane; in space one per contact position
// (`.c<k>` from -y, none with a single point), from the left facade (x = 0) to the right one
// (x = separation), through rigid offsets from the nodes.
void add_links_at(const AdjacentBuildingsSpec& pair, const std::array<Building, 2>& buildings,
                  double h, const LawSpec& law, ModelSpec& out) {
  const ContactNode left = contact_node(buildings[0], h), right = contact_node(buildings[1], h);
  const std::string id = fmt::format("{}.pounding.at{:g}", pair.id, h);
  if (!buildings[0].space) {
    out.links.push_back(make_link(id, left.id, right.id, {1.0, 0.0}, pair.separation, law));
    return;
  }
  const std::vector<double> positions = contact_positions(pair);
  for (std::size_t k = 0; k < positions.size(); ++k) {
    LinkSpec link = make_link(positions.size() == 1 ? id : fmt::format("{}.c{}", id, k), left.id,
                              right.id, {1.0, 0.0, 0.0}, pair.separation, law);
    link.offsets = std::array{offset(left.at, {0.0, positions[k]}),
                              offset(right.at, {pair.separation, positions[k]})};
    out.links.push_back(link);
  }
}

void add_pounding_links(const AdjacentBuildingsSpec& pair, const std::array<Building, 2>& buildings,
                        const std::vector<double>& contacts, ModelSpec& out) {
  // Laws that calibrate with the effective mass get that of the floors nearest each contact
  // (a contact point on a column carries no mass of its own).
  const links::LawEntry* entry = links::find_law(pair.law.type);
  const bool uses_mass = entry && entry->accepts("mass", pair.law);
  for (double h : contacts) {
    for (const Building& building : buildings)
      if (entry && entry->traits.constraint && floor_node_id_at(building, h).empty())
        throw InputError(
            out.source, fmt::format("/generators/{}/law", pair.generator_index),
            fmt::format("a {} gives its force as an impulse between masses, but at {:g} a floor "
                        "strikes the {} building's column between its floors, which has none: "
                        "give the two buildings floors at the same heights there, or a penalty "
                        "law (kelvin_voigt, jankowski, extended_penalty, ...)",
                        pair.law.type, h, kPairSides[building.side]));
    LawSpec law = pair.law;
    if (uses_mass && !pair.law.number("mass")) {
      const double m1 = floor_mass_near(buildings[0], h), m2 = floor_mass_near(buildings[1], h);
      law.parameters["mass"] = m1 * m2 / (m1 + m2);
    }
    add_links_at(pair, buildings, h, law, out);
  }
}

}  // namespace

std::string building_node_id(const AdjacentBuildingsSpec& pair, int side, int floor) {
  return fmt::format("{}.{}.f{}", pair.id, kPairSides[side], floor);
}

void add_adjacent_buildings(const AdjacentBuildingsSpec& pair, ModelSpec& out) {
  require_law_role(pair.law, links::LinkRole::contact, "a pounding link between the buildings",
                   out.source, fmt::format("/generators/{}/law", pair.generator_index));
  const bool space = out.dimension == 3;
  const std::array<Building, 2> buildings{make_building(pair, 0, space, out.source),
                                          make_building(pair, 1, space, out.source)};
  const std::vector<double> contacts = contact_heights(buildings);
  for (const Building& building : buildings) add_building(building, contacts, out);
  add_pounding_links(pair, buildings, contacts, out);
}

}  // namespace pound::builder
