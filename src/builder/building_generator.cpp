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

constexpr const char* kSide[] = {"left", "right"};

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

}  // namespace

std::string building_node_id(const AdjacentBuildingsSpec& pair, int side, int floor) {
  return fmt::format("{}.{}.f{}", pair.id, kSide[side], floor);
}

void add_adjacent_buildings(const AdjacentBuildingsSpec& pair, ModelSpec& out) {
  const BuildingSpec* buildings[2] = {&pair.left, &pair.right};
  const std::vector<double> heights[2] = {floor_heights(pair.left), floor_heights(pair.right)};
  const double x[2] = {0.0, pair.separation};
  // Every height where a floor of either building meets the other one.
  std::vector<double> contacts;
  const double top = std::min(heights[0].back(), heights[1].back());
  for (const auto& side : heights)
    for (std::size_t f = 1; f < side.size(); ++f)
      if (side[f] <= top * (1 + 1e-12)) contacts.push_back(side[f]);
  std::sort(contacts.begin(), contacts.end());
  contacts.erase(
      std::unique(contacts.begin(), contacts.end(),
                  [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(a, b); }),
      contacts.end());

  std::vector<std::string> contact_nodes[2];  // per contact height
  for (int side = 0; side < 2; ++side) {
    const BuildingSpec& building = *buildings[side];
    const std::string material = fmt::format("{}.{}.storeys", pair.id, kSide[side]);
    // Columns carry only the storey stiffness; floors and their masses are at the nodes.
    out.materials.push_back({material, 1.0, 0.0});
    std::optional<std::array<double, 2>> rayleigh;
    std::optional<double> mass_damping;
    if (building.damping_ratio > 0.0) {
      rayleigh = building_rayleigh(building);
      mass_damping = (*rayleigh)[0];
    }
    out.nodes.push_back({building_node_id(pair, side, 0), x[side], 0.0});
    out.supports.push_back({building_node_id(pair, side, 0), true, true, true});
    for (std::size_t s = 0; s < building.storeys.size(); ++s) {
      const StoreySpec& storey = building.storeys[s];
      const double bottom = heights[side][s], upper = heights[side][s + 1];
      const std::string floor = building_node_id(pair, side, static_cast<int>(s + 1));
      out.nodes.push_back({floor, x[side], upper});
      // A rigid floor: it sways, it neither rises nor turns.
      out.supports.push_back({floor, false, true, true});
      out.masses.push_back({floor, storey.mass, 0.0, mass_damping});
      // The storey column, cut where the other building's floors meet it (free rotation there,
      // which keeps the storey's cubic deflection, so its stiffness is unchanged).
      std::vector<std::string> chain{building_node_id(pair, side, static_cast<int>(s))};
      for (double h : contacts)
        if (h > bottom * (1 + 1e-12) && h < upper * (1 - 1e-12)) {
          const std::string cut = fmt::format("{}.{}.s{}.at{:g}", pair.id, kSide[side], s + 1, h);
          out.nodes.push_back({cut, x[side], h});
          out.supports.push_back({cut, false, true, false});
          chain.push_back(cut);
        }
      chain.push_back(floor);
      const double inertia = storey.stiffness * std::pow(storey.height, 3) / 12.0;  // E = 1
      for (std::size_t c = 0; c + 1 < chain.size(); ++c) {
        ElementSpec column;
        column.id = fmt::format("{}.{}.s{}.c{}", pair.id, kSide[side], s + 1, c);
        column.type = "beam";
        column.node_i = chain[c];
        column.node_j = chain[c + 1];
        column.material = material;
        column.area = 1.0;
        column.inertia = inertia;
        column.rayleigh = rayleigh;
        out.elements.push_back(column);
      }
      out.drift_monitors.push_back({fmt::format("{}.{}.s{}", pair.id, kSide[side], s + 1), "storey",
                                    fmt::format("{}.{}", pair.id, kSide[side]), chain.front(),
                                    floor, storey.height, std::nullopt});
    }
    // The node of this building at each contact height.
    for (double h : contacts) {
      std::string node;
      for (std::size_t f = 1; f < heights[side].size(); ++f)
        if (std::abs(heights[side][f] - h) <= 1e-9 * h)
          node = building_node_id(pair, side, static_cast<int>(f));
      if (node.empty())
        for (std::size_t s = 0; s < building.storeys.size(); ++s)
          if (h > heights[side][s] && h < heights[side][s + 1])
            node = fmt::format("{}.{}.s{}.at{:g}", pair.id, kSide[side], s + 1, h);
      contact_nodes[side].push_back(node);
    }
  }
  // Laws that calibrate with the effective mass get that of the floors nearest each contact
  // (a contact point on a column carries no mass of its own).
  auto floor_mass_near = [&](int side, double h) {
    const BuildingSpec& building = *buildings[side];
    for (std::size_t s = 0; s < building.storeys.size(); ++s)
      if (h <= heights[side][s + 1] * (1 + 1e-12)) return building.storeys[s].mass;
    return building.storeys.back().mass;
  };
  const links::LawEntry* law = links::find_law(pair.law.type);
  const bool uses_mass = law && law->accepts("mass", pair.law);
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    LinkSpec link;
    link.id = fmt::format("{}.pounding.at{:g}", pair.id, contacts[c]);
    link.node_i = contact_nodes[0][c];
    link.node_j = contact_nodes[1][c];
    link.gap = pair.separation;
    link.axis = std::vector<double>{1.0, 0.0};
    link.law = pair.law;
    if (uses_mass && !pair.law.number("mass")) {
      const double m1 = floor_mass_near(0, contacts[c]), m2 = floor_mass_near(1, contacts[c]);
      link.law.parameters["mass"] = m1 * m2 / (m1 + m2);
    }
    out.links.push_back(link);
  }
}

}  // namespace pound::builder
