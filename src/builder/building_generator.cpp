// adjacent_buildings: two storey-stick buildings side by side with pounding links wherever a
// floor of one meets the other (builder/spec.hpp, AdjacentBuildingsSpec).
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "builder/generators.hpp"
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
  double x;                                       // where it stands
  std::optional<std::array<double, 2>> rayleigh;  // its own damping, if it has any
};

std::vector<double> floor_heights(const BuildingSpec& building) {
  std::vector<double> heights{0.0};
  for (const StoreySpec& storey : building.storeys)
    heights.push_back(heights.back() + storey.height);
  return heights;
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

Building make_building(const AdjacentBuildingsSpec& pair, int side) {
  const BuildingSpec& spec = side == 0 ? pair.left : pair.right;
  const std::string name = fmt::format("{}.{}", pair.id, kPairSides[side]);
  Building building{.pair = pair,
                    .side = side,
                    .spec = spec,
                    .name = name,
                    .material = name + ".storeys",
                    .heights = floor_heights(spec),
                    .x = side == 0 ? 0.0 : pair.separation};
  if (spec.damping_ratio > 0.0) building.rayleigh = building_rayleigh(spec);
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

// Every height where a floor of either building meets the other one.
std::vector<double> contact_heights(const std::array<Building, 2>& buildings) {
  std::vector<double> contacts;
  const double top = std::min(buildings[0].heights.back(), buildings[1].heights.back());
  for (const Building& building : buildings)
    for (std::size_t f = 1; f < building.heights.size(); ++f)
      if (building.heights[f] <= top * (1 + 1e-12)) contacts.push_back(building.heights[f]);
  std::sort(contacts.begin(), contacts.end());
  contacts.erase(
      std::unique(contacts.begin(), contacts.end(),
                  [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(a, b); }),
      contacts.end());
  return contacts;
}

// The nodes of storey s's column, bottom up: the floor below, the cuts where the other
// building's floors meet it (free rotation there, which keeps the storey's cubic deflection, so
// its stiffness is unchanged) and its floor. Adds the cuts.
std::vector<std::string> add_column_cuts(const Building& building, std::size_t s,
                                         const std::vector<double>& contacts, ModelSpec& out) {
  const double bottom = building.heights[s], upper = building.heights[s + 1];
  std::vector<std::string> chain{floor_node_id(building, s)};
  for (double h : contacts)
    if (h > bottom * (1 + 1e-12) && h < upper * (1 - 1e-12)) {
      const std::string cut = cut_node_id(building, s, h);
      out.nodes.push_back({cut, building.x, h});
      out.supports.push_back({cut, {false, true}});
      chain.push_back(cut);
    }
  chain.push_back(floor_node_id(building, s + 1));
  return chain;
}

// A yielding storey's shear link between its floors: the user's law with the storey's
// stiffness, drift positive when the upper floor moves along +x, and in it the storey's share of
// the building's stiffness-proportional damping: a1 k0, the dashpot its column would have given
// ("initial"), or a1 times its tangent ("committed"; links/stiffness_damping.hpp). In the link,
// not beside it, so that the damping adds no link row to iterate. Returns its yield drift.
std::optional<double> add_storey_link(const Building& building, std::size_t s, ModelSpec& out) {
  const StoreySpec& storey = building.spec.storeys[s];
  const std::string id = storey_id(building, s);
  const std::string top = floor_node_id(building, s + 1), bottom = floor_node_id(building, s);
  LawSpec law = *storey.law;
  law.parameters["stiffness"] = storey.stiffness;
  LinkSpec link = make_link(id, top, bottom, {1.0, 0.0}, 0.0, law);
  if (building.rayleigh && building.spec.storey_damping != StoreyDamping::none)
    link.rayleigh =
        LinkRayleighSpec{.stiffness = building.spec.storey_damping == StoreyDamping::initial
                                          ? links::DampingStiffness::initial
                                          : links::DampingStiffness::committed,
                         .stiffness_coefficient = (*building.rayleigh)[1]};
  out.links.push_back(link);
  const std::string path = fmt::format("/generators/{}/{}/storeys/{}/law",
                                       building.pair.generator_index, kPairSides[building.side], s);
  return links::make_law(law, {out.source, path})(links::LinkContext{})->yield_deformation();
}

// The weight above storey s on a pin-ended leaning column between its floors, whose geometric
// stiffness -P/h on the storey drift is the storey's P-Delta: the storey columns cannot carry it
// (the floors are held vertically, so the gravity analysis gives them no axial force).
void add_leaning_column(const Building& building, std::size_t s, ModelSpec& out) {
  if (!out.gravity || out.gravity->p_delta == PDeltaKind::none) return;
  const double downward =
      -out.gravity->direction[1] * out.gravity->acceleration.value_or(out.units.gravity());
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

// Storey s (from 0): its floor with the floor's mass, its column (or its shear link) and its
// drift monitor.
void add_storey(const Building& building, std::size_t s, const std::vector<double>& contacts,
                ModelSpec& out) {
  const StoreySpec& storey = building.spec.storeys[s];
  const std::string floor = floor_node_id(building, s + 1);
  out.nodes.push_back({floor, building.x, building.heights[s + 1]});
  // A rigid floor: it sways, it neither rises nor turns.
  out.supports.push_back({floor, {false, true, true}});
  const std::optional<double> mass_damping =
      building.rayleigh ? std::optional<double>((*building.rayleigh)[0]) : std::nullopt;
  out.masses.push_back({floor, storey.mass, {}, mass_damping});
  const std::vector<std::string> chain = add_column_cuts(building, s, contacts, out);
  std::optional<double> yield_drift;
  if (storey.law) {
    yield_drift = add_storey_link(building, s, out);  // the reader left it no cuts
  } else {
    const double inertia = storey.stiffness * std::pow(storey.height, 3) / 12.0;  // E = 1
    for (std::size_t c = 0; c + 1 < chain.size(); ++c) {
      ElementSpec column = make_beam(fmt::format("{}.c{}", storey_id(building, s), c), chain[c],
                                     chain[c + 1], building.material, 1.0, inertia);
      column.rayleigh = building.rayleigh;
      out.elements.push_back(column);
    }
  }
  add_leaning_column(building, s, out);
  DriftMonitorSpec monitor{
      storey_id(building, s), DriftKind::storey, building.name, chain.front(), floor,
      storey.height,          yield_drift};
  if (storey.law)
    monitor.shear_link = storey_id(building, s);
  else
    monitor.base_element = fmt::format("{}.c0", storey_id(building, s));
  out.drift_monitors.push_back(monitor);
}

void add_building(const Building& building, const std::vector<double>& contacts, ModelSpec& out) {
  // Columns carry only the storey stiffness; floors and their masses are at the nodes.
  out.materials.push_back({building.material, 1.0, 0.0});
  const std::string base = floor_node_id(building, 0);
  out.nodes.push_back({base, building.x, 0.0});
  out.supports.push_back({base, {true, true, true}});
  for (std::size_t s = 0; s < building.spec.storeys.size(); ++s)
    add_storey(building, s, contacts, out);
}

// The node of a building at a contact height: its floor there, or the cut in its column.
std::string contact_node(const Building& building, double h) {
  std::string node;
  for (std::size_t f = 1; f < building.heights.size(); ++f)
    if (std::abs(building.heights[f] - h) <= 1e-9 * h) node = floor_node_id(building, f);
  if (node.empty())
    for (std::size_t s = 0; s < building.spec.storeys.size(); ++s)
      if (h > building.heights[s] && h < building.heights[s + 1])
        node = cut_node_id(building, s, h);
  return node;
}

// The mass of the building's floor at or just above a contact height.
double floor_mass_near(const Building& building, double h) {
  for (std::size_t s = 0; s < building.spec.storeys.size(); ++s)
    if (h <= building.heights[s + 1] * (1 + 1e-12)) return building.spec.storeys[s].mass;
  return building.spec.storeys.back().mass;
}

void add_pounding_links(const AdjacentBuildingsSpec& pair, const std::array<Building, 2>& buildings,
                        const std::vector<double>& contacts, ModelSpec& out) {
  // Laws that calibrate with the effective mass get that of the floors nearest each contact
  // (a contact point on a column carries no mass of its own).
  const links::LawEntry* law = links::find_law(pair.law.type);
  const bool uses_mass = law && law->accepts("mass", pair.law);
  for (double h : contacts) {
    LinkSpec link =
        make_link(fmt::format("{}.pounding.at{:g}", pair.id, h), contact_node(buildings[0], h),
                  contact_node(buildings[1], h), {1.0, 0.0}, pair.separation, pair.law);
    if (uses_mass && !pair.law.number("mass")) {
      const double m1 = floor_mass_near(buildings[0], h), m2 = floor_mass_near(buildings[1], h);
      link.law.parameters["mass"] = m1 * m2 / (m1 + m2);
    }
    out.links.push_back(link);
  }
}

}  // namespace

std::string building_node_id(const AdjacentBuildingsSpec& pair, int side, int floor) {
  return fmt::format("{}.{}.f{}", pair.id, kPairSides[side], floor);
}

void add_adjacent_buildings(const AdjacentBuildingsSpec& pair, ModelSpec& out) {
  const std::array<Building, 2> buildings{make_building(pair, 0), make_building(pair, 1)};
  const std::vector<double> contacts = contact_heights(buildings);
  for (const Building& building : buildings) add_building(building, contacts, out);
  add_pounding_links(pair, buildings, contacts, out);
}

}  // namespace pound::builder
